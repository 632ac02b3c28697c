#!/usr/bin/env bash
# The bidirectional Bouc-Wen law through the command line (doc/verification.md,
# "Bidirectional Bouc-Wen"; theory §2.8):
#  1. the symmetric 3D shear building shaken along x alone: with Plan/Storey
#     law = bidirectional Bouc-Wen its planes' pairs see no drift across x, so
#     the floor displacements and drifts are those of the uniaxial planes
#     (1e-10 of each column's peak: round-off of the LU path it takes);
#  2. the eccentric building under two components: the pairs yield under
#     their resultant (the response differs from the planes'), and the energy
#     balance closes to 1e-8;
#  3. the 3D frame pair of input/3d-torsional-pair.prm (cut to 2 s) with
#     Hinges/Biaxial interaction = true runs to the end, its hinges report
#     and its energy balance closes as the shipped example's (1e-6).
set -eu
poundfe=$1 here=$2 input=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL $*"; exit 1; }
balance() { sed -n 's/.*"max_relative_balance_error": \([^,}]*\).*/\1/p' "$1/summary.json"; }
bidirectional() { # input output
  sed 's/set Plan dimensions = 12, 9/set Plan dimensions = 12, 9\n    set Storey law = bidirectional Bouc-Wen/' \
      "$1" > "$2"
}

bidirectional "$here/3d-symmetric-shear.prm" "$work/along-x.prm"
"$poundfe" run "$here/3d-symmetric-shear.prm" --output "$work/planes" > /dev/null
"$poundfe" run "$work/along-x.prm" --output "$work/pairs" > /dev/null
for f in floor_displacement.csv drift.csv; do
  python3 "$here/same_columns.py" "$work/planes/$f" "$work/pairs/$f" 1 1e-10 ||
    fail "the bidirectional law along x differs from the planes' ($f)"
done
echo "ok   along x the bidirectional storey law is the planes' uniaxial law"

sed -e 's/set Plan dimensions = 12, 9/set Plan dimensions = 12, 9\n    set Mass eccentricity = 1.5, -0.8/' \
    -e 's/set Type = kanai-tajimi/set Type = kanai-tajimi\n  set Components = 2\n  set Incidence angle = 25/' \
    "$here/3d-symmetric-shear.prm" > "$work/eccentric.prm"
bidirectional "$work/eccentric.prm" "$work/eccentric-pairs.prm"
"$poundfe" run "$work/eccentric.prm" --output "$work/e-planes" > /dev/null
"$poundfe" run "$work/eccentric-pairs.prm" --output "$work/e-pairs" > /dev/null
python3 "$here/same_columns.py" "$work/e-planes/drift.csv" "$work/e-pairs/drift.csv" 1 1e-3 > /dev/null &&
  fail "under two components the pairs yield as the independent planes"
error=$(balance "$work/e-pairs")
awk -v e="$error" 'BEGIN { exit !(e != "" && e <= 1e-8) }' || fail "energy balance error $error"
echo "ok   two components: the pairs interact, energy balance error $error"

sed -e 's/set Duration         = 6/set Duration         = 2/' \
    -e 's/set Locations    = column bases/set Locations    = column bases\n    set Biaxial interaction = true/' \
    "$input/3d-torsional-pair.prm" > "$work/frames.prm"
grep -q "Biaxial interaction = true" "$work/frames.prm" || fail "the frame input was not edited"
"$poundfe" run "$work/frames.prm" --output "$work/frames" > /dev/null
grep -q '"status": "completed"' "$work/frames/summary.json" || fail "frames with biaxial hinges not completed"
[ -s "$work/frames/hinges.csv" ] || fail "no hinges.csv"
error=$(balance "$work/frames")
awk -v e="$error" 'BEGIN { exit !(e != "" && e < 1e-6) }' || fail "frames: energy balance error $error"
echo "ok   3D frames with biaxial hinges, energy balance error $error"
