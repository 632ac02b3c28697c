#!/usr/bin/env bash
# Issue 22's 3D benchmark (Release build, from the repository root): a pair
# of 10-storey 3 x 3-bay 3D frames with Bouc-Wen hinges about both axes at
# every member end and slab contact at every floor (bench/frame3d-pair.prm),
# against a pair of planar frames with about as many equations
# (bench/frame2d-pair.prm: 29 bays), 20 s at 5e-3 s, every output but VTU.
# Prints, per model, the equations, nonlinear elements, steps/s (wall) and
# the CPU time per step per equation, and the ratio 3D / 2D of the latter
# (target of issue 22: at most 1.5). CPU time (user + system, from
# /usr/bin/time) rather than wall time: on a shared machine it is what the
# run itself costs. About 5 minutes on one core.
#   bash bench/frame3d.sh [BUILD_DIR]
set -euo pipefail
build=${1:-build}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
per_equation=()
for model in frame3d frame2d; do
  /usr/bin/time -f "%U %S" -o "$work/$model.time" \
    "$build/poundfe" run "bench/$model-pair.prm" --output "$work/$model" > "$work/$model.log"
  read -r user system < "$work/$model.time"
  line=$(/usr/bin/python3 - "$work/$model/summary.json" "$user" "$system" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
cpu = float(sys.argv[2]) + float(sys.argv[3])
n, steps = s["model"]["equations"], s["analysis"]["steps"]
print(f"{cpu / steps / n:.6e} {n} {steps} {s['analysis']['steps_per_second']:.1f} {cpu:.1f}")
PY
)
  read -r cost n steps rate cpu <<< "$line"
  elements=$(grep -o "^[0-9]* nonlinear elements" "$work/$model.log" | cut -d' ' -f1)
  impacts=$(grep -o "[0-9]* impacts" "$work/$model.log" | cut -d' ' -f1)
  printf "%-8s %5d eqs %5d nonlinear elements %4d impacts %5d steps %7s steps/s (wall) %7s s CPU %s s CPU per step per equation\n" \
    "$model" "$n" "$elements" "${impacts:-0}" "$steps" "$rate" "$cpu" "$cost"
  per_equation+=("$cost")
done
/usr/bin/python3 -c "import sys; print(f'3D / 2D CPU time per step per equation: {float(sys.argv[1]) / float(sys.argv[2]):.2f} (target <= 1.5)')" \
  "${per_equation[0]}" "${per_equation[1]}"
