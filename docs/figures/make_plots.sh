#!/usr/bin/env bash
# Redraws the README's plots: simulates figure06_* and figure09_* and plots their friction
# (fig. 8) and velocity (figs. 10, 11) into docs/images/plots/<scene>/.
# Usage (from the repository root, after building): docs/figures/make_plots.sh
set -euo pipefail
program=${RUGOSIM:-build/release/rugosim}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for scene in figure06_type1_type1 figure06_type2_type1 figure06_type3_type4 figure06_type4_type2 \
             figure09_constant figure09_type2_type3; do
  "$program" simulate "scenes/$scene.json" --trajectory "$work/$scene.trajectory.csv" \
    --events "$work/$scene.events.csv" 2>/dev/null
  (cd "$work" && "$OLDPWD/$program" plot --events "$scene.events.csv" \
     --trajectory "$scene.trajectory.csv" -o "$OLDPWD/docs/images/plots/$scene")
done
