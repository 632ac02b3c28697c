#!/usr/bin/env bash
# Model/Dimension = 3 through the command line (doc/verification.md, "3D shear
# buildings"):
#  1. a symmetric 3D shear building shaken along x gives the planar shear
#     building's floor displacements and drifts to 1e-10;
#  2. an eccentric building under two components: rotating them by 180 degrees
#     changes the sign of every response (floor displacements, drifts);
#  3. `modal` on the example prints the mass ratios along x, y and about z;
#  4. the example runs and reports impacts with their plan point.
set -eu
poundfe=$1 here=$2 input=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL $*"; exit 1; }
compare() { # a b sign what [pattern replacement]: b's columns by a's renamed
  for f in floor_displacement.csv drift.csv; do
    python3 "$here/same_columns.py" "$1/$f" "$2/$f" "$3" 1e-10 ${5:+"$5" "$6"} || fail "$4 ($f)"
  done
}

# the planar model has no Plan (its entries act only in 3D, and are refused in 2D)
sed -e 's/set Dimension = 3/set Dimension = 2/' -e '/subsection Plan/,/^  end/d' \
  "$here/3d-symmetric-shear.prm" > "$work/2d.prm"
"$poundfe" run "$here/3d-symmetric-shear.prm" --output "$work/3d" > /dev/null
"$poundfe" run "$work/2d.prm" --output "$work/2d" > /dev/null
# a planar column is the 3D one along x (S_floor1_disp_m: S_floor1_disp_x_m)
compare "$work/2d" "$work/3d" 1 "3D symmetric building differs from 2D" \
  '(_disp|_drift_ratio)(_m)?$' '\1_x\2'
echo "ok   symmetric 3D = 2D"

eccentric() { # angle output
  sed -e 's/set Dimension = 3/set Dimension = 3/' \
      -e 's/set Plan dimensions = 12, 9/set Plan dimensions = 12, 9\n    set Mass eccentricity = 1.5, -0.8/' \
      -e "s/set Type = kanai-tajimi/set Type = kanai-tajimi\n  set Components = 2\n  set Incidence angle = $1/" \
      "$here/3d-symmetric-shear.prm" > "$work/eccentric-$1.prm"
  "$poundfe" run "$work/eccentric-$1.prm" --output "$2" > /dev/null
}
eccentric 25 "$work/e25"
eccentric 205 "$work/e205"
compare "$work/e25" "$work/e205" -1 "180 degrees do not mirror the response"
grep -q '"torsional_irregularity_x"' "$work/e25/summary.json" || fail "no irregularity ratios"
echo "ok   rotating the ground motion by 180 degrees mirrors the response"

"$poundfe" modal "$input/3d-torsional-shear-pair.prm" --output "$work/modal" > "$work/modal.out"
grep -q "mass ratio (y)" "$work/modal.out" || fail "modal prints no y mass ratios"
grep -q '"participating_mass_ratio_rz"' "$work/modal/summary.json" || fail "no rz ratios"
echo "ok   modal in 3D"

"$poundfe" run "$input/3d-torsional-shear-pair.prm" --output "$work/pair" > /dev/null
head -1 "$work/pair/impacts.csv" | grep -q "plan_x_m,plan_y_m" || fail "impacts.csv without plan point"
[ "$(wc -l < "$work/pair/impacts.csv")" -gt 1 ] || fail "the example pounds nowhere"
echo "ok   the 3D example pounds ($(($(wc -l < "$work/pair/impacts.csv") - 1)) impacts)"
