#!/usr/bin/env bash
# A 3D run reports every direction (doc/verification.md, "Every direction of
# a 3D run"):
#  1. a symmetric linear 3D shear building shaken along y gives along y what
#     it gives along x when shaken along x, column for column, and at 45
#     degrees both directions carry 1/sqrt(2) of the motion (directions_3d.py),
#     base and storey shears, residual drifts and the peak profiles included;
#     the irregularity ratios along the axis without drift are null;
#  2. an undamped contact law (linear) lists no damping and no restitution in
#     summary.json.
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
      -e "s/set Number of modes = 3/set Number of modes = 3\n  subsection Recorders\n    set Record = base shear; storey shear; residual drift\n  end/" \
      "$here/3d-symmetric-shear.prm" > "$work/a$angle.prm"
  "$poundfe" run "$work/a$angle.prm" --output "$work/a$angle" > /dev/null
done
python3 "$here/directions_3d.py" "$work/a0" "$work/a90" "$work/a45" 1e-9 ||
  fail "the directions of a symmetric 3D building"
echo "ok   shaken along y = along x, column for column; at 45 degrees 1/sqrt(2) each; null ratios"

# an undamped law (linear) lists no restitution of its own in summary.json
"$poundfe" run "$input/3d-torsional-shear-pair.prm" --output "$work/pair-3d" > /dev/null
python3 - "$work/pair-3d/summary.json" <<'PY' || fail "an undamped law's summary lists restitution or damping"
import json, sys
contact = json.load(open(sys.argv[1]))["contact"]
sys.exit(contact["law"] != "linear" or "coefficient_of_restitution" in contact or "damping_parameter" in contact)
PY
echo "ok   an undamped contact law lists no damping and no restitution"
