#!/usr/bin/env bash
# A chunked render through a real single-node Slurm cluster (tests/support/slurm_cluster.sh,
# started and stopped here): the checkpoint pass as one job, the chunks as an array job
# (--array=0-3, --chunk auto/4 from SLURM_ARRAY_TASK_ID) after it (afterok), and the join after
# the array; at --crf 0 the joined clip's decoded frames equal a single render's (framemd5).
# Then the array resubmitted as it is skips every complete chunk.
# Usage: chunk_render_slurm.sh PROGRAM SOURCE_DIR WORK_DIR
set -euo pipefail
program=$(realpath "$1") source=$(realpath "$2") work=$3
scene="$source/scenes/figure12a.json"
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "chunk_render_slurm: $*" >&2; exit 1; }
# shellcheck source=../support/slurm_cluster.sh
source "$source/tests/support/slurm_cluster.sh"
slurm_start

# The job as `rugosim plan render` prints it: its Slurm recipe (the pass, the array after it, the
# join after the array), submitted as printed.
"$program" plan render "$scene" -o "$work/clip.mp4" --chunks 4 --every 15 --size 1280x720 \
  --crf 0 --checkpoints "$work/ck" --program "$program" >plan.txt
awk '/^# Slurm/ { on = 1; next } on && /^$/ { exit } on' plan.txt >recipe.sh
grep -q -- "--array=0-3" recipe.sh || fail "plan printed no Slurm array"
bash recipe.sh >submitted.txt || { cat recipe.sh; fail "the plan's Slurm recipe failed"; }
jobs=$(squeue -h -o %F | sort -u | tr '\n' ' ')
[ -n "$jobs" ] || fail "nothing was queued"
# shellcheck disable=SC2086
slurm_wait $jobs
ran=0
for job in $(scontrol -o show job | grep -o '^JobId=[0-9]*' | cut -d= -f2); do
  state=$(slurm_state "$job")
  [ "$state" = "COMPLETED" ] || { cat slurm-*.out 2>/dev/null; fail "job $job ended $state"; }
  ran=$((ran + 1))
done
[ "$ran" -eq 6 ] || fail "expected 6 jobs (pass, 4 array tasks, join), saw $ran"
echo "slurm: the pass, the 4 array tasks and the join: COMPLETED"

"$program" render "$scene" -o single.mp4 --size 1280x720 --crf 0 2>/dev/null
frames() { ffmpeg -v error -i "$1" -f framemd5 - | grep -v '^#' | awk -F, '{print $6}'; }
frames single.mp4 >single.md5
frames clip.mp4 >clip.md5
[ "$(wc -l <clip.md5)" -eq 151 ] || fail "the joined clip has not 151 frames"
cmp -s single.md5 clip.md5 || fail "the joined frames differ from the single render's"
echo "crf 0: 151 decoded frames equal (framemd5)"

# The array resubmitted as it is (a preempted job's rerun): every chunk is complete, skipped.
render="$(printf %q "$program") render $(printf %q "$scene") -o $(printf %q "$work/clip.mp4")"
render+=" --size 1280x720 --crf 0 --checkpoints $(printf %q "$work/ck")"
again=$(sbatch --parsable --chdir="$work" --output=again_%a.log --array=0-3 --wrap "$render --chunk auto/4")
slurm_wait "$again"
[ "$(slurm_state "$again")" = "COMPLETED" ] || fail "the resubmitted array failed"
[ "$(cat again_*.log | grep -c 'already complete')" -eq 4 ] || { cat again_*.log; fail "a rerun redid a chunk"; }
slurm_stop
echo "chunk_render_slurm: ok"
