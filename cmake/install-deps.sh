#!/usr/bin/env bash
# Installs, from Debian 12 packages, whatever rugosim needs to build, test and benchmark,
# and only what is missing. Safe to run again: with everything present it installs nothing.
# Usage: cmake/install-deps.sh        (as root, or with sudo available)
set -euo pipefail

packages=(
  # toolchain
  g++ cmake ninja-build pkg-config git
  # engine
  libeigen3-dev
  # application: CLI, formatting, scene files
  libcli11-dev libfmt-dev nlohmann-json3-dev
  # sweeps: arithmetic expressions of a sweep spec
  libmuparser-dev
  # renderer: off-screen OpenGL, PNG, MP4 (H.264 through libx264)
  libosmesa6-dev libegl-dev libegl1-mesa-dev libegl-mesa0 libgl1-mesa-dri libpng-dev
  libavcodec-dev libavformat-dev libavfilter-dev libavutil-dev libswscale-dev
  # text in frames: FreeType and the DejaVu fonts
  libfreetype-dev fonts-dejavu-core
  # vector stills (render -o still.svg|pdf): cairo
  libcairo2-dev
  # tests and benchmarks (libwebp-dev: the tests decode animated WebP with libwebp's demux API)
  libgtest-dev libgmock-dev libbenchmark-dev libwebp-dev
  # the vector stills' tests: an XML parser and the SVG and PDF rasterisers they compare with
  libxml2-utils librsvg2-bin poppler-utils
  # scale-out tests: chunked renders through GNU parallel and a single-node Slurm cluster that
  # the tests start themselves (docs/scale-out.md)
  parallel slurm-wlm slurm-client munge
  # packaging: cpack's .deb (dpkg-shlibdeps declares the program's libraries; file finds them)
  dpkg-dev file
  # the pile benchmark's competitor
  libbox2d-dev
  # the render benchmark's baseline: the ffmpeg command
  ffmpeg
  # rugosim plot: figures drawn by gnuplot
  gnuplot-nox
  # the scene-loader fuzz target: clang with libFuzzer and the sanitizer runtimes
  clang libclang-rt-14-dev
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present, nothing to install."
  exit 0
fi

echo "install-deps: installing ${#missing[@]} missing package(s): ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null 2>&1 || { echo "install-deps: not root and no sudo; install as root: apt-get install ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
# munge and Slurm are for the tests only, which start their own daemons on loopback and stop
# them: their packages would start munged and the Slurm daemons as system services. A
# policy-rc.d that refuses every service start (invoke-rc.d and deb-systemd-invoke honour it)
# keeps them stopped while apt installs; one the system already has is left alone.
policy=/usr/sbin/policy-rc.d
if [ ! -e "$policy" ]; then
  printf '#!/bin/sh\n# cmake/install-deps.sh: no service starts while it installs\nexit 101\n' |
    "${sudo_cmd[@]}" tee "$policy" >/dev/null
  "${sudo_cmd[@]}" chmod 755 "$policy"
  trap '"${sudo_cmd[@]}" rm -f "$policy"' EXIT
fi
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "install-deps: done."
