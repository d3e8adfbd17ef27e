#!/usr/bin/env bash
# Ctrl-C during `rugosim simulate`: exit 130, and the trajectory written so far is complete
# (header, whole rows from frame 0 on), with no temporary file left behind.
# Usage: simulate_sigint.sh PROGRAM SOURCE_DIR WORK_DIR
set -u
program=$1 source=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
"$program" simulate "$source/tests/app/drifting_disk.json" \
  --trajectory "$work/trajectory.csv" --stats "$work/stats.json" 2>"$work/stderr.txt" &
pid=$!
sleep 1.5
kill -INT "$pid"
wait "$pid"
code=$?
fail() { echo "FAIL: $*"; cat "$work/stderr.txt"; exit 1; }
[ "$code" -eq 130 ] || fail "exit code $code, expected 130"
[ -f "$work/trajectory.csv" ] || fail "no trajectory.csv"
[ -f "$work/stats.json" ] || fail "no stats.json"
head -1 "$work/trajectory.csv" | grep -qx "frame,time,body,x,y,angle,vx,vy,omega,kinetic_energy" \
  || fail "bad header"
rows=$(($(wc -l <"$work/trajectory.csv") - 1))
[ "$rows" -ge 10 ] || fail "only $rows rows"
# Every row whole: 10 fields.
awk -F, 'NR > 1 && NF != 10 { bad = 1 } END { exit bad }' "$work/trajectory.csv" || fail "a partial row"
ls "$work" | grep -q tmp- && fail "a temporary file was left"
grep -q interrupted "$work/stderr.txt" || fail "no 'interrupted' summary"
echo "interrupted after $rows rows: exit 130, files complete"
rm -rf "$work"
