#!/bin/bash
# usage: compare_mpi_solve.sh MPIEXEC SOFTCHAIN FILE.prm
# Runs `softchain solve FILE.prm` on 1 and on 2 MPI ranks (in ./np1, ./np2;
# the .prm's output directory is relative) and compares their
# solve_summary.csv: the converged flag and the counts equal, the load factor
# and the cavity volume to relative 1e-6, the tip displacement vector to 1e-6
# of its length, the base force and moment to 1e-6 of their length plus 1e-7
# N (N m), and the cavity pressure to 1e-6 of (|p| + 1 Pa). With contact,
# each obstacle's force and moment (three columns each, after the fifteen)
# to 1e-6 of their length plus 1e-7 N (N m), as the base's. 1e-6 is Newton's
# residual and displacement tolerance: one rank solves the load steps before
# the last inexactly (single-precision factors and GMRES to the forcing
# term of NewtonSolver), two ranks exactly, so their paths differ within
# the intermediate tolerance and their answers within Newton's (measured
# 6.6e-9 of the tip displacement and 1.6e-8 of an obstacle's force); a
# numbering or gathering error moves them by far more.
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
           if (abs($i - a[i]) <= 1e-6 * scale) return 0
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
