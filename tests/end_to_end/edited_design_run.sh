#!/usr/bin/env bash
# A user copies parameter_files/p10.prm, edits it (another name,
# another pressure list, thinner walls, contact samples within it, no
# validation protocol) and runs
# `softchain run` on the copy: the whole pipeline works without touching
# code, and the edit takes effect. (The protocol's 90-degree inflation and
# 12 tip motions would add minutes; tests/end_to_end/protocol_test.cc covers
# it on the tiny bender.)
#   edited_design_run.sh SOFTCHAIN PARAMETER_DIR
# Resolution 0 and Newton tolerances of 1e-4 keep it to about a minute (the
# update bound |du| <= 1e-4 |u| moves a tip angle of ~20 degrees by ~2e-3
# degrees, far below the margin asserted below).
set -euo pipefail
softchain=$1
parameters=$2
sed -e "s/^\( *set Name *=\).*/\1 my_finger/" \
    -e "s#^subsection Design#subsection Design\n  set Output directory = out-my_finger#" \
    -e "s/^\( *set Wall thickness *=\).*/\1 0.002/" \
    -e "s/^\( *set Pressure sweep *=\).*/\1 5e3, 10e3/" \
    -e "s/^\( *set Lateral tip forces *=\).*/\1 0.1/" \
    -e "s/^\( *set Torsion couples *=\).*/\1 0.1/" \
    -e "s/^\( *set Bending tip forces *=\).*/\1 0.1/" \
    -e "s/^\( *set Force sample pressures *=\).*/\1 0/" \
    -e "s/^\( *set Chord samples *=\).*/\1 0 : tip : 0.5,0,0/" \
    -e "s/^\( *set Skin samples *=\).*/\1 0 : 0.055,0,0 : palm 0.1/" \
    -e "s/^\( *set Validation samples *=\).*/\1 7.5e3/" \
    -e "s/^\( *set Contact samples *=\).*/\1 table : 10e3 ; cylinder : 10e3/" \
    -e "s/^\( *set Tip angle *=\).*/\1 0/" \
    "$parameters/p10.prm" > my_finger.prm
printf 'subsection Solver\n  set Residual tolerance = 1e-4\n  set Displacement tolerance = 1e-4\nend\n' >> my_finger.prm
grep -q "^ *set Tip angle *= 0$" my_finger.prm || { echo "FAIL: the edit did not turn the protocol off"; exit 1; }
rm -rf out-my_finger
status=0
"$softchain" run my_finger.prm > run.log 2>&1 || status=$?
[ "$status" = 0 ] || { cat run.log; echo "FAIL: softchain run exited $status"; exit 1; }
for file in database.h5 stiffness/M2_b0.50a.csv chain/validation.csv chain/fem_tip_poses.csv report.html; do
  [ -s "out-my_finger/$file" ] || { cat run.log; echo "FAIL: no out-my_finger/$file"; exit 1; }
done
# The chain is validated on the pressure and validation samples (the
# default Chain/Validation roles): 5 and 10 kPa and the 7.5 kPa sample.
samples=$(($(wc -l < out-my_finger/chain/fem_tip_poses.csv) - 1))
[ "$samples" = 5 ] || { echo "FAIL: $samples FEM tip poses, expected 5 (2 pressure, 1 validation, 2 contact)"; exit 1; }
# The thinner walls take effect: the shipped P10 (2.5 mm walls) bends 14.93
# degrees at 10 kPa (measured, output/p10/chain/fem_tip_poses.csv). The top
# wall's bending stiffness falls about in proportion to its thickness (0.8x)
# while the cavity grows, so 2 mm walls bend more (measured 20.98 degrees);
# 15.7 (5 % above P10) separates the two.
angle=$(awk -F, '$3 == 10000 && $2 == "pressure" { print $8 }' out-my_finger/chain/fem_tip_poses.csv)
echo "my_finger (2 mm walls): tip bending angle at 10 kPa $angle deg (P10 with 2.5 mm: -14.93)"
awk -v a="$angle" 'BEGIN { exit !(a < 0 && -a > 15.7) }' || { echo "FAIL: the wall edit did not soften the finger"; exit 1; }
