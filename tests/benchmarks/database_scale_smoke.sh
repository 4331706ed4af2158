#!/usr/bin/env bash
# benchmarks/database_scale at tiny sizes: the table's format (every line
# the README and docs/results.md quote), the last line exactly
# "store time ratio last/first: R", the scratch database removed, and a
# usage error for bad arguments. No timing is asserted (speed targets live
# in benchmarks/, not in tests).
#   usage: database_scale_smoke.sh DATABASE_SCALE_EXECUTABLE
set -euo pipefail
program=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"

fail() { echo "FAIL: $*"; echo "--- output:"; cat output.txt; exit 1; }
number='[0-9]+\.[0-9]+'

"$program" 64 25 > output.txt || fail "exit status $?"
grep -Eq "^database_scale: 64 nodes \($number MB of positions per sample\), 25 samples$" output.txt ||
  fail "no header line"
grep -Eq "^first 10 samples +$number +$number$" output.txt || fail "no first-10 row"
grep -Eq "^last 10 samples +$number +$number$" output.txt || fail "no last-10 row"
grep -Eq "^total store time: $number s \($number ms per sample\)$" output.txt || fail "no total"
grep -Eq "^size on disk: $number MB$" output.txt || fail "no size"
tail -n 1 output.txt | grep -Eq "^store time ratio last/first: $number$" || fail "last line"
[ -z "$(ls)" ] || [ "$(ls)" = output.txt ] || fail "scratch files left: $(ls)"

# Bad arguments: exit status 1 and the usage, nothing written.
if "$program" 0 10 > output.txt 2>&1; then fail "0 nodes accepted"; fi
grep -q "usage: database_scale NODES SAMPLES" output.txt || fail "no usage for 0 nodes"
if "$program" 100 > output.txt 2>&1; then fail "a missing argument accepted"; fi
echo "database_scale output format: OK"
