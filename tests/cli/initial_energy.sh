#!/usr/bin/env bash
# The energy balance of runs started from given initial conditions
# (Initial conditions/Floor velocities, Floor displacements): a shear pair,
# an elastic frame pair and the RC fibre frame pair after gravity (and
# without it), each pounding. At every row of energy.csv (every step)
#   |initial + input + constant_load + belt - (kinetic + damping + strain +
#    hysteretic + contact + friction + links + foundation)| <= 1e-8 x the
#   largest term of the run,
# and summary.json's running relative error <= 1e-8. The frames' joint
# rotations carry no mass: given only the floors' sway, they start in
# equilibrium with it (integration/massless_start.cc), else the first step
# does work no term holds (5.7e-3 of the largest term with displacements,
# 1.9e-4 with velocities, on the elastic pair; 8.6e-3 and 8.9e-4 on the
# fibre pair). Tolerance 1e-8: the
# balance's round-off is 1e-10 to 1e-13 on these runs, and 1e-8 is what the
# runs from rest are held to (cli/gravity-energy).
#   initial_energy.sh POUNDFE SHEAR_PAIR ELASTIC_FRAMES FIBRE_FRAMES HINGE_FRAME
set -u
poundfe=$1 shear=$2 elastic=$3 fibre=$4 hinges=$5
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

# $1: the output's name, $2: the example, $3: its end time, $4: the entry,
# $5: its value, then more --set arguments
run_case() {
  local name=$1 example=$2 end=$3 entry=$4 value=$5
  shift 5
  "$poundfe" run "$example" --output "$name" --set "Time integration/End time=$end" \
    --set "Output/Plots=false" --set "Output/Recorders/Record=energy every 0" \
    --set "Initial conditions/$entry=$value" "$@" > /dev/null ||
    { fail "$name: exit $?"; return; }
  python3 - "$name" "${pounding:-yes}" <<'PY' || fail "$name: balance"
import csv, json, sys
name, pounding = sys.argv[1], sys.argv[2] == "yes"
e = json.load(open(name + "/summary.json"))["energy"]
s = json.load(open(name + "/summary.json"))
rows = list(csv.DictReader(open(name + "/energy.csv")))
supplied = ("input_J", "constant_load_J", "belt_J")
stored = ("kinetic_J", "damping_J", "strain_J", "hysteretic_J", "contact_J", "friction_J",
          "links_J", "foundation_J")
value = lambda r, k: float(r[k]) if k in r else 0.0
largest = max([abs(e["initial_J"])] +
              [abs(value(r, k)) for r in rows for k in supplied + stored])
residual = max(abs(e["initial_J"] + sum(value(r, k) for k in supplied) -
                   sum(value(r, k) for k in stored)) for r in rows)
impacts = sum(g.get("impacts", 0) for g in s.get("gaps", []))
print(f"{name}: {len(rows)} rows, initial {e['initial_J']:.6g} J, largest term {largest:.6g} J, "
      f"impacts {impacts}, balance residual {residual / largest:.3g} of it, running error "
      f"{e['max_relative_balance_error']:.3g}")
ok = (e["initial_J"] > 0 and (impacts > 0 or not pounding) and residual <= 1e-8 * largest and
      e["max_relative_balance_error"] <= 1e-8)
sys.exit(0 if ok else 1)
PY
}

run_case shear-velocities "$shear" 1 "Floor velocities" "shear3: all 0.3; shear2: all -0.3"
run_case shear-displacements "$shear" 1 "Floor displacements" "shear3: all 0.02"
run_case elastic-velocities "$elastic" 0.5 "Floor velocities" "F3: all 0.3; F2: all -0.3"
run_case elastic-displacements "$elastic" 0.5 "Floor displacements" "F3: all 0.01"
run_case fibre-velocities "$fibre" 0.6 "Floor velocities" "A: all 0.2; B: all -0.2"
run_case fibre-displacements "$fibre" 0.6 "Floor displacements" "A: all 0.02"
run_case fibre-displacements-from-rest "$fibre" 0.6 "Floor displacements" "A: all 0.02" \
  --set "Model/Gravity analysis/Type=none"
hinge_sway="frame3: 0.04 0.08 0.11"
pounding=no run_case hinges-displacements "$hinges" 0.1 "Floor displacements" "$hinge_sway"
pounding=no run_case hinges-moving "$hinges" 0.1 "Floor displacements" "$hinge_sway" \
  --set "Initial conditions/Floor velocities=frame3: 0.3 -0.2 0.5"
pounding=no run_case hinges-moving-one-way "$hinges" 0.1 "Floor displacements" "$hinge_sway" \
  --set "Initial conditions/Floor velocities=frame3: 0.3 0.6 0.8"
# the joints' rotations at t = 0 do not depend on the velocities: the same
# initial strain energy (to round-off) with and without them
python3 - hinges-displacements hinges-moving hinges-moving-one-way <<'PY' ||
import csv, sys
strain = [float(next(csv.DictReader(open(name + "/energy.csv")))["strain_J"]) for name in sys.argv[1:]]
print("hinge frame: initial strain energy", strain)
sys.exit(0 if max(strain) - min(strain) <= 1e-12 * max(strain) else 1)
PY
  fail "hinge frame: the initial strain energy depends on the velocities"

if [ "$failures" -gt 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "every balance from initial conditions closes"
