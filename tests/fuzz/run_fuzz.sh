#!/usr/bin/env bash
# Fuzzes the scene loader for SECONDS and the command line for half as long (at least 10 s):
# configures and builds the `fuzz` preset (clang, libFuzzer, ASan + UBSan), seeds scratch
# corpora (the scene files of the repository; command lines from tests/fuzz/command_lines.txt)
# and runs build/fuzz/tests/fuzz/fuzz_scene_loader and fuzz_command_line. Exits non-zero when
# a fuzzer finds a crash, a sanitizer report, a broken invariant, a timeout or an
# out-of-memory, and prints the input that caused it.
#
# Usage: tests/fuzz/run_fuzz.sh SECONDS [libFuzzer options...]
#
# The corpora grow in build/fuzz/fuzz-corpus*/ and are kept between runs; the repository stays
# clean. A crashing scene goes into tests/scene/fuzz_regressions/NAME.json once fixed, where
# test_scene replays it; a crashing command line becomes a line of
# tests/fuzz/command_lines.txt (and a case of tests/app/number_options_test.cpp). Replay one
# by hand with: build/fuzz/tests/fuzz/fuzz_scene_loader FILE (or fuzz_command_line FILE).
set -euo pipefail

if [ $# -lt 1 ] || ! [[ "$1" =~ ^[0-9]+$ ]] || [ "$1" -lt 1 ]; then
  echo "usage: $0 SECONDS [libFuzzer options...]" >&2
  exit 2
fi
seconds=$1
shift
cli_seconds=$((seconds / 2 > 10 ? seconds / 2 : 10))

cd "$(dirname "$0")/../.."
root=$(pwd)
build="$root/build/fuzz"

cmake --preset fuzz
cmake --build --preset fuzz

# Seeds are copies, so that libFuzzer, which writes new inputs into its first corpus folder,
# never writes into the source tree.
seeds="$build/fuzz-seeds"
cli_seeds="$build/fuzz-seeds-command-line"
artifacts="$build/fuzz-artifacts"
rm -rf "$seeds" "$cli_seeds" "$artifacts"
mkdir -p "$seeds" "$cli_seeds" "$build/fuzz-corpus" "$build/fuzz-corpus-command-line" "$artifacts"
n_seeds=0
for dir in tests/scene/bad scenes tests/scene/fuzz_regressions; do
  [ -d "$dir" ] || continue
  while IFS= read -r -d '' file; do
    # Flattened names (bad/12_q_zero.json -> tests_scene_bad_12_q_zero.json) cannot collide.
    cp "$file" "$seeds/$(echo "$file" | tr '/' '_')"
    n_seeds=$((n_seeds + 1))
  done < <(find "$dir" -type f -name '*.json' -print0)
done
# One seed per command line: its words separated by NUL bytes, as the target cuts them.
n_cli=0
while IFS= read -r line; do
  [ -z "$line" ] || [[ "$line" == \#* ]] && continue
  n_cli=$((n_cli + 1))
  printf '%s' "$line" | tr ' ' '\0' >"$cli_seeds/line_$n_cli"
done <tests/fuzz/command_lines.txt

status=0
# fuzz TARGET SECONDS DICT MAX_LEN CORPUS SEEDS [libFuzzer options...]
fuzz() {
  local target=$1 time=$2 dict=$3 max_len=$4 corpus=$5 seed_dir=$6
  shift 6
  echo "run_fuzz: $target, corpus $corpus, ${time} s"
  UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}" \
    "$build/tests/fuzz/$target" \
    -max_total_time="$time" -max_len="$max_len" -timeout=10 -rss_limit_mb=2048 \
    -dict="$dict" -artifact_prefix="$artifacts/$target-" -print_final_stats=1 \
    "$@" "$corpus" "$seed_dir" || status=$?
}
echo "run_fuzz: $n_seeds scene seeds, $n_cli command-line seeds"
fuzz fuzz_scene_loader "$seconds" "$root/tests/fuzz/scene.dict" 8192 "$build/fuzz-corpus" \
  "$seeds" "$@"
fuzz fuzz_command_line "$cli_seconds" "$root/tests/fuzz/command_line.dict" 512 \
  "$build/fuzz-corpus-command-line" "$cli_seeds" "$@"

found=$(find "$artifacts" -type f | sort)
if [ "$status" -ne 0 ] || [ -n "$found" ]; then
  echo "run_fuzz: FAILED (libFuzzer exit status $status)" >&2
  for file in $found; do
    echo "run_fuzz: input: $file ($(wc -c <"$file") bytes), its first 2000 shown:" >&2
    # cat -v escapes control bytes, so binary input cannot confuse a terminal or a CI log.
    head -c 2000 "$file" | cat -v >&2
    echo >&2
    target=$(basename "$file" | sed 's/-.*//')
    echo "run_fuzz: replay: $build/tests/fuzz/$target $file" >&2
  done
  [ "$status" -ne 0 ] || status=1
  exit "$status"
fi
echo "run_fuzz: no crash; corpora: $(find "$build/fuzz-corpus" -type f | wc -l) scene files," \
  "$(find "$build/fuzz-corpus-command-line" -type f | wc -l) command lines"
