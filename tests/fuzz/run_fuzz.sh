#!/usr/bin/env bash
# Fuzzes the scene loader for SECONDS: configures and builds the `fuzz` preset (clang,
# libFuzzer, ASan + UBSan), seeds a scratch corpus from the scene files in the repository and
# runs build/fuzz/tests/fuzz/fuzz_scene_loader. Exits non-zero when the fuzzer finds a crash,
# a sanitizer report, a broken invariant, a timeout or an out-of-memory, and prints the input
# that caused it.
#
# Usage: tests/fuzz/run_fuzz.sh SECONDS [libFuzzer options...]
#
# The corpus grows in build/fuzz/fuzz-corpus/ and is kept between runs; the repository stays
# clean. A crashing input goes into tests/scene/fuzz_regressions/NAME.json once fixed, where
# test_scene replays it; replay one by hand with: build/fuzz/tests/fuzz/fuzz_scene_loader FILE
set -euo pipefail

if [ $# -lt 1 ] || ! [[ "$1" =~ ^[0-9]+$ ]] || [ "$1" -lt 1 ]; then
  echo "usage: $0 SECONDS [libFuzzer options...]" >&2
  exit 2
fi
seconds=$1
shift

cd "$(dirname "$0")/../.."
root=$(pwd)
build="$root/build/fuzz"

cmake --preset fuzz
cmake --build --preset fuzz

# Seeds: every scene file of the repository, copied so that libFuzzer, which writes new
# inputs into its first corpus folder, never writes into the source tree.
seeds="$build/fuzz-seeds"
corpus="$build/fuzz-corpus"
artifacts="$build/fuzz-artifacts"
rm -rf "$seeds" "$artifacts"
mkdir -p "$seeds" "$corpus" "$artifacts"
n_seeds=0
for dir in tests/scene/bad scenes tests/scene/fuzz_regressions; do
  [ -d "$dir" ] || continue
  while IFS= read -r -d '' file; do
    # Flattened names (bad/12_q_zero.json -> tests_scene_bad_12_q_zero.json) cannot collide.
    cp "$file" "$seeds/$(echo "$file" | tr '/' '_')"
    n_seeds=$((n_seeds + 1))
  done < <(find "$dir" -type f -name '*.json' -print0)
done
echo "run_fuzz: $n_seeds seed files, corpus $corpus, ${seconds} s"

status=0
UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}" \
  "$build/tests/fuzz/fuzz_scene_loader" \
  -max_total_time="$seconds" -max_len=8192 -timeout=10 -rss_limit_mb=2048 \
  -dict="$root/tests/fuzz/scene.dict" -artifact_prefix="$artifacts/" -print_final_stats=1 \
  "$@" "$corpus" "$seeds" || status=$?

found=$(find "$artifacts" -type f | sort)
if [ "$status" -ne 0 ] || [ -n "$found" ]; then
  echo "run_fuzz: FAILED (libFuzzer exit status $status)" >&2
  for file in $found; do
    echo "run_fuzz: input: $file ($(wc -c <"$file") bytes), its first 2000 shown:" >&2
    # cat -v escapes control bytes, so binary input cannot confuse a terminal or a CI log.
    head -c 2000 "$file" | cat -v >&2
    echo >&2
    echo "run_fuzz: replay: $build/tests/fuzz/fuzz_scene_loader $file" >&2
    echo "run_fuzz: once fixed: cp $file tests/scene/fuzz_regressions/NAME.json" >&2
  done
  [ "$status" -ne 0 ] || status=1
  exit "$status"
fi
echo "run_fuzz: no crash in ${seconds} s; corpus: $(find "$corpus" -type f | wc -l) files"
