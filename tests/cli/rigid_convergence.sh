#!/usr/bin/env bash
# The convergence of a penalty law to rigid contact (`poundfe sweep` with
# Contact/Model = nonsmooth and Sweep/Parameter = Contact/Stiffness): two
# undamped one-storey shear buildings 10 mm apart released towards each
# other (0.5 and -0.3 m/s), restitution 0.65, over their first impact
# (0.12 s) at 1e-5 s; the penalty law is Hertz-damp with its damping
# calibrated to the same e, at k = 1e9 ... 1e12 N/m^1.5:
#   - rigid_limit.csv is `poundfe run`'s nonsmooth run (to 1e-9 relative:
#     the same run);
#   - each peak drift's relative difference from rigid contact
#     (contact_convergence.csv) decreases over the last three stiffnesses
#     and is below 5 % at the stiffest (a Hertz contact's penetration, and
#     so its difference from a rigid one, falls as k^(-2/5); over later
#     impacts the differences compound and the rigid scheme's own first
#     order error at impacts, ~ v h, takes over);
#   - contact_convergence.csv holds the peak drifts and displacements only
#     (the user guide's columns): rigid contact's floor accelerations leave
#     out the impulses, so they are not comparable to a penalty law's;
#   - the law's entries, used by the penalty runs (Stiffness among them),
#     are not warned about as without effect, as `poundfe run` does;
#   - a bad law for the penalty runs is refused before anything is written.
set -u
poundfe=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
. "$here/expect.sh"

if ! "$poundfe" --version | grep -q "nonsmooth"; then
  echo "rigid-convergence: this build has no Siconos (penalty only): nothing to check"
  exit 0
fi
building() {
  printf 'subsection Building %s\n  set Name = %s\n  set Type = shear\n  set Number of storeys = 1\n' "$1" "$2"
  printf '  set Storey heights = 3.0\n  set Floor masses = 1000\n  set Storey stiffnesses = %s\n' "$3"
  printf '  subsection Damping\n    set Type = none\n  end\nend\n'
}
{
  printf 'subsection Model\n  set Number of buildings = 2\n  set Separations = 0.01\nend\n'
  building 1 A 5e6
  building 2 B 3e6
  printf 'subsection Ground motion\n  set Type = none\nend\n'
  printf 'subsection Initial conditions\n  set Floor velocities = A: all 0.5; B: all -0.3\nend\n'
  printf 'subsection Contact\n  set Model = nonsmooth\n  set Law = hertz-damp\n'
  printf '  set Stiffness = 1e10\n  set Damping from = calibrated\n  set Calibration velocity = 0.8\n'
  printf '  set Coefficient of restitution = 0.65\nend\n'
  printf 'subsection Time integration\n  set Time step = 1e-5\n  set End time = 0.12\nend\n'
  printf 'subsection Output\n  set Plots = false\n  set VTU interval = 0\nend\n'
  printf 'subsection Sweep\n  set Parameter = Contact/Stiffness\n  set Values = 1e9, 1e10, 1e11, 1e12\nend\n'
} > pair.prm

"$poundfe" sweep pair.prm --output sweep > sweep.out 2> sweep.err || fail "sweep exited $?: $(head -c 300 sweep.err)"
"$poundfe" run pair.prm --output run > /dev/null 2> run.err || fail "run exited $?: $(head -c 300 run.err)"
# the swept law's entries are the penalty runs': no "has no effect" here
grep -q "has no effect" sweep.err && fail "sweep warns about the law it sweeps: $(grep 'has no effect' sweep.err | head -1)"
grep -q "parameter 'Contact/Stiffness': has no effect" run.err || fail "run does not warn about Contact/Stiffness"
python3 - sweep run <<'PY' || fail "convergence to rigid contact"
import csv, json, sys
sweep, run = sys.argv[1:]
limit = next(csv.DictReader(open(f"{sweep}/rigid_limit.csv")))
s = json.load(open(f"{run}/summary.json"))
drifts = {f"{b['name']}_storey{st['storey']}_peak_drift_ratio": st["peak_drift_ratio"]
          for b in s["buildings"] for st in b["storeys"]}
assert int(float(limit["completed"])) == 1, limit
for name, value in drifts.items():
    assert abs(float(limit[name]) - value) <= 1e-9 * value, (name, limit[name], value)
assert int(float(limit["n_impacts"])) == sum(g["impacts"] for g in s["gaps"]) > 0, limit
rows = list(csv.DictReader(open(f"{sweep}/contact_convergence.csv")))
assert [float(r["Contact_Stiffness"]) for r in rows] == [1e9, 1e10, 1e11, 1e12], rows
# the user guide's columns: each nonzero peak drift and displacement, nothing else
expected = [f"{n}_relative_error" for n in limit if n != "completed" and float(limit[n]) != 0
            and (n.endswith("drift_ratio") or n.endswith("peak_displacement_m"))]
assert list(rows[0])[1:] == expected, list(rows[0])
assert any(n.endswith("peak_acc_m_s2") for n in limit), list(limit)
for name in drifts:
    error = [float(r[f"{name}_relative_error"]) for r in rows]
    print(f"{name}: relative difference from rigid contact " + ", ".join(f"{x:.3g}" for x in error))
    assert error[-3] > error[-2] > error[-1], (name, error)
    assert error[-1] < 0.05, (name, error)
summary = json.load(open(f"{sweep}/summary.json"))
assert summary["rigid_limit"]["max_drift_ratio"] == float(limit["max_drift_ratio"]), summary["rigid_limit"]
PY

# the penalty runs' law is checked as the penalty model checks it
expect 1 "parameter 'Contact/Coefficient of restitution'" sweep pair.prm \
  --set "Contact/Coefficient of restitution=0" --output out
echo "rigid-convergence: $n refusals checked, $failures failures"
exit $((failures > 0))
