#!/usr/bin/env bash
# A 3D run reports every direction (doc/verification.md, "Every direction of
# a 3D run"):
#  1. a symmetric linear 3D shear building shaken along y gives along y what
#     it gives along x when shaken along x, column for column, and at 45
#     degrees both directions carry 1/sqrt(2) of the motion (directions_3d.py);
#     the irregularity ratios along the axis without drift are null;
#  2. an undamped contact law (linear) dissipates exactly nothing, in 3D and
#     in 2D: the summary's contact energy, each gap's, energy.csv's column.
#   directions_3d.sh POUNDFE CLI_DIR INPUT_DIR
set -eu
poundfe=$1 here=$2 input=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL $*"; exit 1; }

# linear: no yield drift; the first component alone, turned by the angle
for angle in 0 90 45; do
  sed -e '/Storey yield drifts/d' \
      -e "s/set Type = kanai-tajimi/set Type = kanai-tajimi\n  set Incidence angle = $angle/" \
      "$here/3d-symmetric-shear.prm" > "$work/a$angle.prm"
  "$poundfe" run "$work/a$angle.prm" --output "$work/a$angle" > /dev/null
done
python3 "$here/directions_3d.py" "$work/a0" "$work/a90" "$work/a45" 1e-9 ||
  fail "the directions of a symmetric 3D building"
echo "ok   shaken along y = along x, column for column; at 45 degrees 1/sqrt(2) each; null ratios"

undamped() { # prm output
  "$poundfe" run "$1" --output "$2" > /dev/null
  python3 - "$2" <<'PY' || fail "an undamped law dissipates energy ($1)"
import csv, json, sys
s = json.load(open(sys.argv[1] + "/summary.json"))
assert s["contact"]["law"] == "linear" and "coefficient_of_restitution" not in s["contact"], s["contact"]
dissipated = [s["energy"]["contact_J"]] + [g["dissipated_energy_J"] for g in s["gaps"]]
column = [float(r["contact_J"]) for r in csv.DictReader(open(sys.argv[1] + "/energy.csv"))]
impacts = sum(g["impacts"] for g in s["gaps"])
print(f"{impacts} impacts; dissipated {max(map(abs, dissipated))} J, energy.csv {max(map(abs, column))} J")
sys.exit(impacts == 0 or any(x != 0 for x in dissipated + column))
PY
}
undamped "$input/3d-torsional-shear-pair.prm" "$work/pair-3d"
undamped "$input/shear-pair-pounding.prm" "$work/pair-2d"
echo "ok   an undamped contact law dissipates exactly nothing (3D and 2D)"
