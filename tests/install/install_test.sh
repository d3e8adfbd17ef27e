#!/usr/bin/env bash
# What a user gets from the build's install rules (cmake/RugosimInstall.cmake):
#   find_package BUILD WORK SOURCE  cmake --install into WORK/prefix, then tests/install/example
#                                   configured against it with find_package(rugosim), built,
#                                   and run on a scene: it must drop the validation disk.
#   deb BUILD WORK                  cpack's two .debs: their control fields (declared
#                                   dependencies), their contents, and the program unpacked
#                                   from rugosim_*.deb answering --version.
set -euo pipefail
mode=$1 build=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
version=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build/CMakeCache.txt")
fail() { echo "install_test: $*" >&2; exit 1; }

case "$mode" in
find_package)
  source=$4
  cmake --install "$build" --prefix "$work/prefix" >"$work/install.log"
  [ -x "$work/prefix/bin/rugosim" ] || fail "no bin/rugosim in the prefix"
  config=$(find "$work/prefix" -name rugosimConfig.cmake -path "*/cmake/rugosim/*" | head -n 1)
  [ -n "$config" ] || fail "no package config (lib*/cmake/rugosim/rugosimConfig.cmake)"
  cmake -S "$source/tests/install/example" -B "$work/example" -G Ninja \
        -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix" >"$work/configure.log" ||
    { cat "$work/configure.log"; fail "the example does not configure against the package"; }
  cmake --build "$work/example" >"$work/build.log" ||
    { cat "$work/build.log"; fail "the example does not build against the package"; }
  out=$("$work/example/drop" "$work/prefix/share/rugosim/scenes/validation_bouncing_disk.json" 0.2)
  echo "$out"
  grep -q "^rugosim $version, t = 0.2 s$" <<<"$out" || fail "the example did not run to 0.2 s"
  # The disk starts 1 m up (validation_bouncing_disk.json) and falls: it must be lower.
  awk '$1 == "disk" { found = 1; if (!($3 < 1.0)) exit 1 } END { exit !found }' <<<"$out" ||
    fail "the disk did not fall"
  ;;
deb)
  cpack --config "$build/CPackConfig.cmake" -G DEB -B "$work" >"$work/cpack.log" ||
    { cat "$work/cpack.log"; fail "cpack failed"; }
  program=$(ls "$work"/rugosim_"$version"_*.deb) || fail "no rugosim_${version}_*.deb"
  dev=$(ls "$work"/rugosim-dev_"$version"_*.deb) || fail "no rugosim-dev_${version}_*.deb"
  depends=$(dpkg-deb -f "$program" Depends)
  echo "rugosim Depends: $depends"
  for needed in libosmesa6 libavcodec59 libcairo2 libpng16-16 fonts-dejavu-core; do
    grep -q "$needed" <<<"$depends" || fail "rugosim's Depends lacks $needed"
  done
  dev_depends=$(dpkg-deb -f "$dev" Depends)
  for needed in libeigen3-dev nlohmann-json3-dev libosmesa6-dev; do
    grep -q "$needed" <<<"$dev_depends" || fail "rugosim-dev's Depends lacks $needed"
  done
  contents=$(dpkg-deb -c "$dev")
  grep -q "usr/lib/cmake/rugosim/rugosimConfig.cmake" <<<"$contents" ||
    fail "rugosim-dev holds no package config"
  grep -q "usr/include/rugosim/engine/dynamics/world.h" <<<"$contents" ||
    fail "rugosim-dev holds no headers"
  dpkg-deb -x "$program" "$work/root"
  [ -f "$work/root/usr/share/rugosim/scenes/figure12a.json" ] || fail "no scenes in the package"
  "$work/root/usr/bin/rugosim" --version | tee "$work/version.txt"
  grep -q "^rugosim $version$" "$work/version.txt" || fail "--version answered otherwise"
  ;;
*) fail "unknown mode $mode" ;;
esac
echo "install_test: $mode ok"
