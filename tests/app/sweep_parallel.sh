#!/usr/bin/env bash
# Sweeps through GNU parallel (Debian's `parallel`, -j2; `sweep --task auto` takes its index from
# PARALLEL_SEQ):
#  1. the 64-task incline sweep (scenes/sweeps/incline_friction.json, friction gain × angle), half
#     of it first, then the whole array resubmitted as it is: the 32 tasks done are skipped, the
#     rest run; gathered into a CSV in which the block sticks below tan θ = μ and slides above it
#     (within one grid step, tests/app/check_stick_boundary.sh);
#  2. a task killed (SIGKILL) half-way through a 200-body pile: the array resubmitted removes what
#     it left, reruns it alone, and the table completes.
# Usage: sweep_parallel.sh PROGRAM SOURCE_DIR WORK_DIR
set -euo pipefail
program=$(realpath "$1") source=$(realpath "$2") work=$3
spec="$source/scenes/sweeps/incline_friction.json"
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "sweep_parallel: $*" >&2; exit 1; }
command -v parallel >/dev/null || fail "GNU parallel is not installed (cmake/install-deps.sh)"
array() {  # array N SPEC OUT LOG: tasks 0..N-1 as GNU parallel runs them, two at a time
  seq "$1" | parallel --will-cite -j2 -N0 -q "$program" sweep "$2" -o "$3" --task auto >"$4" 2>&1 \
    || { cat "$4"; fail "a task of $2 failed"; }
}

[ "$("$program" sweep "$spec" -o out --list 2>/dev/null | grep -c 'to do$')" -eq 64 ] \
  || fail "--list does not show 64 tasks to do"
array 32 "$spec" out first.log
[ "$(ls -d out/task_* | wc -l)" -eq 32 ] || fail "the first half did not leave 32 task folders"
stamp=$(stat -c %Y.%y out/task_000007/result.json)
array 64 "$spec" out whole.log
[ "$(grep -c 'done already' whole.log)" -eq 32 ] || { cat whole.log; fail "the resubmitted array did not skip the 32 tasks done"; }
[ "$(grep -c ': done in ' whole.log)" -eq 32 ] || fail "the resubmitted array did not run the other 32"
[ "$(stat -c %Y.%y out/task_000007/result.json)" = "$stamp" ] || fail "a task done was redone"
"$program" sweep "$spec" -o out --gather >gather.log 2>&1 || { cat gather.log; fail "--gather failed"; }
bash "$source/tests/app/check_stick_boundary.sh" out/sweep.csv || fail "the stick/slide boundary is not at tan θ = μ"
[ -s out/plots/stick_map.png ] && [ -s out/plots/slide_vs_angle.png ] || fail "--gather drew no plots"
echo "incline: 64 tasks (32, then the array resubmitted: 32 skipped, 32 run), boundary at tan θ = μ"

# A task killed half-way: a 200-body pile for 0.6 s at precise on one thread (about 4 s of work)
# as task 1.
cat >pile.json <<SPEC
{ "version": 1, "scene": "$source/scenes/pile_200.json",
  "axes": [ { "name": "duration", "values": [0.1, 0.6], "pointer": "/world/duration" } ],
  "command": { "simulate": { "accuracy": "precise" } },
  "measures": [ { "name": "steps", "stats": "steps" }, { "name": "sim_time", "stats": "sim_time" } ] }
SPEC
"$program" sweep pile.json -o pile --task 0 >/dev/null 2>&1 || fail "pile task 0 failed"
stamp=$(stat -c %Y.%y pile/task_000000/result.json)
"$program" sweep pile.json -o pile --task 1 --threads 1 >killed.log 2>&1 &
victim=$!
for _ in $(seq 600); do compgen -G "pile/.task_000001.partial-*/stats.json.tmp-*" >/dev/null && break; sleep 0.05; done
compgen -G "pile/.task_000001.partial-*/stats.json.tmp-*" >/dev/null || fail "task 1 did not start simulating within 30 s"
sleep 0.3
kill -KILL "$victim"
wait "$victim" 2>/dev/null && fail "the task to kill had already finished"
[ ! -e pile/task_000001 ] || fail "a killed task left a result"
compgen -G "pile/.task_000001.partial-*" >/dev/null || fail "the killed task left no partial folder (killed too early?)"
array 2 pile.json pile rerun.log
grep -q 'that was stopped' rerun.log || { cat rerun.log; fail "the rerun did not remove the killed run's folder"; }
grep -q 'task 0 of 2 .*done already' rerun.log || fail "the rerun redid task 0"
[ "$(stat -c %Y.%y pile/task_000000/result.json)" = "$stamp" ] || fail "task 0 was redone"
! compgen -G "pile/.task_*" >/dev/null || fail "partial folders remain"
"$program" sweep pile.json -o pile --gather >/dev/null 2>&1 || fail "the pile sweep does not gather"
[ "$(tail -n 1 pile/sweep.csv | cut -d, -f4)" = "0.6" ] || { cat pile/sweep.csv; fail "task 1 did not simulate 0.6 s"; }
echo "pile: a task killed half-way, rerun by the resubmitted array alone; table complete"
echo "sweep_parallel: ok"
