#!/usr/bin/env bash
# The program's .deb on a fresh Debian 12: a minimal bookworm made by debootstrap from the
# machine's own Debian mirror, where `apt install ./rugosim_*.deb` must pull every library the
# package declares, and the installed program must render a frame (the OSMesa context, the font
# and libpng all found at run time from what the package brought).
# Usage (root, network to a Debian mirror): tests/install/deb_in_chroot.sh DEB [WORK]
# Not in ctest or CI (it downloads ~150 MB); docs/deploy.md gives its last result.
set -euo pipefail
deb=$(realpath "$1")
work=${2:-/tmp/rugosim-chroot}
mirror=${RUGOSIM_DEBIAN_MIRROR:-http://deb.debian.org/debian}
[ "$(id -u)" -eq 0 ] || { echo "deb_in_chroot: needs root (debootstrap, chroot)" >&2; exit 1; }
command -v debootstrap >/dev/null || apt-get install -y -qq debootstrap
rm -rf "$work"
debootstrap --variant=minbase bookworm "$work" "$mirror" >"$work.debootstrap.log" 2>&1 ||
  { tail -20 "$work.debootstrap.log"; echo "deb_in_chroot: debootstrap failed" >&2; exit 1; }
cp "$deb" "$work/tmp/"
cp "$(dirname "$0")/../../scenes/validation_bouncing_disk.json" "$work/tmp/scene.json"
chroot "$work" /bin/bash -c "
  set -euo pipefail
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends /tmp/$(basename "$deb") >/tmp/apt.log
  rugosim --version
  rugosim render /tmp/scene.json -o /tmp/frame.png --frame 10 --size 320x180 -y
  test -s /tmp/frame.png
  echo deb_in_chroot: installed packages: \$(dpkg-query -W -f='\${Package}\n' | wc -l)"
echo "deb_in_chroot: ok ($work)"
