#!/usr/bin/env bash
# Coarse steps without cuts (issue 23 item 5; theory §3.7b): a 2-storey
# shear pair with Jankowski contact at both floors (tests/cli/coarse-pair.prm,
# 3 s of an El Centro-like 0.5 g motion, 5 mm gap, ~15 impacts) with
# Steps per shortest period = 50, Steps per contact = 100, Event
# refinement = 10, at Time step = 1e-2, 1e-3, 1e-4 and 2e-4 s:
#   - at 1e-2 and 1e-3 s no step cut and at most 4 Newton iterations in any
#     step or sub-step (the issue's requirement);
#   - the level of the sub-steps: the Gershgorin bound of the stiffer
#     building's omega_max, sqrt((8e6 + 4e6) / 1000) = 109.5 rad/s, asks
#     h <= 2 pi / (50 x 109.5) = 1.147e-3 s, so 2^4 sub-steps of 6.25e-4 s per
#     step of 1e-2 s (accuracy_refinements = 300 x 15) and none at 1e-3 s;
#   - every peak (drift ratio and absolute acceleration of every storey, the
#     peak force of each gap) within 1 % (1e-2 s) and 0.5 % (1e-3 s) of
#     the 1e-4 s run, the issue's tolerances (measured: doc/verification.md);
#   - the 1e-4 s reference within 0.2 % of the 2e-4 s run: converged (second
#     order: the 1e-4 s run's own error is a third of that difference,
#     <= 0.07 %, small against the tolerances).
set -eu
poundfe=$1 model=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

for dt in 1e-2 1e-3 1e-4 2e-4; do
  sed "s/^\( *set Time step *=\).*/\1 $dt/" "$model" > "$work/$dt.prm"
  "$poundfe" run "$work/$dt.prm" --output "$work/$dt" > /dev/null
done

PYTHONPATH=$(cd "$(dirname "$0")" && pwd) python3 - "$work" <<'PY'
import json, sys
from summary_peaks import peaks
work = sys.argv[1]
def summary(dt):
    return json.load(open(f"{work}/{dt}/summary.json"))
failed = []
reference = summary("1e-4")
ref = peaks(reference)
impacts = sum(g["impacts"] for g in reference["gaps"])
if impacts < 5 or min(ref.values()) <= 0:
    failed.append(f"the reference pounds too little ({impacts} impacts): the test would not test")
for dt, tolerance, splits in (("1e-2", 0.01, 300 * 15), ("1e-3", 0.005, 0), ("2e-4", 0.002, 0)):
    s = summary(dt)
    newton = s["newton"]
    if s["status"] != "completed":
        failed.append(f"dt {dt}: {s['status']}")
    if dt != "2e-4":
        if newton["step_cuts"] != 0:
            failed.append(f"dt {dt}: {newton['step_cuts']} step cuts, expected none")
        if newton["max_iterations_per_step"] > 4:
            failed.append(f"dt {dt}: {newton['max_iterations_per_step']} Newton iterations "
                          "in a step, at most 4 allowed")
        if newton["accuracy_refinements"] != splits:
            failed.append(f"dt {dt}: {newton['accuracy_refinements']} accuracy refinements, "
                          f"expected {splits}")
    worst = 0
    for key, value in peaks(s).items():
        error = abs(value - ref[key]) / ref[key]
        worst = max(worst, error)
        if error > tolerance:
            failed.append(f"dt {dt}: {key} {value:.6g} against {ref[key]:.6g} at 1e-4 s: "
                          f"{100 * error:.3f} % > {100 * tolerance:g} %")
    print(f"dt {dt}: cuts {newton['step_cuts']}, max iterations "
          f"{newton['max_iterations_per_step']}, worst peak error {100 * worst:.3f} % "
          f"(tolerance {100 * tolerance:g} %)")
for f in failed:
    print("FAIL:", f)
sys.exit(1 if failed else 0)
PY
echo "coarse steps: ok"
