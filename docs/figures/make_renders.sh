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

# Roughness as the eye sees it. One rock (scenes/rock_closeup.json) at 256 px, 720p and 4K:
# the whole frame of each (top row) and the same 1/4 × 1/4 corner of each (bottom row), every
# panel scaled to 480×270 (the 256 px one by nearest neighbour, so its pixels show).
for size in 455x256 1280x720 3840x2160; do
  "$program" render scenes/rock_closeup.json -o "$work/rock_$size.png" --frame 0 --size "$size" \
    -y 2>/dev/null
done
panel='scale=480:270:flags=neighbor'
corner='crop=iw/4:ih/4:iw*3/8:ih/8,scale=480:270:flags=neighbor'
ffmpeg -loglevel error -y -i "$work/rock_455x256.png" -i "$work/rock_1280x720.png" \
  -i "$work/rock_3840x2160.png" -filter_complex \
  "[0]split[a0][b0];[1]split[a1][b1];[2]split[a2][b2];\
[a0]$panel[p0];[a1]scale=480:270:flags=area[p1];[a2]scale=480:270:flags=area[p2];\
[b0]$corner[c0];[b1]$corner[c1];[b2]$corner[c2];\
[p0][p1][p2]hstack=3[top];[c0][c1][c2]hstack=3[bottom];[top][bottom]vstack" \
  -frames:v 1 "$out/roughness_resolutions.png"
# figure12a at 720p, frame 30, with render.roughness_scale 1, 3 and 10 (the rocks and floor).
for scale in 1 3 10; do
  "$program" render scenes/figure12a.json -o "$work/scale_$scale.png" --frame 30 \
    --roughness-scale "$scale" -y 2>/dev/null
done
ffmpeg -loglevel error -y -i "$work/scale_1.png" -i "$work/scale_3.png" -i "$work/scale_10.png" \
  -filter_complex "[0]crop=760:200:260:390[a];[1]crop=760:200:260:390[b];\
[2]crop=760:200:260:390[c];[a][b][c]vstack=3" -frames:v 1 "$out/roughness_scales.png"

# figure12a for slides: as a GIF, with text, as a grid, and in each theme. The text and theme
# keys go into a copy of the scene (docs/scene-format.md, "render").
"$program" render scenes/figure12a.json -o "$out/figure12a.gif" --size 480x270 --fps 15 -y \
  2>/dev/null
strip figure12a 6 320x180 figure12a_grid.png --columns 3 --strip-labels
text_keys='"title": "Eight rough rocks (σ = 3 mm)", "caption": "rugosim: figure 12a of the paper",
  "clock": true, "scale_bar": true,'
themed() {  # theme out.png size
  sed "s/\"render\": {/\"render\": { $(echo "$text_keys" | tr -d '\n') \"theme\": \"$1\",/" \
    scenes/figure12a.json >"$work/figure12a_$1.json"
  "$program" render "$work/figure12a_$1.json" -o "$2" --frame 45 --size "$3" -y 2>/dev/null
}
themed paper "$out/figure12a_text.png" 640x360
for theme in paper dark print; do themed "$theme" "$work/theme_$theme.png" 480x270; done
ffmpeg -loglevel error -y -i "$work/theme_paper.png" -i "$work/theme_dark.png" \
  -i "$work/theme_print.png" -filter_complex "vstack=3" -frames:v 1 "$out/themes.png"

# A vector still (the SVG itself, which the README shows as it is) and a transparent PNG still.
"$program" render scenes/figure12a_slide.json -o "$out/figure12a_slide.svg" --frame 90 \
  --size 640x360 -y 2>/dev/null
sed 's/"render": {/"render": { "background": "transparent",/' scenes/figure12a.json \
  >"$work/transparent.json"
"$program" render "$work/transparent.json" -o "$out/figure12a_transparent.png" --frame 45 \
  --size 480x270 -y 2>/dev/null
