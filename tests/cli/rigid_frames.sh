#!/usr/bin/env bash
# Rigid contact (Contact/Model = nonsmooth) on frames whose rotations carry
# no mass (lumped masses) and carry Bouc-Wen hinges: the default example,
# input/two-buildings.prm, over its first 4 s.
#   - far apart (Separations = 1 m, no contact), Moreau-Jean's theta = 1/2 is
#     Newmark's average acceleration on the smooth part, the massless rows
#     equilibrium in both: drift.csv and the peak drifts within 1e-9 of the
#     penalty run's (Event refinement and Steps per contact 0, the same
#     steps; the two Newton loops stop on different measures, 1e-10 of the
#     velocity against a residual of 1e-12, hence not round-off);
#   - 1 cm apart, a Hertz-damp law of growing stiffness (damping calibrated
#     to e = 0.65, 2.75e9 ... 2.75e12 N/m^1.5) at 1e-4 s, sweep of
#     Contact/Stiffness: each peak drift's difference from rigid contact
#     falls by at least 5 times from the softest to the stiffest and is
#     below 0.5 % there (over several impacts the differences compound, so
#     they need not fall at every stiffness);
#   - 3 mm apart at 2e-3 s, J dense (umfpack below the Dense matrix limit)
#     against J sparse (Contact/Dense matrix limit = 0, eigen-ldlt), and the
#     default (eigen-ldlt, left to choose) exactly the sparse run, its solves
#     estimated cheaper on 60 equations: the same equations
#     by different factors, so drift.csv, floor_displacement.csv and the
#     impulses of impacts.csv within 1e-9 of a column's peak (round-off carried
#     through Newton's tolerance 1e-10 on the velocities); and the sparse path
#     refusing a linear solver on several processes and modal damping (exit 1);
#   - 1 cm apart at 2e-2 s (record sampled at 0.01 s): a step the modified
#     Newton fails is redone by full Newton, counted in summary.json.
set -u
poundfe=$1 input=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
cd "$work"
. "$here/expect.sh"

if ! "$poundfe" --version | grep -q "nonsmooth"; then
  echo "rigid-frames: this build has no Siconos (penalty only): nothing to check"
  exit 0
fi
sed -e 's/^\( *set Duration *=\).*/\1 4/' -e '/^subsection Contact/a\  set Event refinement = 0\n  set Steps per contact = 0' \
    -e 's/^\( *set Output interval *=\).*/\1 0.01/' -e 's/^\( *set VTU interval *=\).*/\1 0/' \
    -e 's/^\( *set Number of modes *=\).*/\1 0/' -e '/^subsection Output/a\  set Plots = false' \
    "$input" > pair.prm
sed 's/^\( *set Separations *=\).*/\1 1.0/' pair.prm > apart.prm
"$poundfe" run apart.prm --set "Time integration/Newton residual tolerance=1e-12" --output penalty > /dev/null 2> penalty.err || fail "penalty exited $?: $(head -c 300 penalty.err)"
"$poundfe" run apart.prm --set "Contact/Model=nonsmooth" --output rigid > /dev/null 2> rigid.err ||
  fail "nonsmooth on frames exited $?: $(head -c 300 rigid.err)"
python3 "$here/same_trajectory.py" 1e-9 penalty/drift.csv rigid/drift.csv || fail "apart: drift.csv differs"
python3 - penalty rigid <<'PY' || fail "apart: hinge peaks differ"
import json, sys
a, b = (json.load(open(f"{d}/summary.json")) for d in sys.argv[1:])
assert a["analysis"]["steps"] == b["analysis"]["steps"], (a["analysis"]["steps"], b["analysis"]["steps"])
peaks = lambda s: [x["peak_drift_ratio"] for g in s["buildings"] for x in g["storeys"]]
print("apart: peak drifts", peaks(a), peaks(b))
assert all(abs(x - y) <= 1e-9 * max(peaks(a)) for x, y in zip(peaks(a), peaks(b)))
PY

{
  cat pair.prm
  printf 'subsection Sweep\n  set Parameter = Contact/Stiffness\n  set Values = 2.75e9, 2.75e10, 2.75e11, 2.75e12\nend\n'
} > sweep.prm
"$poundfe" sweep sweep.prm --set "Contact/Model=nonsmooth" --set "Time integration/Time step=1e-4" \
  --output sweep > /dev/null 2> sweep.err || fail "sweep exited $?: $(head -c 300 sweep.err)"
python3 - sweep <<'PY' || fail "frames: convergence to rigid contact"
import csv, sys
rows = list(csv.DictReader(open(f"{sys.argv[1]}/contact_convergence.csv")))
names = [n[: -len("_relative_error")] for n in rows[0] if n.endswith("_relative_error") and "drift" in n]
failed = []
for name in names:
    error = [float(r[f"{name}_relative_error"]) for r in rows]
    print(f"{name}: relative difference " + ", ".join(f"{x:.3g}" for x in error))
    failed.extend(n for n in [name] if not (error[-1] < error[0] / 5 and error[-1] < 0.005))
assert names and not failed, failed
PY
# J dense against J sparse, 3 mm apart (impacts within the 4 s); the contact
# law's force parameters left out (unused by nonsmooth: no warnings)
sed -e 's/^\( *set Separations *=\).*/\1 0.003/' -e '/set Stiffness *=/d' -e '/set Damping from *=/d' \
    pair.prm > close.prm
# (J dense: umfpack below the limit, where the cost model weighs eigen-ldlt's
# factor only; sparse: limit 0; left to choose with eigen-ldlt, the default,
# sparse, the same numbers as limit 0 exactly)
for matrix in "dense 500 umfpack" "sparse 0 eigen-ldlt" "chosen 500 eigen-ldlt"; do
  set -- $matrix
  "$poundfe" run close.prm --set "Contact/Model=nonsmooth" --set "Time integration/Time step=2e-3" \
    --set "Contact/Dense matrix limit=$2" --set "Time integration/Linear solver=$3" --output "$1" \
    > /dev/null 2> "$1.err" || fail "nonsmooth, J $1, exited $?: $(head -c 300 "$1.err")"
done
for file in drift.csv floor_displacement.csv; do
  python3 "$here/same_trajectory.py" 1e-9 dense/$file sparse/$file || fail "dense and sparse J: $file differs"
  python3 "$here/same_trajectory.py" 0 sparse/$file chosen/$file || fail "J left to choose: not sparse ($file)"
done
python3 - dense/impacts.csv sparse/impacts.csv <<'PY' || fail "dense and sparse J: impacts.csv differs"
import csv, sys
dense, sparse = (list(csv.DictReader(open(f))) for f in sys.argv[1:])
assert len(dense) == len(sparse) and len(dense) > 0, (len(dense), len(sparse))
column = next(c for c in dense[0] if c.startswith("impulse"))
scale = max(abs(float(r[column])) for r in dense)
worst = max(abs(float(a[column]) - float(b[column])) for a, b in zip(dense, sparse)) / scale
print(f"dense and sparse J: {len(dense)} impacts, impulses within {worst:.2e} of the largest")
assert worst < 1e-9
PY
expect 1 "eigen-ldlt or umfpack" run close.prm --set "Contact/Model=nonsmooth" \
  --set "Contact/Dense matrix limit=0" --set "Time integration/Linear solver=petsc-mumps" --output out
sed -e 's/^\( *set Type *= *\)modes$/\1modal\n    set Modal ratios = 0.05, 0.05/' \
    -e '/set Damping ratio/d' -e '/set Modes /d' close.prm > modal.prm
expect 1 "modal damping" run modal.prm --set "Contact/Model=nonsmooth" \
  --set "Contact/Dense matrix limit=0" --output out
# a step the modified Newton (kept J) cannot solve is redone by full Newton:
# 1 cm apart at 2e-2 s, the record sampled at 0.01 s, whose step at 2.06 s
# failed without the retry (exit 2); the retry is counted, and the step's
# iterations count both attempts (at least the failed one's Newton iterations)
sed -e '/set Stiffness *=/d' -e '/set Damping from *=/d' pair.prm > coarse.prm
"$poundfe" run coarse.prm --set "Contact/Model=nonsmooth" --set "Time integration/Time step=2e-2" \
  --set "Ground motion/Stochastic/Sample interval=0.01" --set "Output/Output interval=0.02" \
  --output coarse > /dev/null 2> coarse.err || fail "full-Newton retry: exited $?: $(head -c 300 coarse.err)"
python3 - coarse/summary.json <<'PY' || fail "full-Newton retry: not counted"
import json, sys
newton = json.load(open(sys.argv[1]))["newton"]
print("full-Newton retry:", newton["full_newton_retries"], "retries, at most",
      newton["max_iterations_per_step"], "iterations in a step")
assert newton["full_newton_retries"] >= 1 and newton["max_iterations_per_step"] > 50, newton
PY
echo "rigid-frames: $failures failures"
exit $((failures > 0))
