#!/usr/bin/env bash
# A Subset Simulation level whose samples cannot estimate its coefficient of
# variation (20 samples per level: the last level's CoV is NaN) reports it as
# undefined: an empty cell in subset_levels.csv, null in summary.json,
# "undefined" on the terminal; never "nan" in any of them.
#   subset_undefined_cov.sh POUNDFE SUBSET_DRIFT_PRM
set -u
poundfe=$1
input=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

"$poundfe" subset "$input" --set 'Subset simulation/Samples per level=20' \
  --set 'Output/Plots=false' --output out > stdout 2> stderr || fail "exit $?: $(cat stderr)"
grep -qi 'nan' out/subset_levels.csv && fail "nan in subset_levels.csv: $(cat out/subset_levels.csv)"
grep -qi 'nan' stdout && fail "nan on the terminal: $(cat stdout)"
grep -q 'CoV between undefined' stdout || fail "no undefined CoV on the terminal: $(cat stdout)"
# the level whose CoV is undefined: empty cells, and null in summary.json
grep -qE ',,,$' out/subset_levels.csv || fail "no level with empty CoV cells: $(cat out/subset_levels.csv)"
grep -q '"coefficient_of_variation": null' out/summary.json || fail "summary.json: no null CoV"
echo "$failures failures"
[ "$failures" -eq 0 ]
