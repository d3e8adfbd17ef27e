#!/usr/bin/env bash
# A render split into chunks by GNU parallel and joined (docs/scale-out.md), against the single
# render of the same clip: figure12a at 1280x720, 4 chunks on `parallel -j2` with
# `--chunk auto/4` (PARALLEL_SEQ), after one checkpoint pass — run as `rugosim plan render`
# prints it (its GNU parallel recipe, executed as printed, in a folder whose name has a space).
#   --crf 0 (lossless): the joined clip's decoded frames equal the single render's (framemd5).
#   default CRF: PSNR of the joined clip against the single render >= 45 dB on every frame, and
#   the joined clip plays as one clip of the single render's duration and frame count.
# Then a rerun of the same job skips the complete chunks, and join refuses a missing chunk.
# Usage: chunk_render_parallel.sh PROGRAM SOURCE_DIR WORK_DIR
set -euo pipefail
program=$(realpath "$1") source=$2 work=$3
scene="$source/scenes/figure12a.json"
rm -rf "$work" && mkdir -p "$work/job dir" && cd "$work/job dir"
fail() { echo "chunk_render_parallel: $*" >&2; exit 1; }
command -v parallel >/dev/null || fail "GNU parallel is not installed (cmake/install-deps.sh)"
parallel --version | grep -q "GNU parallel" || fail "'parallel' is not GNU parallel"

frames() { ffmpeg -v error -i "$1" -f framemd5 - | grep -v '^#' | awk -F, '{print $6}'; }
for crf in 0 18; do
  "$program" render "$scene" -o "single$crf.mp4" --size 1280x720 --crf "$crf" 2>/dev/null
  "$program" plan render "$scene" -o "$PWD/clip$crf.mp4" --chunks 4 --every 15 --size 1280x720 \
    --crf "$crf" --checkpoints "$PWD/ck$crf" --program "$program" >"plan$crf.txt"
  # The recipe: from its heading to the blank line after it, run as printed.
  awk '/^# GNU parallel/ { on = 1; next } on && /^$/ { exit } on' "plan$crf.txt" >"recipe$crf.sh"
  grep -q "parallel -j2 -N0 -q" "recipe$crf.sh" || fail "plan printed no GNU parallel recipe"
  PARALLEL="--will-cite" bash "recipe$crf.sh" 2>"parallel$crf.log" ||
    { cat "recipe$crf.sh" "parallel$crf.log"; fail "the plan's GNU parallel recipe failed (crf $crf)"; }
  for i in 0 1 2 3; do [ -f "clip$crf.chunk$i.mp4" ] || fail "chunk $i missing (crf $crf)"; done
  single_duration=$(ffprobe -v error -show_entries format=duration -of csv=p=0 "single$crf.mp4")
  joined_duration=$(ffprobe -v error -show_entries format=duration -of csv=p=0 "clip$crf.mp4")
  [ "$single_duration" = "$joined_duration" ] ||
    fail "joined clip lasts $joined_duration s, the single render $single_duration s (crf $crf)"
  frames "single$crf.mp4" >"single$crf.md5"
  frames "clip$crf.mp4" >"clip$crf.md5"
  [ "$(wc -l <"single$crf.md5")" -eq 151 ] || fail "the single render has not 151 frames"
  [ "$(wc -l <"clip$crf.md5")" -eq 151 ] || fail "the joined clip has not 151 frames (crf $crf)"
done
cmp -s single0.md5 clip0.md5 || fail "at --crf 0 the joined frames differ from the single render's"
echo "crf 0: 151 decoded frames equal (framemd5)"
# Per-frame PSNR of the joined default-CRF clip against the single render.
ffmpeg -v error -i clip18.mp4 -i single18.mp4 -lavfi "psnr=stats_file=psnr.log" -f null -
worst=$(awk '{for (i = 1; i <= NF; i++) if ($i ~ /^psnr_avg:/) { split($i, v, ":"); print v[2] }}' \
  psnr.log | sort -g | head -1)
echo "default CRF: worst frame PSNR $worst dB"
awk -v w="$worst" 'BEGIN { exit !(w == "inf" || w >= 45) }' ||
  fail "a frame of the joined clip is $worst dB from the single render (expected >= 45)"

# Resubmitting the same job: every chunk is complete and skipped, nothing is rewritten.
before=$(stat -c %Y clip18.chunk2.mp4)
seq 4 | parallel --will-cite -j2 -N0 "$program" render "$scene" -o clip18.mp4 --size 1280x720 \
  --crf 18 --chunk auto/4 --checkpoints ck18 2>rerun.log
grep -c "already complete" rerun.log | grep -q '^4$' || { cat rerun.log; fail "a rerun redid a chunk"; }
[ "$(stat -c %Y clip18.chunk2.mp4)" = "$before" ] || fail "a complete chunk was rewritten"
rm clip18.chunk3.mp4
if "$program" join clip18.mp4 --chunks 4 -y 2>join.log; then fail "join accepted a missing chunk"; fi
grep -q "chunk 3 of 4 is missing" join.log || { cat join.log; fail "join did not name the missing chunk"; }
# A chunk file of another render (here another CRF) is neither skipped nor overwritten without -y,
# and join refuses chunks of two renders.
if "$program" render "$scene" -o clip18.mp4 --size 1280x720 --crf 20 --chunk 2/4 \
  --checkpoints ck18 2>stale.log; then fail "a chunk of another render was reused"; fi
grep -q "is not chunk 2 of 4 of this render" stale.log || { cat stale.log; fail "no reason given"; }
for i in 0 1 2 3; do cp "clip0.chunk$i.mp4" "mixed.chunk$i.mp4"; done
cp clip18.chunk2.mp4 mixed.chunk2.mp4
if "$program" join mixed.mp4 --chunks 4 2>mixed.log; then fail "join mixed two renders"; fi
grep -q "mixed.chunk2.mp4: not chunk 2 of 4 of the same render" mixed.log ||
  { cat mixed.log; fail "join did not name the foreign chunk"; }
[ ! -e mixed.mp4 ] || fail "a refused join wrote its output"
echo "chunk_render_parallel: ok"
