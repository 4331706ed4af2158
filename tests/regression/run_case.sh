#!/usr/bin/env bash
# One regression case: `softchain run` on CASE/case.prm in WORK (a fresh
# output, the mesh cache inside WORK), then gold_compare of every gold CSV
# file against the output within CASE/tolerances. With a LAUNCHER (e.g.
# "mpirun -np 2") the run goes through it: the gold holds for any rank count.
#   run_case.sh SOFTCHAIN GOLD_COMPARE CASE WORK [LAUNCHER...]
set -euo pipefail
softchain=$1 compare=$2 case=$3 work=$4
shift 4
launcher=("$@")
rm -rf "$work" && mkdir -p "$work" && cd "$work"
cp "$case/case.prm" .
if ! "${launcher[@]}" "$softchain" run case.prm > run.log 2>&1; then
  echo "softchain run failed on $case/case.prm:"; tail -20 run.log; exit 1
fi
name=$(awk '/^subsection Design/ { d = 1 } d && /set Name/ { print $4; exit }' case.prm)
"$compare" "$case/gold" "output/$name" "$case/tolerances"
