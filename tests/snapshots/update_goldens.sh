#!/usr/bin/env bash
# Rewrites the project's own snapshot goldens: four frames of every built-in scene at 192×108
# (a few KB each), which `ctest -R snapshot.` compares with `rugosim snapshot`. Run it only when
# a change of pictures is intended, look at the new PNGs, and say why in the commit.
# Usage (from the repository root, after building): tests/snapshots/update_goldens.sh
set -euo pipefail
program=${RUGOSIM:-build/release/rugosim}
for scene in scenes/*.json; do
  case "$scene" in
    scenes/pile_200.json | scenes/pile_1000.json) continue ;;  # left to bench_pile
  esac
  "$program" snapshot "$scene" --golden tests/snapshots --size 192x108 --update
done
