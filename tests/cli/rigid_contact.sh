#!/usr/bin/env bash
# Contact/Model = nonsmooth (rigid contact, Moreau-Jean with Siconos
# Numerics, doc/theory.md §3.9d) through `poundfe run` on the shear pair of
# input/shear-pair-pounding.prm for 10 s (three impacts):
#   - impacts are logged with their impulses (> 0) and velocity jumps, the
#     separation velocity e times the approach velocity for an impact of a
#     single step (Newton's law; the floors are also driven by the storeys
#     and the ground within the step, hence 2 % on velocities >= 0.05 m/s);
#   - the gaps' penetration stays below the step's travel, |U| h;
#   - the energy balance, with the energy lost at impacts as the contact
#     term, closes to 1e-9 (theta = 1/2 on a linear model is exact);
#   - no warning that the (undamped) law ignores the restitution, one that
#     the law's Stiffness written in the file has no effect;
#   - summary.json's contact names the model, theta, the LCP solver, e per
#     pair and the LCPs' counts, not the law's stiffness; each impact's
#     largest penetration time lies within the impact;
#   - an LCP not solved to its tolerance (NSGS capped at one sweep, two
#     coupled contacts of tests/cli/rigid-squeeze.prm; Lemke solves it) stops
#     the run with exit 2, the step and residual named, the results so far
#     kept (summary.json "failed");
# then bad input: Theta outside [1/2, 1], a restitution outside [0, 1], no
# gaps (Law = none), a command that does not take it (modal, dynamic-form), fibre members,
# friction surfaces, a Friction coefficient on a 2D gap, with penalty
# contact or negative: exit 1, one message naming the file, line and parameter, no
# output directory. A build without Siconos refuses nonsmooth itself
# (Contact/Model) and offers penalty only.
set -u
poundfe=$1 input=$2
inputs=$(cd "$(dirname "$input")" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
. "$here/expect.sh"

sed -e '/^subsection Contact/a\  set Model = nonsmooth\n  set Coefficient of restitution = 0.65' \
    -e 's/^\( *set Duration *=\).*/\1 10/' -e 's/^\( *set Time step *=\).*/\1 1e-4/' \
    "$input" > pair.prm
if ! "$poundfe" --version | grep -q "nonsmooth"; then
  expect 1 "parameter 'Contact/Model'" run pair.prm --output out
  echo "rigid-contact: this build has no Siconos (penalty only): refused as it should"
  exit $((failures > 0))
fi
"$poundfe" run pair.prm --output run > /dev/null 2> run.err || fail "run exited $?"
# the restitution is Newton's law's: no warning that the linear law ignores it
! grep -q "parameter 'Contact/Coefficient of restitution'" run.err || fail "moot warning: $(cat run.err)"
python3 - run <<'PY' || fail "rigid contact run"
import csv, json, sys
run = sys.argv[1]
impacts = list(csv.DictReader(open(f"{run}/impacts.csv")))
assert impacts, "no impacts"
h, e = 1e-4, 0.65
single = 0
for i in impacts:
    P, va, vs = float(i["impulse_N_s"]), float(i["approach_velocity_m_s"]), float(i["separation_velocity_m_s"])
    assert P > 0, i
    assert float(i["max_penetration_m"]) <= abs(va) * h + 1e-12, i
    if i["end_time_s"] and float(i["end_time_s"]) - float(i["start_time_s"]) <= 1.001 * h and va >= 0.05:
        single += 1
        assert abs(vs - e * va) <= 0.02 * va, (vs, e * va)
assert single > 0, "no single-step impact"
s = json.load(open(f"{run}/summary.json"))
energy = s["energy"]
print(f"{len(impacts)} impacts ({single} single-step checked), contact {energy['contact_J']:.4g} J, "
      f"balance error {energy['max_relative_balance_error']:.3g}")
assert energy["contact_J"] > 0
assert energy["max_relative_balance_error"] <= 1e-9, energy
# the contact as rigid contact has it: no law stiffness, e per pair, the LCPs
c = s["contact"]
assert c["model"] == "nonsmooth" and c["theta"] == 0.5 and c["lcp_solver"] == "lemke", c
assert "stiffness" not in c and "law" not in c, c
assert [p["coefficient_of_restitution"] for p in c["pairs"]] == [e] * len(s["gaps"]), c
# (Lemke reports no iteration count: its iterations are 0)
assert c["lcp"]["solves"] > 0 and c["lcp"]["mean_iterations"] <= c["lcp"]["max_iterations"], c
# the largest residual of the run's LCPs (Siconos's lcp_compute_error), each solved
assert 0 <= c["lcp"]["max_residual"] <= c["lcp_tolerance"], c
# the law's stiffness, written in the file, is warned about as without effect
assert any("Contact/Stiffness" in w and "no effect" in w for w in s["warnings"]), s["warnings"]
# each episode's largest penetration lies in it (0 would be before it)
for i in impacts:
    assert float(i["start_time_s"]) <= float(i["max_penetration_time_s"]), i
    if i["end_time_s"]:
        assert float(i["max_penetration_time_s"]) <= float(i["end_time_s"]), i
print(f"{c['lcp']['solves']} LCPs solved")
PY
grep -q "Contact/Stiffness.*no effect" run.err || fail "no warning that Contact/Stiffness is unused"
# an LCP the solver cannot solve to its tolerance: NSGS with one sweep on
# two coupled contacts (a building squeezed between two others)
"$poundfe" run "$here/rigid-squeeze.prm" --set "Contact/LCP solver=nsgs" \
  --set "Contact/LCP iterations=1" --output capped > /dev/null 2> capped.err
status=$?
[ "$status" -eq 2 ] || fail "an unsolved LCP: exit $status, expected 2: $(head -c 300 capped.err)"
grep -q "step [0-9]* (t = .* s): Siconos's .* did not solve the contact LCP .* residual" capped.err ||
  fail "an unsolved LCP: the step and the residual not named: $(cat capped.err)"
python3 - capped <<'PY' || fail "an unsolved LCP: the results so far"
import json, sys
s = json.load(open(f"{sys.argv[1]}/summary.json"))
assert s["status"] == "failed" and "did not solve the contact LCP" in s["message"], s["status"]
assert 0 < s["analysis"]["end_time_s"] < 0.5, s["analysis"]
assert s["contact"]["lcp"]["max_iterations"] == 1, s["contact"]
assert s["contact"]["lcp"]["max_residual"] > s["contact"]["lcp_tolerance"], s["contact"]
print(f"unsolved LCP: exit 2 at t = {s['analysis']['end_time_s']} s, results so far kept")
PY
"$poundfe" run "$here/rigid-squeeze.prm" --output squeeze > /dev/null 2>&1 ||
  fail "the squeezed building with Lemke: exit $?"
expect 1 "parameter 'Contact/LCP tolerance'" run pair.prm --set "Contact/LCP tolerance=0" --output out

expect 1 "parameter 'Contact/Theta'" run pair.prm --set "Contact/Theta=0.4" --output out
expect 1 "parameter 'Contact/Theta'" run pair.prm --set "Contact/Theta=1.5" --output out
expect 1 "parameter 'Contact/Coefficient of restitution'" run pair.prm \
  --set "Contact/Coefficient of restitution=1.2" --output out
expect 1 "parameter 'Contact/Coefficient of restitution'" run pair.prm \
  --set "Contact/Coefficient of restitution=-0.1" --output out
expect 1 "parameter 'Contact/Model'" run pair.prm --set "Contact/Law=none" --output out
expect 1 "parameter 'Contact/Model'" modal pair.prm --output out
expect 1 "parameter 'Contact/Model'" dynamic-form pair.prm --output out
# models the stepper does not take yet: the example with Contact/Model =
# nonsmooth (and a law making gaps, if it has no Contact section)
nonsmooth() {
  if grep -q '^subsection Contact' "$inputs/$1"; then
    sed '/^subsection Contact/a\  set Model = nonsmooth' "$inputs/$1"
  else
    cat "$inputs/$1"
    printf 'subsection Contact\n  set Model = nonsmooth\n  set Law = linear\nend\n'
  fi
}
# friction: along contacts in plan only, with rigid contact only, mu >= 0
expect 1 "parameter 'Contact/Friction coefficient'" run pair.prm \
  --set "Contact/Friction coefficient=0.3" --output out
expect 1 "parameter 'Contact/Friction coefficient'" run pair.prm --set "Contact/Model=penalty" \
  --set "Contact/Friction coefficient=0.3" --output out
expect 1 "parameter 'Contact/Friction coefficient'" run pair.prm \
  --set "Contact/Friction coefficient=-0.1" --output out
nonsmooth fibre-frame-pounding.prm > fibre.prm
expect 1 "parameter 'Contact/Model'" run fibre.prm --output out
nonsmooth sd-oscillator.prm > friction.prm
expect 1 "parameter 'Contact/Model'" run friction.prm --output out
echo "rigid-contact: $n refusals checked, $failures failures"
exit $((failures > 0))
