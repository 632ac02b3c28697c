#!/usr/bin/env bash
# Coarse steps through pounding (theory §3.7a, Time integration/Contact
# onset from acceleration) on four pairs of its own: a 2 + 4 and a 3 + 5
# storey shear pair with Jankowski contact (coarse-contact-shear.prm,
# coarse-onset-shear.prm) and two pairs of elastic frames with Hertz-damp
# contact (coarse-contact-frames.prm, coarse-onset-frames.prm), each run
# with the option at Time step = 5e-5 (the reference), 1e-4, 1e-3 and
# 1e-2 s:
#   - at 1e-2 and 1e-3 s no step cut and at most 4 Newton iterations in any
#     step or sub-step (without the option the first shear pair takes 4 cuts
#     and 5 iterations at 1e-2 s; with the option but without its predictor
#     and onset correction the second frame pair takes 5 iterations);
#   - every peak (drift ratio and absolute acceleration of every storey,
#     each gap's peak force) within 0.5 % of the 5e-5 s run at 1e-3 s;
#   - the reference within 0.2 % of the 1e-4 s run (second order: its own
#     error is a third of that difference, small against 0.5 %).
# Models after --coarse-only (a 0.3 mm gap whose peaks at 1e-3 s are
# further off: doc/benchmarks.md) run at 1e-2 s only, for the first check.
set -eu
poundfe=$1
shift
models=() coarse_only=()
while [ $# -gt 0 ]; do
  if [ "$1" = --coarse-only ]; then coarse_only+=("$2"); shift; else models+=("$1"); fi
  shift
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

for model in "${models[@]}" ${coarse_only[@]+"${coarse_only[@]}"}; do
  name=$(basename "$model" .prm)
  dts="1e-2 1e-3 1e-4 5e-5"
  case " ${coarse_only[*]-} " in *" $model "*) dts=1e-2 ;; esac
  for dt in $dts; do
    "$poundfe" run "$model" --output "$work/$name/$dt" \
      --set "Time integration/Time step=$dt" --set "Output/Output interval=$dt" \
      --set "Time integration/Contact onset from acceleration=true" > /dev/null
  done
done

PYTHONPATH=$(cd "$(dirname "$0")" && pwd) python3 - "$work" "${models[@]}" -- \
  ${coarse_only[@]+"${coarse_only[@]}"} <<'PY'
import json, os, sys
from summary_peaks import peaks
work = sys.argv[1]
split = sys.argv.index("--")
models = [os.path.basename(m)[:-4] for m in sys.argv[2:split]]
coarse_only = [os.path.basename(m)[:-4] for m in sys.argv[split + 1:]]
def summary(name, dt):
    return json.load(open(f"{work}/{name}/{dt}/summary.json"))
failed = []
for name in coarse_only:
    s, newton = summary(name, "1e-2"), summary(name, "1e-2")["newton"]
    if s["status"] != "completed" or newton["step_cuts"] != 0 or \
            newton["max_iterations_per_step"] > 4:
        failed.append(f"{name} dt 1e-2: {s['status']}, {newton['step_cuts']} step cuts, "
                      f"{newton['max_iterations_per_step']} Newton iterations in a step "
                      "(none and at most 4 expected)")
    print(f"{name} dt 1e-2: cuts {newton['step_cuts']}, max iterations "
          f"{newton['max_iterations_per_step']}")
for name in models:
    reference = summary(name, "5e-5")
    ref = peaks(reference)
    impacts = sum(g["impacts"] for g in reference["gaps"])
    if impacts < 10 or min(ref.values()) <= 0:
        failed.append(f"{name}: the reference pounds too little ({impacts} impacts)")
    for dt, tolerance in (("1e-2", None), ("1e-3", 0.005), ("1e-4", 0.002)):
        s = summary(name, dt)
        newton = s["newton"]
        if s["status"] != "completed":
            failed.append(f"{name} dt {dt}: {s['status']}")
        if dt != "1e-4":
            if newton["step_cuts"] != 0:
                failed.append(f"{name} dt {dt}: {newton['step_cuts']} step cuts, expected none")
            if newton["max_iterations_per_step"] > 4:
                failed.append(f"{name} dt {dt}: {newton['max_iterations_per_step']} Newton "
                              "iterations in a step, at most 4 allowed")
        worst = 0
        for key, value in peaks(s).items():
            error = abs(value - ref[key]) / ref[key]
            worst = max(worst, error)
            if tolerance is not None and error > tolerance:
                failed.append(f"{name} dt {dt}: {key} {value:.6g} against {ref[key]:.6g} "
                              f"at 5e-5 s: {100 * error:.3f} % > {100 * tolerance:g} %")
        print(f"{name} dt {dt}: cuts {newton['step_cuts']}, max iterations "
              f"{newton['max_iterations_per_step']}, worst peak error {100 * worst:.3f} %")
for f in failed:
    print("FAIL:", f)
sys.exit(1 if failed else 0)
PY
echo "coarse contact: ok"
