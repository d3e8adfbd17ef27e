#!/usr/bin/env bash
# The property-based stress suite for MINUTES (issue 15): builds the release preset's program
# and stress runner, runs every kept regression scene (tests/stress/regressions and its long/
# folder of slower ones, which ctest leaves out), then, for the rest of the time, random valid
# scenes (tests/stress/random_scene.h) through
# `rugosim validate` and `rugosim simulate --strict` until the time is up, checking each for
# exit 0, zero accepted crossings, finite states, no energy gain beyond 1% of the scene's energy
# scale, bodies inside closed containers and the same trajectory with 1 and 2 threads
# (tests/stress/stress_runner.cpp). Prints a line per scene and a summary: scenes run, refused
# and why, failures, the slowest runs (wall s per simulated s) and the cost by scale.
#
# Usage: tests/stress/run_stress.sh MINUTES [FIRST_SEED]
#
# Seeds run from FIRST_SEED (default 1000, past the 1..30 that ctest runs) upwards; the same
# seed is the same scene on any machine. Work files go to build/release/stress-long/; a failing
# scene is copied to build/release/stress-long/failures/seed_N.json: once it is fixed, move it
# to tests/stress/regressions/ (where ctest runs it every time) or, if it takes more than a few
# seconds, to tests/stress/regressions/long/. CSVs of every scene are left in
# build/release/stress-long/. Exits 1 when a scene failed.
set -euo pipefail

if [ $# -lt 1 ] || ! [[ "$1" =~ ^[0-9]+([.][0-9]+)?$ ]]; then
  echo "usage: $0 MINUTES [FIRST_SEED]" >&2
  exit 2
fi
minutes=$1
first=${2:-1000}

cd "$(dirname "$0")/../.."
cmake --preset release >/dev/null
cmake --build --preset release --target rugosim stress_runner
work=build/release/stress-long
mkdir -p "$work"
# A copy of the program, so that rebuilding while this runs changes nothing under it.
cp build/release/rugosim "$work/rugosim"
start=$(date +%s)
status=0
# Every scene that ever failed first: those ctest runs, then the slower ones it leaves to this.
for kept in tests/stress/regressions tests/stress/regressions/long; do
  build/release/tests/stress_runner --program "$work/rugosim" --scenes "$kept" \
    --work "$work/kept" --csv "$work/kept_$(basename "$kept").csv" --guard 600 || status=1
done
left=$(awk -v m="$minutes" -v s="$(($(date +%s) - start))" 'BEGIN { r = m - s / 60; print (r > 0.1 ? r : 0.1) }')
build/release/tests/stress_runner --program "$work/rugosim" --minutes "$left" \
  --first-seed "$first" --work "$work/scenes" --keep "$work/failures" --csv "$work/scenes.csv" \
  --guard 600 || status=1
exit $status
