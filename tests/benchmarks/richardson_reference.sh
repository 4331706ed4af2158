#!/usr/bin/env bash
# benchmarks/p10_error_time's Richardson reference and error table on a
# synthetic runs table (REPLOT=1: no FEM runs).
#   pressure scene: the Q2 runs (REFERENCE=Q2) follow f(h) = f_inf + C h^p
#     exactly, h = DoFs^(-1/3), at unequal refinement ratios (1.30, 1.36),
#     with p = 2 for the tip position and p = 3 for the rotation. The
#     extrapolation must return f_inf and the observed orders p (to the
#     printed 6 and 2 decimals; the fixed-point iteration converges to
#     round-off for an exact power law).
#   lateral scene: the corrections alternate in sign (no asymptotic range),
#     so the finest run is the reference and is flagged "finest".
#   A Q1 run 0.9 mm off the pressure reference in x has a tip error of
#     exactly 1 % of L = 90 mm.
#   usage: richardson_reference.sh SOURCE_DIR
set -euo pipefail
top=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
runs=$dir/synthetic_runs.csv
awk -v OFS=, 'BEGIN {
  print "model,mesh_size_mm,dofs,scene,status,load_steps,newton_iterations,time_s,peak_memory_MB,tip_x_mm,tip_y_mm,tip_z_mm,tip_rotation_deg"
  split("80 -50 0.5 75", f); split("-300 500 10 20000", c); split("2 2 2 3", p)
  split("50000 20000 9000", n)
  for (i = 1; i <= 3; ++i) {
    h = n[i] ^ (-1 / 3)
    row = "Q2,," n[i] ",pressure,converged,1,1," i ",100"
    for (q = 1; q <= 4; ++q) row = row "," sprintf("%.12f", f[q] + c[q] * h ^ p[q])
    print row
    sign = (i % 2) ? 1 : -1
    row = "Q2,," n[i] ",lateral,converged,1,1," i ",100"
    for (q = 1; q <= 4; ++q) row = row "," sprintf("%.12f", f[q] + sign * c[q] * h ^ 2)
    print row
  }
  print "Q1,,1000,pressure,converged,1,1,0.5,90,80.9,-50,0.5,77"
}' > "$runs"

log=$(REPLOT=1 REFERENCE=Q2 RESULTS=synthetic RESULTS_DIR="$dir" DEMO_OUTPUT="$dir/no_demo" \
      bash "$top/benchmarks/p10_error_time" 2>&1)
echo "$log"
fail() { echo "FAILED: $*"; exit 1; }
pressure=$(echo "$log" | sed -n 's/^  pressure: //p')
[ "$pressure" = "80.000000:2.00:extrapolated,-50.000000:2.00:extrapolated,0.500000:2.00:extrapolated,75.000000:3.00:extrapolated" ] ||
  fail "pressure reference '$pressure'"
# The finest lateral run (50000 DoFs): f_inf + C h^2, printed to 6 decimals.
finest=$(awk -F, '$4 == "lateral" && $3 == 50000 { printf "%.6f", $10 }' "$runs")
lateral_x=$(echo "$log" | sed -n 's/^  lateral: \([^,]*\),.*/\1/p')
[ "${lateral_x%%:*}" = "$finest" ] && [[ $lateral_x == *:finest ]] || fail "lateral reference '$lateral_x', expected finest run $finest"
q1=$(awk -F, '$1 == "Q1" && $4 == "pressure" { print $7 }' "$dir/synthetic_error.csv")
[ "$q1" = "1.0000" ] || fail "Q1 tip error '$q1' % of L, expected 1.0000"
q1_angle=$(awk -F, '$1 == "Q1" && $4 == "pressure" { print $8 }' "$dir/synthetic_error.csv")
[ "$q1_angle" = "2.000" ] || fail "Q1 angle error '$q1_angle' deg, expected 2.000"
echo "PASSED"
