#!/usr/bin/env bash
# Draws the README's speed plot (docs/images/speed.png): wall time per simulated second against
# the number of bodies, log-log, for rugosim at draft and normal (on every CPU) and Box2D 2.4.1,
# from a run of bench_pile. The run takes about 25 minutes here (Box2D's 1,000-body pile alone
# takes 11); give a table from an earlier run to redraw without it.
# Usage (from the repository root, after building):
#   docs/figures/make_speed_plot.sh [TABLE.tsv]
set -euo pipefail
table=${1:-}
if [ -z "$table" ]; then
  table=out/bench_pile.tsv
  mkdir -p out
  build/release/bench/bench_pile --ratio_table="$table"
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# rugosim on the most threads the table has (named like normal_2_threads), else on one.
most_threads() {
  local v
  v=$(awk -F'\t' -v p="$1" '$1 == "pile" && $2 ~ "^" p "_[0-9]+_threads$" { print $2 }' "$table" |
        sort -t_ -k2 -n | tail -n 1)
  echo "${v:-$1_1_thread}"
}
draft=$(most_threads draft)
normal=$(most_threads normal)
# Each run is 5 simulated seconds: ns per run / 5e9 = wall seconds per simulated second.
for variant in box2d_1_sample "$draft" "$normal"; do
  awk -F'\t' -v v="$variant" '$1 == "pile" && $2 == v { split($3, a, "/"); print a[1], $4 / 5e9 }' \
    "$table" | sort -n > "$work/$variant.dat"
done
gnuplot <<GNUPLOT
set terminal pngcairo size 900,560 font ",12"
set output "docs/images/speed.png"
set logscale xy
set xlabel "bodies in the pile"
set ylabel "wall time per simulated second (s)"
set title "Piles settling for 5 s: rugosim (every CPU of this machine) and Box2D 2.4.1"
set key bottom right
set grid
set xrange [8:1300]
set xtics (10, 50, 200, 1000)
plot "$work/box2d_1_sample.dat" with linespoints lw 2 pt 7 title "Box2D 2.4.1 (1 outline point per segment)", \
     "$work/$normal.dat" with linespoints lw 2 pt 5 title "rugosim normal", \
     "$work/$draft.dat" with linespoints lw 2 pt 9 title "rugosim draft"
GNUPLOT
echo "wrote docs/images/speed.png"
