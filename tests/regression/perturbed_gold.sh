#!/usr/bin/env bash
# The regression check must fail when the gold differs from the output: a
# copy of CASE/gold with one number of FILE, COLUMN, ROW (1 = the first data
# row) scaled by 1 + 1e-3 -- ten times the loosest relative tolerance of the
# cases -- compared with the output of the case's run in WORK. Passes if
# gold_compare exits 1 naming that cell.
#   perturbed_gold.sh GOLD_COMPARE CASE WORK FILE COLUMN ROW
set -euo pipefail
compare=$1 case=$2 work=$3 file=$4 column=$5 row=$6
gold=$(mktemp -d)
trap 'rm -rf "$gold"' EXIT
cp -r "$case/gold/." "$gold"
awk -F, -v OFS=, -v col="$column" -v row="$row" '
  NR == 1 { for (i = 1; i <= NF; ++i) if ($i == col) c = i; print; next }
  NR == row + 1 { $c = sprintf("%.17g", $c * (1 + 1e-3)) } { print }' "$case/gold/$file" > "$gold/$file"
name=$(awk '/^subsection Design/ { d = 1 } d && /set Name/ { print $4; exit }' "$case/case.prm")
set +e
out=$("$compare" "$gold" "$work/output/$name" "$case/tolerances")
status=$?
set -e
echo "$out"
[ $status -eq 1 ] && grep -q "$file, row $((row + 1)), column $column" <<< "$out"
