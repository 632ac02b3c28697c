#!/usr/bin/env bash
# The pushover command and the gravity analysis through the real binary:
#   bad input (exit 1, one line naming the entry, nothing written): a control
#     building or floor that does not exist, a cyclic push without a
#     protocol, a non-positive target drift, a negative floor load;
#   a push that cannot go on (a mechanism at once: storeys with no
#     post-yield stiffness pushed beyond their strength without arc length)
#     exits 2 with the curve so far in pushover.csv and a failed summary;
#   ASCE 41's target without a Spectrum/Target, with an unknown site class or
#     C_m outside (0, 1]: exit 1;
#   the example input: pushover.csv, summary.json with the gravity state and
#     the capacity curve's idealisation, N2 and ASCE 41 targets (7-28 and
#     mu_strength recomputed from the reported terms), and a run of the same
#     file that starts from the gravity state (summary.json "gravity").
#   pushover.sh POUNDFE SOURCE_DIR
set -u
poundfe=$(readlink -f "$1") source=$(readlink -f "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
. "$source/tests/cli/expect.sh"

# a shear building with $1 in Building 1 and $2 in the Pushover section
push() {
  shear "$1"
  printf 'subsection Ground motion\n  set Type = none\nend\n'
  printf 'subsection Pushover\n%s\nend\n' "${2:-}"
}

push '' '  set Control building = 2' > building.prm
expect 1 "Pushover/Control building" pushover building.prm --output out
push '' '  set Control floor = 4' > floor.prm
expect 1 "Pushover/Control floor" pushover floor.prm --output out
push '' '  set Type = cyclic' > protocol.prm
expect 1 "Pushover/Protocol" pushover protocol.prm --output out
push '' '  set Target drift = 0' > target.prm
expect 1 "Pushover/Target drift" pushover target.prm --output out
push '' '  set Target drift = -0.01' > negative-target.prm
expect 1 "Pushover/Target drift" pushover negative-target.prm --output out
# ASCE 41's target: a Spectrum/Target, a known site class, C_m in (0, 1]
push '' '  set Target method = ASCE41' > asce-spectrum.prm
expect 1 "Pushover/Target method" pushover asce-spectrum.prm --output out
spectrum='subsection Spectrum\n  set Target = ec8-type-1\nend\n'
{ push '' '  set Target method = both
  set ASCE41 site class = G'; printf "$spectrum"; } > asce-site.prm
expect 1 "Pushover/ASCE41 site class" pushover asce-site.prm --output out
for cm in 0 1.5 -0.5; do
  { push '' "  set Target method = ASCE41
  set ASCE41 effective mass factor = $cm"; printf "$spectrum"; } > asce-cm.prm
  expect 1 "Pushover/ASCE41 effective mass factor" pushover asce-cm.prm --output out
done
push '  set Floor loads = 1e4, -5, 0' '' > loads.prm
expect 1 "Building 1/Floor loads" pushover loads.prm --output out
expect 1 "Building 1/Floor loads" run loads.prm --output out

# storeys that yield in the first step, which one Newton iteration cannot
# converge, with one step cut and no arc length: exit 2, the curve so far
push '  set Storey yield drifts = 0.002
  subsection Bouc-Wen
    set alpha = 0
    set n = 40
  end' '  set Target drift = 0.5
  set Number of steps = 5
  set Max step cuts = 1
  set Max iterations = 1
  set Arc length = false' > mechanism.prm
expect 2 "pushover: no equilibrium" pushover mechanism.prm --output out
[ -s out/pushover.csv ] && [ "$(wc -l < out/pushover.csv)" -ge 2 ] ||
  fail "a failed pushover keeps no curve: $(ls out 2>&1)"
grep -q '"status": "failed"' out/summary.json || fail "a failed pushover's summary: $(cat out/summary.json)"

# the example: a frame with gravity first, its pushover and its run
example=$source/input/pushover-frame.prm
n=$((n + 1))
if "$poundfe" pushover "$example" --output push > stdout 2> stderr; then
  python3 - push/summary.json push/pushover.csv <<'PY' || fail "pushover's outputs"
import csv, json, sys
s = json.load(open(sys.argv[1]))
assert s["status"].startswith("completed"), s["status"]
g = s["gravity"]
assert g["peak_displacement_m"] > 0 and all(r > 0 for r in g["base_vertical_reactions_N"]), g
c = s["capacity"]
assert 0 < c["yield_displacement_m"] < c["ultimate_displacement_m"], c
assert c["target_displacement_m"] > 0, c
# ASCE 41 (Target method = both): its equation 7-28 from the reported terms
import math
a = c["asce41"]
assert a["computed"] is True and a["C0"] > 1 and a["C1"] >= 1 and a["C2"] >= 1 and a["converged"], a
assert a["effective_period_s"] >= a["initial_period_s"] and a["site_class"] == "D", a
assert 0 < a["yield_base_shear_N"] <= s["peak_base_shear_N"] * (1 + 1e-12), a
t = a["C0"] * a["C1"] * a["C2"] * a["spectral_acceleration_m_s2"] * (a["effective_period_s"] / (2 * math.pi)) ** 2
assert abs(a["target_displacement_m"] - t) <= 1e-9 * t, (a, t)
mu = a["spectral_acceleration_m_s2"] * a["seismic_mass_kg"] * a["effective_mass_factor"] / a["yield_base_shear_N"]
assert abs(a["strength_ratio"] - mu) <= 1e-9 * mu, (a, mu)
rows = list(csv.DictReader(open(sys.argv[2])))
assert len(rows) > 10 and float(rows[0]["load_factor"]) == 0.0
assert float(rows[-1]["base_shear_N"]) > 0
PY
  echo "ok   pushover $example"
else
  fail "pushover $example: $(head -c 400 stderr)"
fi
n=$((n + 1))
if "$poundfe" run "$example" --output run --set "Time integration/End time=0.2" > stdout 2> stderr; then
  grep -q '"gravity"' run/summary.json || fail "run after gravity: no gravity in summary.json"
  echo "ok   run $example"
else
  fail "run $example: $(head -c 400 stderr)"
fi
report pushover
