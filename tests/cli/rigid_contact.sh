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
#   - no warning that the (undamped) law ignores the restitution;
# then bad input: Theta outside [1/2, 1], a restitution outside [0, 1], no
# gaps (Law = none), another command than run, a 3D model, fibre members,
# friction: exit 1, one message naming the file, line and parameter, no
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
! grep -q "Coefficient of restitution" run.err || fail "moot warning: $(cat run.err)"
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
PY

expect 1 "parameter 'Contact/Theta'" run pair.prm --set "Contact/Theta=0.4" --output out
expect 1 "parameter 'Contact/Theta'" run pair.prm --set "Contact/Theta=1.5" --output out
expect 1 "parameter 'Contact/Coefficient of restitution'" run pair.prm \
  --set "Contact/Coefficient of restitution=1.2" --output out
expect 1 "parameter 'Contact/Coefficient of restitution'" run pair.prm \
  --set "Contact/Coefficient of restitution=-0.1" --output out
expect 1 "parameter 'Contact/Model'" run pair.prm --set "Contact/Law=none" --output out
expect 1 "parameter 'Contact/Model'" modal pair.prm --output out
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
nonsmooth 3d-torsional-shear-pair.prm > plan.prm
expect 1 "parameter 'Contact/Model'" run plan.prm --output out
nonsmooth fibre-frame-pounding.prm > fibre.prm
expect 1 "parameter 'Contact/Model'" run fibre.prm --output out
nonsmooth sd-oscillator.prm > friction.prm
expect 1 "parameter 'Contact/Model'" run friction.prm --output out
echo "rigid-contact: $n refusals checked, $failures failures"
exit $((failures > 0))
