#!/usr/bin/env bash
# Redraws the README's stills and film strips with `rugosim render` into docs/images/render/.
# Usage (from the repository root, after building): docs/figures/make_renders.sh
set -euo pipefail
program=${RUGOSIM:-build/release/rugosim}
out=docs/images/render
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
still() {  # scene frame size out.png [render options...]
  local scene=$1 frame=$2 size=$3 target=$4
  shift 4
  "$program" render "scenes/$scene.json" -o "$work/f_%d.png" --frames "$frame:$frame" \
    --size "$size" -y "$@" 2>/dev/null
  mv "$work/f_$frame.png" "$out/$target"
}
strip() {  # scene frames size out.png [render options...]
  local scene=$1 count=$2 size=$3 target=$4
  shift 4
  "$program" render "scenes/$scene.json" -o "$out/$target" --strip "$count" --size "$size" -y \
    "$@" 2>/dev/null
}
still figure12a 24 960x540 figure12a.png
still figure12a 24 960x540 figure12a_overlays.png --overlay rugosity,contacts,velocity
strip figure12a 6 320x180 figure12a_strip.png
strip figure12b 6 320x180 figure12b_strip.png
still figure09_type2_type3 20 960x360 figure09_type2_type3.png --overlay rugosity,velocity
strip figure09_type2_type3 6 320x120 figure09_type2_type3_strip.png
