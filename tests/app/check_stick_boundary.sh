#!/usr/bin/env bash
# Checks the gathered incline sweep (scenes/sweeps/incline_friction.json, `sweep --gather`): 64
# rows; for each friction gain, the block sticks (moves less than 1 mm in its second second) at
# the low angles and slides at the high ones, and the first angle at which it slides is within
# one grid step of the first with tan θ > μ. Prints the boundary per μ.
# Usage: check_stick_boundary.sh SWEEP.csv
set -euo pipefail
csv=$1
awk -F, '
  NR == 1 {
    for (i = 1; i <= NF; ++i) column[$i] = i
    split("gain angle mu tan_angle stick", needed, " ")
    for (i in needed) if (!(needed[i] in column)) { print "no column " needed[i] > "/dev/stderr"; exit 1 }
    next
  }
  {
    rows++
    gain = $column["gain"]
    if (!(gain in count)) order[++gains] = gain
    k = ++count[gain]
    if ($column["stick"] != "0" && $column["stick"] != "1") { printf("task %s: stick is \"%s\", not 0 or 1\n", $1, $column["stick"]) > "/dev/stderr"; bad_row = 1 }
    angle[gain, k] = $column["angle"]
    stick[gain, k] = $column["stick"]
    mu[gain] = $column["mu"]
    tangent[gain, k] = $column["tan_angle"]
  }
  END {
    if (rows != 64) { printf("expected 64 rows, got %d\n", rows) > "/dev/stderr"; exit 1 }
    bad = bad_row
    for (g = 1; g <= gains; ++g) {
      gain = order[g]; n = count[gain]
      observed = n + 1; predicted = n + 1
      for (k = n; k >= 1; --k) if (stick[gain, k] == 0) observed = k
      for (k = n; k >= 1; --k) if (tangent[gain, k] + 0 > mu[gain] + 0) predicted = k
      # Sticking below the boundary, sliding above it: no stick after the first slide.
      for (k = observed; k <= n; ++k) if (stick[gain, k] != 0) { bad = 1; printf "gain %s: sticks again at %s deg\n", gain, angle[gain, k] }
      diff = observed - predicted; if (diff < 0) diff = -diff
      shown = observed <= n ? angle[gain, observed] " deg" : "none"
      expect = predicted <= n ? angle[gain, predicted] " deg" : "none"
      printf "mu = %-5g slides from %-7s (tan theta > mu from %s)%s\n", mu[gain], shown, expect, (diff > 1 ? "  WRONG" : "")
      if (diff > 1) bad = 1
    }
    exit bad
  }
' "$csv"
