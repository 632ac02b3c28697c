#!/usr/bin/env bash
# The figures of poundfe run (report/run_summary.h; doc/verification.md,
# "Figures of a run"):
#  1. a frame row with hinges (input/three-buildings-row.prm): one
#     hysteresis loop per building, drawn from data blocks of hinges.csv's
#     columns, each a PNG and listed in summary.json; no figure missing;
#  2. a shear pair of 14 storeys (14 gaps: more than a key names): the
#     contact figure is drawn (its curves, the pair's total force, are
#     checked in tests/report/test_contact_force_plot.cc), no figure missing.
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

sed -e 's/Number of storeys  = [23]/Number of storeys  = 14/' -e 's/Duration   = 10/Duration   = 2/' \
  "$input/shear-pair-pounding.prm" > "$work/tall.prm"
"$poundfe" run "$work/tall.prm" --output "$work/tall" > /dev/null
gaps=$(head -1 "$work/tall/contact_force.csv" | tr ',' '\n' | grep -c '_force_N$')
[ "$gaps" -eq 14 ] || fail "$gaps gaps, not 14"
is_png "$work/tall/contact_force.png" || fail "no contact_force.png"
no_missing "$work/tall"
echo "ok   contact forces of $gaps gaps as one pair's total"
