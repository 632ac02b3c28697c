#!/usr/bin/env bash
# `separation` with a site hazard (theory §7.1, Separation/Site hazard):
#  - the hazard of `poundfe site-hazard` (input/site-hazard.prm) read from its
#    hazard_curve.csv and from its summary.json: both report the gap for
#    10 % in 50 years on the console and in summary.json, and agree to 1e-6
#    (the Gumbel rate exp(-(I - u)/s) with I linear in log PGA is a power law
#    in PGA, which the CSV's log-log interpolation keeps to its 17 digits);
#  - P(pounding in 50 years) at the gap for the target is the target
#    (pounding_hazard.csv interpolated here, 2 %: the grid's spacing);
#  - without a hazard, no pounding_hazard.csv;
#  - a missing hazard file and a target outside (0, 1): exit 1, one message,
#    nothing written;
#  - twin buildings (identical, so they move in phase: the largest approach
#    is 0 and the lognormal demand cannot be fitted): exit 2, the cause on
#    stderr and in summary.json ("failed"), the per-event results written.
set -eu
poundfe=$1 pair=$2 site=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/helpers.sh"

"$poundfe" site-hazard "$site" --output "$work/hazard" > /dev/null || fail "site-hazard"
with_hazard() { # file, target, name[, model file] -> a parameter file
  { cat "${4:-$pair}"; printf 'subsection Separation\n  subsection Site hazard\n    set File = %s\n    set PGA levels = 0.02, 0.05, 0.1\n    set Target probability = %s\n  end\nend\n' "$1" "$2"; } > "$work/$3.prm"
  echo "$work/$3.prm"
}
gap_of() { python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["site_hazard"]["pairs"][0]["gap_for_target_probability_m"])' "$1"; }

for source in hazard_curve.csv summary.json; do
  prm=$(with_hazard "$work/hazard/$source" 0.1 "${source%%.*}")
  "$poundfe" separation "$prm" --output "$work/${source%%.*}" > "$work/${source%%.*}.log" 2> /dev/null ||
    fail "separation with $source"
  grep -q "gap for P = 0.1 in 50 years" "$work/${source%%.*}.log" || fail "$source: no gap on the console"
done
csv_gap=$(gap_of "$work/hazard_curve/summary.json") json_gap=$(gap_of "$work/summary/summary.json")
python3 - "$csv_gap" "$json_gap" "$work/summary/pounding_hazard.csv" <<'PY' || fail "hazard curve against fit"
import csv, sys
a, b = float(sys.argv[1]), float(sys.argv[2])
if not (a > 0 and abs(a - b) <= 1e-6 * b):
    sys.exit(f"gap {a} m (hazard_curve.csv) against {b} m (summary.json)")
rows = list(csv.reader(open(sys.argv[3])))[1:]
g = [float(r[0]) for r in rows]; p = [float(r[2]) for r in rows]
i = next(i for i in range(len(g)) if g[i] >= b)
at = p[i - 1] + (p[i] - p[i - 1]) * (b - g[i - 1]) / (g[i] - g[i - 1])
if abs(at - 0.1) > 0.002:
    sys.exit(f"P(pounding in 50 years) at the gap for 0.1 is {at}")
PY
echo "ok   separation with a site hazard: gap for 10 % in 50 years $json_gap m (fit), $csv_gap m (hazard_curve.csv)"

"$poundfe" separation "$pair" --output "$work/none" > /dev/null 2>&1 || fail "separation without a hazard"
[ -e "$work/none/pounding_hazard.csv" ] && fail "a pounding_hazard.csv without a hazard"
echo "ok   separation without a hazard: no pounding_hazard.csv"

expect_input_error() { # prm, message
  if "$poundfe" separation "$1" --output "$work/bad" > "$work/bad.log" 2>&1; then fail "accepted: $2"; fi
  grep -q "$2" "$work/bad.log" || { cat "$work/bad.log"; fail "no message '$2'"; }
  [ -e "$work/bad" ] && fail "output written for bad input: $2"
  return 0
}
expect_input_error "$(with_hazard "$work/missing.csv" 0.1 missing)" "cannot open the hazard file"
expect_input_error "$(with_hazard "$work/hazard/summary.json" 1.5 target)" "Target probability"
echo "ok   separation with a missing hazard file or a target outside (0, 1): exit 1, nothing written"

# Twins: building 2 made a copy of building 1 (named twin)
python3 - "$pair" "$work/twins-base.prm" <<'PY'
import sys
s = open(sys.argv[1]).read()
one = s[s.index("subsection Building 1"):s.index("subsection Building 2")]
twin = one.replace("Building 1", "Building 2").replace("shear3", "twin")
s = s[:s.index("subsection Building 2")] + twin + s[s.index("subsection Ground motion"):]
open(sys.argv[2], "w").write(s)
PY
twins=$(with_hazard "$work/hazard/hazard_curve.csv" 0.1 twins "$work/twins-base.prm")
status=0
"$poundfe" separation "$twins" --output "$work/twins" > "$work/twins.log" 2> "$work/twins.err" || status=$?
[ "$status" -eq 2 ] || fail "twins: exit status $status"
grep -q "numerical failure: site hazard: pair shear3-twin: a realization whose buildings never approach" "$work/twins.err" ||
  fail "twins: no cause on stderr: $(cat "$work/twins.err")"
python3 - "$work/twins/summary.json" <<'PY' || fail "twins: summary.json"
import json, sys
s = json.load(open(sys.argv[1]))
assert s["status"] == "failed", s["status"]
assert "never approach" in s["message"] and s["site_hazard"]["status"] == "failed"
assert s["pairs"][0]["levels"], "no per-event levels"
PY
[ -s "$work/twins/separation.csv" ] && [ -s "$work/twins/pounding_probability.csv" ] || fail "twins: per-event results not written"
[ ! -e "$work/twins/pounding_hazard.csv" ] || fail "twins: a pounding_hazard.csv without a fit"
echo "ok   twin buildings (largest approach 0): exit 2, the cause on stderr and in summary.json, per-event results kept"

# Random parameters at the hazard's PGA levels: a lognormal storey stiffness
# of building 1. At the level equal to the file's Target PGA (0.1 g: the
# amplitude factor is 1) realization r runs the same loading and the same
# sampled structure as realization r of the Monte Carlo at the file's PGA, so
# pga_0.1g/realizations.csv's largest approach is the largest of the
# levels' approaches in realizations.csv, to the last digit; the nominal
# structure (what the levels ran before) gives other values.
prm=$(with_hazard "$work/hazard/hazard_curve.csv" 0.1 random)
sed -i 's/set PGA levels = 0.02, 0.05, 0.1/set PGA levels = 0.05, 0.1/' "$prm"
printf 'subsection Random parameters\n  set Variables = k: Building 1/Storey stiffnesses ~ lognormal mean 5e6 cov 0.3\nend\n' >> "$prm"
"$poundfe" separation "$prm" --output "$work/random" > /dev/null 2>&1 || fail "separation with a hazard and random parameters"
python3 - "$work/random/realizations.csv" "$work/random/pga_0.1g/realizations.csv" "$work/none/realizations.csv" <<'PY' || fail "random parameters at the hazard's levels"
import csv, sys
def largest(path):
    rows = list(csv.DictReader(open(path)))
    return [max(float(v) for k, v in r.items() if k.endswith("approach_m")) for r in rows]
at_file, at_level, nominal = largest(sys.argv[1]), largest(sys.argv[2]), largest(sys.argv[3])
assert len(at_level) == len(at_file) == 12, (len(at_level), len(at_file))
assert at_level == at_file, (at_level, at_file)
assert sum(a != b for a, b in zip(at_level, nominal)) == 12, "the levels ran the nominal structure"
PY
echo "ok   separation with a hazard and a random storey stiffness: the 0.1 g level's largest approaches = the Monte Carlo's (12 of 12), none the nominal's"
