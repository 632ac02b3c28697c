#!/usr/bin/env bash
# The figures of poundfe run (report/run_summary.h; doc/verification.md,
# "Figures of a run"):
#  1. a frame row with hinges (input/three-buildings-row.prm): one
#     hysteresis loop per building, drawn from data blocks of hinges.csv's
#     columns, each a PNG and listed in summary.json; no figure missing;
#     with 'hinge states of B2, A3_C1.2_bottom', the loops of B2 (the same
#     hinge as with all recorded) and of A3_C1.2_bottom alone;
#  2. a shear pair of 14 storeys (14 gaps: more than a key names): the
#     contact figure is drawn (its curves, the pair's total force, are
#     checked in tests/report/test_contact_force_plot.cc), no figure missing;
#  3. a row of 15 shear buildings (more than a key names): the figures with a
#     curve per building (profiles, roof displacement, base shear), per
#     floor (floor spectra) and per pair (contact) are drawn, of the 12 with the largest peaks (the
#     selection is the one checked in 2), none missing.
set -eu
poundfe=$1 input=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL $*"; exit 1; }
is_png() { head -c 8 "$1" | od -An -tx1 | grep -q "89 50 4e 47 0d 0a 1a 0a"; }
no_missing() {
  python3 -c 'import json, sys; s = json.load(open(sys.argv[1])); sys.exit(1 if s.get("missing_figures") else 0)' \
    "$1/summary.json" || fail "missing figures in $1/summary.json"
}

"$poundfe" run "$input/three-buildings-row.prm" --output "$work/row" > /dev/null
loops=$(ls "$work/row" | grep -c '^hysteresis_.*\.png$' || true)
[ "$loops" -eq 3 ] || fail "$loops hysteresis loops for 3 buildings with hinges"
for png in "$work/row"/hysteresis_*.png; do
  is_png "$png" || fail "$(basename "$png") is not a PNG"
  grep -q "\"$(basename "$png")\"" "$work/row/summary.json" || fail "$(basename "$png") not listed"
done
no_missing "$work/row"
echo "ok   one hysteresis loop per building"
# the loops of the hinges recorded: B2's (all of them), A3's one, none of C4
sed 's/^subsection Output$/subsection Output\n  subsection Recorders\n    set Record = hinge states of B2, A3_C1.2_bottom; gap states of C4\n  end/' \
  "$input/three-buildings-row.prm" > "$work/chosen.prm"
"$poundfe" run "$work/chosen.prm" --output "$work/chosen" > /dev/null
loops=$(cd "$work/chosen" && ls hysteresis_*.png | tr '\n' ' ')
[ "$loops" = "hysteresis_A3_C1.2_bottom.png $(cd "$work/row" && ls hysteresis_B2_*.png) " ] ||
  fail "loops of the recorded hinges: $loops"
is_png "$work/chosen/contact_force.png" || fail "no contact_force.png of the recorded gaps"
no_missing "$work/chosen"
echo "ok   the loops of the recorded hinges: $loops"

sed -e 's/Number of storeys  = [23]/Number of storeys  = 14/' -e 's/Duration   = 10/Duration   = 2/' \
  "$input/shear-pair-pounding.prm" > "$work/tall.prm"
"$poundfe" run "$work/tall.prm" --output "$work/tall" > /dev/null
gaps=$(head -1 "$work/tall/contact_force.csv" | tr ',' '\n' | grep -c '_force_N$')
[ "$gaps" -eq 14 ] || fail "$gaps gaps, not 14"
is_png "$work/tall/contact_force.png" || fail "no contact_force.png"
no_missing "$work/tall"
echo "ok   contact forces of $gaps gaps as one pair's total"

python3 - > "$work/row15.prm" <<'PY'
print("subsection Model\n  set Number of buildings = 15\n  set Separations = 0.005\nend")
for b in range(15):
    print(f"""subsection Building {b + 1}
  set Name = R{b + 1:02d}
  set Type = shear
  set Number of storeys = {3 + b % 3}
  set Storey heights = 3.0
  set Floor masses = 1000
  set Storey stiffnesses = {2e6 + 3e5 * b}
end""")
print("""subsection Ground motion
  set Type = kanai-tajimi
  subsection Stochastic
    set Target PGA = 0.35
    set Duration = 2
    set Seed = 11
  end
end
subsection Contact
  set Law = linear
  set Stiffness = 5e8
end
subsection Time integration
  set Time step = 0.0025
end
subsection Output
  set Output interval = 0.01
  set VTU interval    = 0
  set Floor spectra   = true
  subsection Recorders
    set Record = base shear
  end
end""")
PY
"$poundfe" run "$work/row15.prm" --output "$work/row15" > /dev/null
for png in drift_profile acceleration_profile roof_displacement base_shear floor_spectra contact_force; do
  is_png "$work/row15/$png.png" || fail "no $png.png of 15 buildings"
done
no_missing "$work/row15"
echo "ok   the figures of 15 buildings"
