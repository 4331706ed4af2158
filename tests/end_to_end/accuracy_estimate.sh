#!/usr/bin/env bash
# `softchain accuracy` on P10 with 16 mm hexahedra at 40 kPa (four solves,
# about a minute): the table holds the design's run, three sheet runs and
# the converged estimate; the sheet runs converge (each refinement moves the
# tip less than the one before: measured 6.2 mm, then 1.2 mm); the design's
# distance to the estimate, recomputed here from the table's tips, is the
# printed error (to the 3 digits printed); the design's run names the design
# hash of the database a sweep of the same .prm writes.
#   accuracy_estimate.sh SOFTCHAIN PARAMETER_DIR
set -euo pipefail
softchain=$1
parameters=$2
out=$PWD/accuracy-out
rm -rf "$out"
sed -e "s/^\( *set Mesh sizes *=\).*/\1 0.016, 0.004, 0.0018/" \
    -e "s#^subsection Design#subsection Design\n  set Output directory = $out#" \
    "$parameters/p10.prm" > accuracy.prm
"$softchain" accuracy accuracy.prm > accuracy.log 2>&1 || { cat accuracy.log; echo "FAIL: accuracy did not run"; exit 1; }
cat accuracy.log
table=$out/fem_accuracy.csv
[ "$(wc -l < "$table")" -eq 6 ] || { echo "FAIL: $table should have a header and 5 rows"; exit 1; }
# Rows 2-5: design, sheets at 16, 11.3, 8 mm; row 6: the estimate.
awk -F, 'NR >= 3 && NR <= 5 { x[NR] = $7; y[NR] = $8 }
  END { d1 = sqrt((x[4] - x[3]) ^ 2 + (y[4] - y[3]) ^ 2); d2 = sqrt((x[5] - x[4]) ^ 2 + (y[5] - y[4]) ^ 2)
        printf "sheet refinements move the tip by %.3f, then %.3f mm\n", d1, d2; exit !(d2 < d1) }' "$table" ||
  { echo "FAIL: the sheet runs do not converge"; exit 1; }
printed=$(sed -n 's/^FEM discretisation error: \([0-9.e+-]*\) % of L.*/\1/p' accuracy.log)
[ -n "$printed" ] || { echo "FAIL: no 'FEM discretisation error' line"; exit 1; }
awk -F, -v printed="$printed" 'NR == 2 { x = $7; y = $8; z = $9 } NR == 6 { cx = $7; cy = $8; cz = $9 }
  END { e = 100 * sqrt((x - cx) ^ 2 + (y - cy) ^ 2 + (z - cz) ^ 2) / 90
        printf "design to estimate: %.4f %% of L (printed %s)\n", e, printed
        exit !(e > 0 && (e - printed) ^ 2 <= (5e-3 * e) ^ 2) }' "$table" ||
  { echo "FAIL: the printed error is not the design's distance to the estimate"; exit 1; }
# The table names the design it was made for: the design's own run carries the
# hash of the database `softchain sweep` writes for the same .prm (the report
# shows the error only for that database), the sheet runs other hashes.
hash=$(awk -F, 'NR == 2 { print $11 }' "$table")
[[ "$hash" =~ ^[0-9a-f]{16}$ ]] || { echo "FAIL: the design's run has no design hash ('$hash')"; exit 1; }
[ "$(awk -F, -v h="$hash" 'NR >= 3 && NR <= 5 && $11 == h' "$table")" = "" ] ||
  { echo "FAIL: a sheet run has the design's hash"; exit 1; }
sed -e "s/^\( *set \(Lateral tip forces\|Torsion couples\|Bending tip forces\|Chord samples\|Skin samples\|Validation samples\|Contact samples\) *=\).*/\1/" \
    -e "s/^\( *set Pressure sweep *=\).*/\1 40e3/" -e "s/^\( *set Tip angle *=\).*/\1 0/" \
    accuracy.prm > accuracy_sweep.prm
"$softchain" sweep accuracy_sweep.prm > accuracy_sweep.log 2>&1 || { cat accuracy_sweep.log; echo "FAIL: sweep"; exit 1; }
grep -aq "$hash" "$out/database.h5" ||
  { echo "FAIL: the database's design hash is not the table's $hash"; exit 1; }
echo "accuracy estimate: OK"
