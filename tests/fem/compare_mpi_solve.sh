#!/bin/bash
# usage: compare_mpi_solve.sh MPIEXEC SOFTCHAIN FILE.prm
# Runs `softchain solve FILE.prm` on 1 and on 2 MPI ranks (in ./np1, ./np2;
# the .prm's output directory is relative) and compares their
# solve_summary.csv: the converged flag and the counts equal, the load factor
# and the cavity volume to relative 1e-8, the tip displacement vector to 1e-8
# of its length (a component that is zero by symmetry is round-off on both
# runs), the base force and moment to 1e-8 of their length plus 1e-9 N
# (N m): under pressure alone they are round-off, ~1e-12 (one code path in
# serial and in parallel), and the cavity pressure to 1e-8 of (|p| + 1 Pa).
# With contact, each obstacle's force and moment (three columns each, after
# the fifteen) to 1e-8 of their length plus 1e-9 N (N m), as the base's.
set -eu
mpiexec=$1 softchain=$2 prm=$3
for n in 1 2; do
  rm -rf "np$n"
  mkdir "np$n"
  (cd "np$n" && "$mpiexec" -np "$n" --oversubscribe "$softchain" solve "$prm")
done
one=np1/output/solve_summary.csv two=np2/output/solve_summary.csv
cat "$one" "$two"
awk -F, 'function abs(x) { return x < 0 ? -x : x }
         function differs(i, scale) {
           if (abs($i - a[i]) <= 1e-8 * scale) return 0
           print "column " i " differs by " abs($i - a[i]) " (scale " scale ")"
           return 1
         }
         NR == 2 { for (i = 1; i <= NF; ++i) a[i] = $i }
         NR == 4 {
           if (NF < 15 || (NF - 15) % 3 != 0) { print "expected 15 + 3k columns, got " NF; exit 1 }
           bad = ($1 != a[1] || $3 != a[3] || $4 != a[4])
           if (bad) print "converged flag or counts differ"
           tip = sqrt(a[5] ^ 2 + a[6] ^ 2 + a[7] ^ 2)
           bad += differs(2, abs(a[2])) + differs(5, tip) + differs(6, tip) + differs(7, tip)
           bad += differs(8, abs(a[8]))
           force = sqrt(a[9] ^ 2 + a[10] ^ 2 + a[11] ^ 2) + 0.1
           moment = sqrt(a[12] ^ 2 + a[13] ^ 2 + a[14] ^ 2) + 0.1
           for (i = 9; i <= 11; ++i) bad += differs(i, force)
           for (i = 12; i <= 14; ++i) bad += differs(i, moment)
           bad += differs(15, abs(a[15]) + 1)
           for (j = 16; j < NF; j += 3) {
             size = sqrt(a[j] ^ 2 + a[j + 1] ^ 2 + a[j + 2] ^ 2) + 0.1
             for (i = j; i < j + 3; ++i) bad += differs(i, size)
           }
           exit bad > 0
         }
         END { if (NR != 4) { print "expected a header and a row in each file"; exit 1 } }' \
  "$one" "$two"
