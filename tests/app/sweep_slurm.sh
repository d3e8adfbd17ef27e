#!/usr/bin/env bash
# Sweeps through a real single-node Slurm cluster (tests/support/slurm_cluster.sh, started and
# stopped here):
#  1. the 64-task incline sweep (scenes/sweeps/incline_friction.json) as an array job
#     (--array=0-63, `--task auto` from SLURM_ARRAY_TASK_ID) and `--gather` as a job that depends
#     on it (afterok): the stick/slide boundary at tan θ = μ (tests/app/check_stick_boundary.sh),
#     and the same CSV, byte for byte, as the 64 tasks run one after another without Slurm;
#  2. a task cancelled by scancel half-way (a 200-body pile), which stops on SIGTERM and removes
#     its partial folder: the array resubmitted as it is skips the task done and runs it again.
# Usage: sweep_slurm.sh PROGRAM SOURCE_DIR WORK_DIR
set -euo pipefail
program=$(realpath "$1") source=$(realpath "$2") work=$3
spec="$source/scenes/sweeps/incline_friction.json"
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "sweep_slurm: $*" >&2; exit 1; }
# shellcheck source=../support/slurm_cluster.sh
source "$source/tests/support/slurm_cluster.sh"
slurm_start

quoted() { printf '%q ' "$@"; }
task=$(quoted "$program" sweep "$spec" -o "$work/out")
array=$(sbatch --parsable --chdir="$work" --output=task_%a.log --array=0-63 --wrap "$task --task auto")
gather=$(sbatch --parsable --chdir="$work" --output=gather.log --dependency="afterok:$array" \
  --wrap "$task --gather")
slurm_wait "$array" "$gather"
[ "$(slurm_state "$array")" = "COMPLETED" ] || { tail -n 3 task_*.log; fail "the array ended $(slurm_state "$array")"; }
[ "$(slurm_state "$gather")" = "COMPLETED" ] || { cat gather.log; fail "the gather job ended $(slurm_state "$gather")"; }
[ "$(cat task_*.log | grep -c ': done in ')" -eq 64 ] || fail "not every array task ran its task"
bash "$source/tests/app/check_stick_boundary.sh" out/sweep.csv || fail "the stick/slide boundary is not at tan θ = μ"
echo "slurm: 64 array tasks and the dependent gather COMPLETED; boundary at tan θ = μ"

for i in $(seq 0 63); do "$program" sweep "$spec" -o serial --task "$i" >/dev/null 2>&1 || fail "task $i failed without Slurm"; done
"$program" sweep "$spec" -o serial --gather >/dev/null 2>&1 || fail "the serial sweep does not gather"
cmp out/sweep.csv serial/sweep.csv || fail "Slurm's table differs from the serial run's"
echo "the same sweep.csv as the 64 tasks run one after another"

# Preemption: task 1 of a pile sweep (one thread, about 4 s of work) cancelled half-way: scancel
# sends SIGTERM, on which a task stops within its step and removes its partial folder. Then the
# array resubmitted as it is.
cat >pile.json <<SPEC
{ "version": 1, "scene": "$source/scenes/pile_200.json",
  "axes": [ { "name": "duration", "values": [0.1, 0.6], "pointer": "/world/duration" } ],
  "command": { "simulate": { "accuracy": "precise" } },
  "measures": [ { "name": "sim_time", "stats": "sim_time" } ] }
SPEC
pile=$(quoted "$program" sweep "$work/pile.json" -o "$work/pile" --threads 1)
first=$(sbatch --parsable --chdir="$work" --output=pile_%a.log --array=0-1 --wrap "$pile --task auto")
for _ in $(seq 600); do compgen -G "pile/.task_000001.partial-*/stats.json.tmp-*" >/dev/null && break; sleep 0.05; done
compgen -G "pile/.task_000001.partial-*/stats.json.tmp-*" >/dev/null || fail "task 1 did not start simulating within 30 s"
sleep 0.3
scancel "${first}_1"
slurm_wait "$first"
[ ! -e pile/task_000001 ] || fail "task 1 finished before it could be cancelled"
grep -q 'stopped with exit code 130; nothing kept' pile_1.log || { cat pile_1.log; fail "the cancelled task did not stop on SIGTERM"; }
for _ in $(seq 600); do compgen -G "pile/.task_000001.partial-*" >/dev/null || break; sleep 0.05; done
! compgen -G "pile/.task_000001.partial-*" >/dev/null || fail "the cancelled task left its partial folder"
[ -e pile/task_000000/result.json ] || { cat pile_0.log; fail "task 0 did not complete"; }
again=$(sbatch --parsable --chdir="$work" --output=again_%a.log --array=0-1 --wrap "$pile --task auto")
slurm_wait "$again"
[ "$(slurm_state "$again")" = "COMPLETED" ] || fail "the resubmitted array ended $(slurm_state "$again")"
grep -q 'done already' again_0.log || { cat again_0.log; fail "the resubmitted array redid task 0"; }
grep -q ': done in ' again_1.log || { cat again_1.log; fail "the resubmitted array did not run task 1"; }
"$program" sweep pile.json -o pile --gather >/dev/null 2>&1 || fail "the pile sweep does not gather"
echo "slurm: a cancelled task rerun by the resubmitted array alone; table complete"
slurm_stop
echo "sweep_slurm: ok"
