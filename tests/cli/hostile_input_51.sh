#!/usr/bin/env bash
# Hostile input, round three, through the real binary: physically impossible
# models refused and every message naming its entry (exit 1, one line,
# nothing written; tests/cli/expect.sh), and SIGINT handled alike:
#   impossible models: 3D entries in a planar model (.prm and JSON), a mass
#     centre off the slab, coordinates too large for the gap, an initial
#     condition given twice, a negative realization, two mesh nodes at one
#     point, contact and bumper stiffness beyond the links' bound;
#   named entries: a billion storeys, a list index past any int, bay widths,
#     plan rotation and dimensions, a lognormal of mean 0, positions, soil and
#     initial states beyond range;
#   interruption: mitigation, separation and reliability say "interrupted";
#     SIGINT stops a background job of a script (started with SIGINT ignored).
#   hostile_input_51.sh POUNDFE SOURCE_DIR
set -u
poundfe=$(readlink -f "$1") source=$(readlink -f "$2")
inputs=$source/input
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
. "$source/tests/cli/expect.sh"

pair3d=$inputs/3d-torsional-shear-pair.prm
# the 3D shear pair with one line replaced: $1 sed expression, $2 file
pair3d() { sed "$1" "$pair3d" > "$2"; }
# a shear building with stochastic loading and random parameters $1
random() {
  shear
  printf 'subsection Ground motion\n  set Type = kanai-tajimi\n  subsection Stochastic\n'
  printf '    set Duration = 2\n  end\nend\nsubsection Monte Carlo\n  set Realizations = 2\nend\n'
  printf 'subsection Random parameters\n  set Variables = %s\nend\n' "$1"
}

# --- physically impossible models
shear '  subsection Plan
    set Rotation = 30
  end' > plan-2d.prm
expect 1 "plan-2d.prm:7: parameter 'Building 1/Plan/Rotation': has no effect on a 2D shear building: it is a [3D] entry" modal plan-2d.prm --output out
printf '{ "Building 1": { "Type": "shear", "Number of storeys": "3", "Floor masses": "1000",\n  "Storey stiffnesses": "5e6", "Plan": { "Mass eccentricity": "1, 0" } } }\n' > plan-2d.json
expect 1 "parameter 'Building 1/Plan/Mass eccentricity': has no effect on a 2D shear building" modal plan-2d.json --output out
sed 's/  set Column I          = 6.75e-4/&\n  set Column Iz = 1e-3/' "$source/tests/cli/montecarlo-small.prm" > frame-2d.prm
expect 1 "parameter 'Building 2/Column Iz': has no effect on a 2D frame building" modal frame-2d.prm --output out
pair3d 's/set Mass eccentricity = 1.0, 0.5/set Mass eccentricity = 6, 0.5/' eccentric.prm
expect 1 "parameter 'Building 1/Plan/Mass eccentricity': e_x = 6 m puts the mass centre outside the slab" modal eccentric.prm --output out
pair3d 's/set Position                      = 14.05, 2/set Position = 1e17, 2/' far.prm
expect 1 "parameter 'Building 2/Plan/Position': got 1e+17 m, at most 1e+07 m in size" modal far.prm --output out
# 9e6 m (within a site's coordinates) and a 1 mm gap: 1e6 ulps of 9e6 are 1.9 mm
pair3d 's/set Position                      = 14.05, 2/set Position = 9000009.001, 2/
        s/set Plan dimensions   = 10, 8/set Plan dimensions   = 10, 8\n    set Position = 9000000, 0/' unresolved.prm
expect 1 "parameter 'Building 2/Plan/Position': the gap " modal unresolved.prm --output out
{ shear; printf 'subsection Initial conditions\n  set Floor displacements = B1: all 0.01; 1: all 0.02\nend\n'; } > floors-twice.prm
expect 1 "parameter 'Initial conditions/Floor displacements': building 'B1' is given twice" run floors-twice.prm --output out
{ shear; printf 'subsection Initial conditions\n  set Equation velocities = 0 = 0.1; 2 = 0; 0 = 0.2\nend\n'; } > equations-twice.prm
expect 1 "parameter 'Initial conditions/Equation velocities': equation 0 is given twice" run equations-twice.prm --output out
{ shear; printf 'subsection Ground motion\n  set Type = kanai-tajimi\n  subsection Stochastic\n    set Realization = -5\n  end\nend\n'; } > realization.prm
expect 1 "realization.prm:15: parameter 'Ground motion/Stochastic/Realization': The entry value -5 for the entry named Realization does not match" ground-motion realization.prm --output out
python3 - "$source/meshes/setback.msh" <<'PY' > twin.msh
import sys
s = open(sys.argv[1]).read()
s = s.replace("$Nodes\n11\n", "$Nodes\n12\n").replace("11 6 9.5 0\n$EndNodes", "11 6 9.5 0\n12 6 6.5 0\n$EndNodes")
print(s.replace("\n8 1 2 1 8 8 11\n", "\n8 1 2 1 8 12 11\n"), end="")
PY
sed 's|= ../meshes/setback.msh|= twin.msh|' "$inputs/setback-frame.prm" > twin.prm
expect 1 "twin.msh:17: Gmsh mesh: nodes 8 and 12 are at one point (6, 6.5, 0)" modal twin.prm --output out
sed 's/set Stiffness         = 5e8/set Stiffness = 1e200/' "$inputs/shear-pair-pounding.prm" > contact.prm
expect 1 "parameter 'Contact/Stiffness': got 1e+200, at most 1e+150 in size" modal contact.prm --output out
{ cat "$inputs/shear-pair-pounding.prm"; printf 'subsection Bumpers\n  set Law = linear\n  set Thickness = 0.01\n  set Stiffness = 1e200\nend\n'; } > bumper.prm
expect 1 "parameter 'Bumpers/Stiffness': got 1e+200, at most 1e+150 in size" modal bumper.prm --output out

# --- messages that name the entry
shear | sed 's/Number of storeys = 3/Number of storeys = 1000000000/' > storeys.prm
expect 1 "storeys.prm:3: parameter 'Building 1/Number of storeys': got 1000000000, at most 100000" modal storeys.prm --output out
random 'k: Building 1/Storey stiffnesses[99999999999999999999] ~ lognormal mean 5e6 cov 0.1' > index.prm
expect 1 "'Building 1/Storey stiffnesses[99999999999999999999]': the index 99999999999999999999 is out of range" montecarlo index.prm --output out
sed 's/\(set Bay widths *=\).*/\1 1e300/' "$inputs/two-storey-frame.prm" > bays.prm
expect 1 "parameter 'Building 1/Bay widths': got 1e+300 m, at most 10000 m in size" modal bays.prm --output out
pair3d 's/set Plan dimensions   = 10, 8/set Plan dimensions   = 10, 8\n    set Rotation = 1e308/' rotation.prm
expect 1 "parameter 'Building 1/Plan/Rotation': got 1e+308 degrees, at most 360 degrees" modal rotation.prm --output out
pair3d 's/set Plan dimensions   = 10, 8/set Plan dimensions   = 1e300, 8/' dimensions.prm
expect 1 "parameter 'Building 1/Plan/Plan dimensions': got 1e+300 m, at most 10000 m" modal dimensions.prm --output out
random 'k: Building 1/Storey stiffnesses ~ lognormal mean 0 cov 0.1' > lognormal.prm
expect 1 "variable 'k' (lognormal): a lognormal mean must be > 0 (its values are positive), got 0" montecarlo lognormal.prm --output out
pair3d 's/set Position                      = 14.05, 2/set Position = 1e308, 2/' position.prm
expect 1 "parameter 'Building 2/Plan/Position': got 1e+308 m, at most 1e+07 m" run position.prm --output out
sed 's/\(set Shear-wave velocity *=\).*/\1 1e-300/' "$inputs/soil-shear-pair.prm" > soil.prm
expect 1 "parameter 'Building 1/Foundation/Shear-wave velocity': must lie in [1, 10000] m/s" run soil.prm --output out
{ shear; printf 'subsection Initial conditions\n  set State = 1e308, 0, 0, 0, 0, 0\nend\n'; } > state.prm
expect 1 "parameter 'Initial conditions/State': got 1e+308, at most 1000 in size" run state.prm --output out

# --- interrupted: said on the console, in summary.json and by the status
# interrupted COMMAND FILE SAYS: COMMAND stopped by SIGINT once its output
# directory holds a file; a background job of this script (no job control:
# started with SIGINT ignored, which poundfe handles all the same)
interrupted() {
  n=$((n + 1))
  rm -rf out
  "$poundfe" "$1" "$2" --output out > stdout 2> stderr &
  local pid=$! _
  for _ in $(seq 1 600); do
    [ -n "$(ls out 2> /dev/null)" ] && break
    sleep 0.1
  done
  sleep 0.5
  kill -INT "$pid"
  for _ in $(seq 1 300); do
    kill -0 "$pid" 2> /dev/null || break
    sleep 0.1
  done
  kill -0 "$pid" 2> /dev/null && { kill -KILL "$pid"; wait "$pid"; fail "$1: still running 30 s after SIGINT"; return; }
  wait "$pid"
  local got=$?
  [ "$got" -eq 130 ] || { fail "$1: exit $got, expected 130: $(head -c 300 stderr)"; return; }
  grep -q '"status": "interrupted"' out/summary.json || { fail "$1: summary.json does not say interrupted"; return; }
  grep -qF -- "$3" stdout stderr || { fail "$1: no '$3' in: $(tail -c 400 stdout)"; return; }
  echo "ok   $1 stopped by SIGINT: $(grep -hF -- "$3" stdout stderr | head -1)"
}
sed 's/set Realizations = 4/set Realizations = 400/; s|set Directory.*|set Plots = false|' "$inputs/mitigation-shear-pair.prm" > mitigation.prm
interrupted mitigation mitigation.prm "mitigation interrupted after"
sed 's/set Realizations = 100/set Realizations = 4000/; s|set Directory.*|set Plots = false|' "$inputs/separation.prm" > separation.prm
interrupted separation separation.prm "separation interrupted: "
sed 's/set Monte Carlo samples = 400000/set Monte Carlo samples = 1000000000/
     s/set Methods .*/set Methods = Monte Carlo/' "$inputs/thesis-cantilever-reliability.prm" > reliability.prm
interrupted reliability reliability.prm "reliability interrupted: "
{ shear; printf 'subsection Time integration\n  set End time = 5000\nend\nsubsection Initial conditions\n  set Floor displacements = B1: all 0.01\nend\n'; } > long.prm
interrupted run long.prm "poundfe: interrupted at t = "

report "round-three hostile input"
