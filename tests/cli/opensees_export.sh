#!/usr/bin/env bash
# `poundfe export-opensees` (Exporting a model to OpenSees in
# doc/user-guide.md): every example of input/ that OpenSees can express is
# exported, the script run by poundfe's own `poundfe opensees`, and its
# floor displacements compared with `poundfe run` of the same file, step by
# step (Output interval = 0), relative to each floor's peak:
#  - linear (no gaps): 1e-9, round-off of two implementations of the same
#    Newmark recursion on the same M, C, K and record samples;
#  - with linear gaps (ElasticPPGap): poundfe run without its event location
#    and impact sub-steps (Contact/Event refinement = 0, Steps per contact =
#    0), the same fixed-step Newmark-Newton: 1e-6, the difference of two
#    converged Newton iterates (poundfe stops at a relative residual of
#    1e-8, the script at |dU| < 1e-12);
#  - the nonlinear contact laws OpenSees has the same equations of (hertz as
#    Hertzdamp without damping, jankowski as JankowskiImpact), the same way
#    at 1e-6, on the pounding pair with Contact/Law set;
#  - 2D frames: elastic members at 1e-9 (with the gravity analysis, and its
#    state checked), fibre members at 1e-6 as the other nonlinear cases,
#    Bouc-Wen hinges by first-order convergence in the time step (below);
#  - Bouc-Wen storeys by the same convergence;
#  - 3D frames on rigid floors: elastic members at 1e-9, fibre members at
#    1e-6;
#  - Bouc-Wen hinges of alpha = 1 (rates written as 0) at 1e-9; ElasticPP's
#    default epsyN written as -epsyP (the script's text); names with a blank
#    and a backslash one quoted word of the comments;
# and the refusals name the entry OpenSees cannot be given (P-Delta, 3D
# shear buildings, 3D hinges, 3D member mass, contact in plan, hinges of A != 1,
# a Hysteretic fibre material (by Sections/Materials), the contact laws hertz-damp and
# kelvin-voigt (saying how OpenSees's namesakes differ), nodal forces, modal
# damping, a record that does not start at zero).
#   opensees_export.sh POUNDFE INPUT_DIR PYTHON3
set -u
poundfe=$1 inputs=$2 python=$3
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$here/helpers.sh"
"$python" -c "import numpy" 2> /dev/null || python=/usr/bin/python3

# compare.py-like: floor_disp.out (time, floors) against floor_displacement.csv
same_floors() { # OPENSEES_DIR RUN_DIR SCRIPT TOLERANCE
  "$python" - "$@" <<'PY'
import re, shlex, sys
import numpy as np
ours, run, script, tolerance = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
columns = shlex.split(re.search(r"columns: time (.*)", open(script).read()).group(1))
table = np.loadtxt(ours + "/floor_disp.out", ndmin=2)
csv = np.genfromtxt(run + "/floor_displacement.csv", delimiter=",", names=True)
assert len(csv) == len(table) + 1, (len(csv), len(table))  # the run's row at t = 0
# a frame's floor: a column per node, its displacement their mean (poundfe's)
for name in dict.fromkeys(columns):
    mine = table[:, [j + 1 for j, c in enumerate(columns) if c == name]].mean(axis=1)
    theirs = csv[name][1:]
    peak = np.abs(theirs).max()
    d = np.abs(mine - theirs).max() / peak
    print(f"{name}: peak {peak:.6e} largest difference / peak {d:.1e}")
    assert d <= tolerance, (name, d)
PY
}

check_example() { # NAME TOLERANCE [--set ...] (to both the export and the run)
  local name=$1 tolerance=$2
  shift 2
  local dir="$work/$name${case_suffix:-}"
  "$poundfe" export-opensees "$inputs/$name.prm" --output "$dir/script" "$@" > "$dir.log" 2>&1 \
    || { cat "$dir.log"; fail "$name: export"; }
  "$poundfe" opensees "$dir/script/model.tcl" "$dir/script" > "$dir.os.log" 2>&1 \
    || { cat "$dir.os.log"; fail "$name: poundfe opensees"; }
  grep -q "^status 0 " "$dir.os.log" || { cat "$dir.os.log"; fail "$name: analyze failed"; }
  "$poundfe" run "$inputs/$name.prm" --output "$dir/run" --set "Output/Output interval=0" \
    --set "Output/VTU interval=0" --set "Output/Plots=false" "$@" > "$dir.run.log" 2>&1 \
    || { cat "$dir.run.log"; fail "$name: run"; }
  same_floors "$dir/script" "$dir/run" "$dir/script/model.tcl" "$tolerance" > "$dir.cmp" 2>&1 \
    || { cat "$dir.cmp"; fail "$name: floor displacements"; }
  echo "ok $name${case_suffix:-}"; cat "$dir.cmp"
}

# every example of input/ the export takes (the others are refused: below)
check_example three-storey-shear 1e-9
check_example floor-spectra 1e-9
no_events=(--set "Contact/Event refinement=0" --set "Contact/Steps per contact=0")
for name in shear-pair-pounding site-hazard separation-hazard mitigation-shear-pair; do
  check_example $name 1e-6 "${no_events[@]}"
done
# the nonlinear contact laws OpenSees 3.8 has: hertz as Hertzdamp without
# damping, jankowski as JankowskiImpact (its damping from the restitution)
for law in hertz jankowski; do
  case_suffix=-$law check_example shear-pair-pounding 1e-6 "${no_events[@]}" \
    --set "Contact/Law=$law" --set "Contact/Stiffness=2e10"
  grep -q "^uniaxialMaterial $( [ $law = hertz ] && echo Hertzdamp || echo JankowskiImpact) " \
    "$work/shear-pair-pounding-$law/script/model.tcl" || fail "$law: not its OpenSees material"
done
# 2D frames of elastic members (elasticBeamColumn on geomTransf Linear; a
# Gmsh building, Type = mesh, the same way): the same M, K, C and Newmark,
# 1e-9 as the shear buildings
for name in one-storey-frame two-storey-frame three-storey-frame setback-frame; do
  check_example $name 1e-9
done
# with the gravity analysis first, on two unequal bays: the floors at 1e-9,
# and the gravity state, OpenSees's vertical displacement of the node where
# poundfe's is largest (summary.json), at 1e-9 of it (the same linear solve)
gravity=(--set "Model/Gravity analysis/Type=static" --set "Building 1/Number of bays=2"
  --set "Building 1/Bay widths=6.0, 4.0")
case_suffix=-gravity check_example three-storey-frame 1e-9 "${gravity[@]}"
dir=$work/three-storey-frame-gravity
grep -q "^pattern Plain 2 Linear {" "$dir/script/model.tcl" || fail "gravity: no gravity pattern"
"$python" - "$dir" "$poundfe" <<'PY' || fail "gravity: the gravity state"
import json, re, subprocess, sys
dir, poundfe = sys.argv[1], sys.argv[2]
summary = json.load(open(dir + "/run/summary.json"))
text = json.dumps(summary)
peak = float(re.search(r'"peak_displacement_m": ([-0-9.e]+)', text).group(1))
where = re.search(r'"peak_displacement_at": "\S+ node \d+ at \(([-0-9.e]+), ([-0-9.e]+)\) uy"',
                  text)
script = open(dir + "/script/model.tcl").read()
tag = re.search(r"^node (\d+) %s %s\b" % where.groups(), script, re.M).group(1)
probe = script.replace("wipeAnalysis\n", 'puts "gravity uy [nodeDisp %s 2]"\nwipeAnalysis\n' % tag)
open(dir + "/probe.tcl", "w").write(probe.replace("[file dirname [info script]]",
                                                  '"%s/script"' % dir))
out = subprocess.run([poundfe, "opensees", dir + "/probe.tcl", dir + "/probe"],
                     capture_output=True, text=True).stdout
uy = float(re.search(r"gravity uy (\S+)", out).group(1))
print(f"gravity: node {tag} uy {uy:.9e}, poundfe's peak {peak:.9e}")
assert abs(abs(uy) - peak) <= 1e-9 * peak, (uy, peak)
PY
# a pounding pair of frames: two-buildings without its hinges, with the linear
# law and one set of Rayleigh coefficients (OpenSees's rayleigh acts on every
# element), without event location: 1e-6 as the shear pairs
frame_pair=(--set "Building 1/Hinges/Locations=" --set "Building 2/Hinges/Locations="
  --set "Contact/Law=linear" "${no_events[@]}")
for b in 1 2; do
  frame_pair+=(--set "Building $b/Damping/Type=coefficients" --set "Building $b/Damping/a0=0.5"
    --set "Building $b/Damping/a1=0.002")
done
check_example two-buildings 1e-6 "${frame_pair[@]}"
# the same pair with each frame's own Rayleigh coefficients (a0 0.3 and 0.5, a1
# 0.004 and 0.001): each frame's a1 on its members by a region (region -eleOnly
# -rayleigh 0 0 a1 0), 1e-6 as above
own_a1=(--set "Building 1/Hinges/Locations=" --set "Building 2/Hinges/Locations="
  --set "Contact/Law=linear" "${no_events[@]}")
for b in 1 2; do
  own_a1+=(--set "Building $b/Damping/Type=coefficients" --set "Building $b/Damping/a0=0.$((2 * b + 1))"
    --set "Building $b/Damping/a1=$([ $b = 1 ] && echo 0.004 || echo 0.001)")
done
case_suffix=-own-a1 check_example two-buildings 1e-6 "${own_a1[@]}"
[ "$(grep -c '^region [12] -eleOnly [0-9 ]* -rayleigh 0.0 0.0 [0-9.e-]* 0.0 ;# ' \
  "$work/two-buildings-own-a1/script/model.tcl")" = 2 ] || fail "own a1: not a region a frame"
grep -q "^rayleigh " "$work/two-buildings-own-a1/script/model.tcl" && fail "own a1: a rayleigh"
# fibre members (forceBeamColumn on Lobatto points, dispBeamColumn on
# Legendre, section Fiber of poundfe's fibres, Concrete02 and Steel02, the
# columns on geomTransf PDelta), gravity first: fibre-frame-pounding with the
# linear law and one set of Rayleigh coefficients, without event location;
# its steel yields and its concrete passes its peak strain. 1e-6 as the other
# nonlinear cases: the difference of two converged Newton iterates, carried
# along the path of the materials' histories
fibre_pair=(--set "Contact/Law=linear" "${no_events[@]}")
for b in 1 2; do
  fibre_pair+=(--set "Building $b/Damping/Type=coefficients" --set "Building $b/Damping/a0=0.5"
    --set "Building $b/Damping/a1=0.002")
done
check_example fibre-frame-pounding 1e-6 "${fibre_pair[@]}"
grep -q "^element forceBeamColumn .* 2 1 ;# A_C1.1" "$work/fibre-frame-pounding/script/model.tcl" \
  || fail "fibre: not a forceBeamColumn on PDelta"
for b in 1 2; do
  fibre_pair+=(--set "Building $b/Member element=displacement" --set "Building $b/Integration points=3")
done
case_suffix=-displacement check_example fibre-frame-pounding 1e-6 "${fibre_pair[@]}"
grep -q "^beamIntegration Legendre 1 1 3" "$work/fibre-frame-pounding-displacement/script/model.tcl" \
  || fail "fibre: not Legendre points"
# Bouc-Wen hinges (zeroLength -dir 6 on BoucWen, the member end's node
# tied to the joint by equalDOF): elastic (yield moments far beyond reach)
# at 1e-9 as the elastic frames; yielding (three-storey-frame-hinges, whose
# hinges reach ductilities near 30), by convergence: OpenSees's BoucWen
# integrates z by backward Euler, poundfe's by the trapezoidal rule, so at
# the steps 0.002, 0.001 and 0.0005 s (the record held over 0.002 s,
# Sample interval, the same motion at every step) the difference must
# halve with each halving (first order: ratios 0.4 to 0.6) and be below
# 5e-4 of the peak at the finest
case_suffix=-elastic check_example three-storey-frame-hinges 1e-9 \
  --set "Building 1/Hinges/Yield moment=200e9, 150e9, 150e9, 120e9"
grep -q -- "-dir 6 -doRayleigh 1$" "$work/three-storey-frame-hinges-elastic/script/model.tcl" \
  || fail "hinges: no rotational zeroLength"
# alpha = 1: F = k u whatever z, so both laws give the same force and the
# degradation rates, over OpenSees's energy (1 - alpha) k int z du = 0, are
# written as 0 (not 0/0): 1e-9 as the elastic frames
case_suffix=-alpha1 check_example three-storey-frame-hinges 1e-9 \
  --set "Building 1/Bouc-Wen/alpha=1" --set "Building 1/Bouc-Wen/delta nu=0.1"
grep -q "^uniaxialMaterial BoucWen [0-9]* 1 [^;]* 1 0 0 0 " \
  "$work/three-storey-frame-hinges-alpha1/script/model.tcl" || fail "alpha = 1: its rates"
converges() { # NAME FINEST-TOLERANCE DT1 DT2 DT3 -- [--set ...]: first order in the step
  local name=$1 finest=$2 steps=("$3" "$4" "$5")
  shift 6
  for dt in "${steps[@]}"; do
    case_suffix=-$dt check_example $name 1 --set "Time integration/Time step=$dt" "$@"
  done
  "$python" - "$work" $name $finest "${steps[@]}" <<'PY' || fail "$name: no first-order convergence"
import re, sys
work, name, finest, steps = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4:]
d = [max(float(x) for x in re.findall(r"peak ([0-9.e+-]+)$",
                                          open(f"{work}/{name}-{dt}.cmp").read(), re.M))
     for dt in steps]
print(f"{name}: largest difference / peak at dt, dt/2, dt/4:", " ".join(f"{x:.2e}" for x in d))
assert all(0.4 <= b / a <= 0.6 for a, b in zip(d, d[1:])) and d[-1] < finest, d
PY
}
converges three-storey-frame-hinges 5e-4 0.002 0.001 0.0005 -- \
  --set "Ground motion/Stochastic/Sample interval=0.002"
# Bouc-Wen storeys (a zeroLength on BoucWen beside one on Elastic 0 eta), the
# same way: ida-pounding-pair, its buildings apart (Separations 1 m: no
# impact; storey ductilities up to 2.6), the record held over 0.005 s; below
# 1e-2 of the peak at the finest step
converges ida-pounding-pair 1e-2 0.005 0.0025 0.00125 -- --set "Model/Separations=1" \
  --set "Ground motion/Stochastic/Sample interval=0.005"
# 3D frames (-ndm 3 -ndf 6: a master at each floor's mass centre, the joints
# under rigidDiaphragm 3, elasticBeamColumn A E G J Iy Iz on poundfe's v_xz):
# building A5 of 3d-torsional-pair alone, without hinges, one horizontal
# component along x; its mass eccentricity couples x, y and the twist. Each
# floor's x, y and theta_z at 1e-9 (linear), with the gravity analysis too
first_building() { # INPUT OUTPUT: the input with its first building alone
  "$python" - "$1" "$2" <<'PY'
import sys
text = open(sys.argv[1]).read()
start = text.index("subsection Building 2")
end = text.index("end\n", text.index("subsection Damping", start))
end = text.index("end\n", end + 4) + 4
open(sys.argv[2], "w").write((text[:start] + text[end:]).replace(
    "set Number of buildings = 2", "set Number of buildings = 1"))
PY
}
first_building "$inputs/3d-torsional-pair.prm" "$work/frame3d.prm"
frame3d=(--set "Building 1/Hinges/Locations=" --set "Ground motion/Stochastic/Duration=4"
  --set "Ground motion/Components=1" --set "Ground motion/Incidence angle=0")
inputs=$work check_example frame3d 1e-9 "${frame3d[@]}"
grep -q "^rigidDiaphragm 3 " "$work/frame3d/script/model.tcl" || fail "3D: no rigidDiaphragm"
inputs=$work case_suffix=-gravity check_example frame3d 1e-9 "${frame3d[@]}" \
  --set "Model/Gravity analysis/Type=static"
grep -q "^pattern Plain 2 Linear {" "$work/frame3d-gravity/script/model.tcl" \
  || fail "3D: no gravity pattern"
# a 3D member's mass per length: refused by its entry, saying whose limit it is
"$poundfe" export-opensees "$work/frame3d.prm" --output "$work/frame3d-mass" "${frame3d[@]}" \
  --set "Building 1/Column mass per length=300" > /dev/null 2> "$work/frame3d-mass.err"
[ $? = 1 ] && [ ! -e "$work/frame3d-mass/model.tcl" ] || fail "3D member mass: not refused"
grep -qF "'Building 1/Column mass per length': export-opensees writes 3D members without mass: \
the script's check, \`poundfe opensees\`, takes no mass" "$work/frame3d-mass.err" \
  || { cat "$work/frame3d-mass.err"; fail "3D member mass: message"; }
# 3D fibre members (section Fiber with -GJ, forceBeamColumn on 4 Lobatto
# points, the columns on geomTransf PDelta): building A of fibre-frame-3d
# alone, gravity first, its mass centre moved (Plan/Mass eccentricity) so
# that y and the twist respond; its steel yields. 1e-6 as the 2D fibre frames
first_building "$inputs/fibre-frame-3d.prm" "$work/fibre3d.prm"
inputs=$work check_example fibre3d 1e-6 --set "Ground motion/Components=1" \
  --set "Ground motion/Incidence angle=0" --set "Building 1/Plan/Mass eccentricity=0.5, 0.3"
grep -q "^section Fiber 1 -GJ " "$work/fibre3d/script/model.tcl" || fail "3D fibre: no -GJ"

# the gaps closed: the pounding pairs' scripts have gap forces, some non-zero
for case in shear-pair-pounding shear-pair-pounding-hertz shear-pair-pounding-jankowski \
  two-buildings fibre-frame-pounding; do
  "$python" -c "
import numpy as np, sys
f = np.loadtxt('$work/$case/script/gap_force.out', ndmin=2)
sys.exit(0 if np.abs(f[:, 1:]).max() > 0 else 'no impact')" || fail "$case: no impact"
done

# a default that stands for another value is written as that value:
# ElasticPP's epsyN, 0 for -epsyP in poundfe, would be no compressive
# strength in OpenSees 3.8 (ElasticPPMaterial: fyn = E epsyN), which
# `poundfe opensees` reads as poundfe does: so the text. The sections'
# steel law (Section 1) and a material of Sections/Materials without epsyN
# (Section 2 of fibres), exported, each ElasticPP line's epsyN = -epsyP
fibre_materials() { # OUTPUT MATERIALS: fibre-frame-pounding, Section 2 fibres of m and c
  "$python" - "$inputs/fibre-frame-pounding.prm" "$1" "$2" <<'PY'
import sys
text = open(sys.argv[1]).read()
text = text.replace("  set Number of sections = 2\n",
                    "  set Number of sections = 2\n  set Materials = %s\n" % sys.argv[3])
text = text.replace("    set Type                = RC rectangle\n    set Depth               = 0.5",
                    "    set Type = fibres\n    set Fibres = patch rect c 8 2 -0.25 -0.15 0.25 0.15;"
                    " layer straight m 3 3e-4 -0.2 -0.1 -0.2 0.1; layer straight m 3 3e-4 0.2 -0.1 0.2 0.1\n"
                    "    set Depth               = 0.5")
open(sys.argv[2], "w").write(text)
PY
}
concrete="c: Concrete01 fpc=-30e6 epsc0=-0.002 fpcu=-6e6 epscu=-0.0035"
fibre_materials "$work/fibre-elasticpp.prm" "m: ElasticPP E=2e11 epsyP=0.002; $concrete"
"$poundfe" export-opensees "$work/fibre-elasticpp.prm" --output "$work/fibre-elasticpp" \
  --set "Sections/Section 1/Steel law=ElasticPP" "${fibre_pair[@]}" > "$work/fibre-elasticpp.log" \
  2>&1 || { cat "$work/fibre-elasticpp.log"; fail "ElasticPP: export"; }
"$python" - "$work/fibre-elasticpp/model.tcl" <<'PY' || fail "ElasticPP: epsyN not -epsyP"
import sys
lines = [l.split() for l in open(sys.argv[1]) if l.startswith("uniaxialMaterial ElasticPP ")]
print("ElasticPP:", "; ".join(" ".join(l[3:6]) for l in lines))
assert len(lines) == 2 and all(float(l[5]) == -float(l[4]) < 0 for l in lines), lines
PY
# a name with a blank and an end backslash (a building's, a material's):
# one quoted word of the comments, which then end on the quote (a backslash
# there would join the next line to the comment); the script runs
fibre_materials "$work/fibre-names.prm" \
  "m\\: ElasticPP E=2e11 epsyP=0.002; c\\: Concrete01 fpc=-30e6 epsc0=-0.002 fpcu=-6e6 epscu=-0.0035"
sed -i 's/patch rect c /patch rect c\\ /; s/layer straight m /layer straight m\\ /g' \
  "$work/fibre-names.prm"
names=(--set "Building 1/Name=my bldg\\" --set "Time integration/End time=0.05")
"$poundfe" export-opensees "$work/fibre-names.prm" --output "$work/fibre-names" "${fibre_pair[@]}" \
  "${names[@]}" > "$work/fibre-names.log" 2>&1 || { cat "$work/fibre-names.log"; fail "names: export"; }
"$poundfe" opensees "$work/fibre-names/model.tcl" "$work/fibre-names" \
  > "$work/fibre-names.os.log" 2>&1 || { cat "$work/fibre-names.os.log"; fail "names: poundfe opensees"; }
grep -q "^status 0 " "$work/fibre-names.os.log" || { cat "$work/fibre-names.os.log"; fail "names: analyze"; }
"$python" - "$work/fibre-names/model.tcl" <<'PY' || fail "names: the comments' words"
import re, shlex, sys
script = open(sys.argv[1]).read()
columns = shlex.split(re.search(r"columns: time (.*)", script).group(1))
assert columns[0] == "my bldg\\_floor1_disp_m", columns
assert re.search(r';# "m\\\\"$', script, re.M), "material m\\"
assert re.search(r';# "my bldg\\\\_C1.1"$', script, re.M), "member my bldg\\_C1.1"
PY
echo "ok ElasticPP's epsyN, names in comments"

# refusals by entry, nothing written
refused() { # NAME EXPECTED-ENTRY-AND-MESSAGE-PART
  local dir="$work/refused-$1"
  "$poundfe" export-opensees "$inputs/$1.prm" --output "$dir" > "$dir.out" 2> "$dir.err"
  local status=$?
  [ "$status" = 1 ] || { cat "$dir.err"; fail "$1: exit status $status"; }
  grep -qF -- "$2" "$dir.err" || { cat "$dir.err"; fail "$1: message"; }
  [ ! -e "$dir/model.tcl" ] || fail "$1: model.tcl written"
}
refused_with() { # NAME LABEL EXPECTED-MESSAGE-PART [--set ...]
  local dir="$work/refused-$2" message=$3
  "$poundfe" export-opensees "$inputs/$1.prm" --output "$dir" "${@:4}" > "$dir.out" 2> "$dir.err"
  [ $? = 1 ] || { cat "$dir.err"; fail "$2: not refused"; }
  grep -qF -- "$message" "$dir.err" || { cat "$dir.err"; fail "$2: message"; }
  [ ! -e "$dir/model.tcl" ] || fail "$2: model.tcl written"
}
refused_with three-storey-frame-hinges bouc-wen-a "'Building 1/Bouc-Wen/A': export-opensees writes hinges of A = 1 only" \
  --set "Building 1/Bouc-Wen/A=0.9"
refused_with fibre-frame-pounding self-weight "'Building 1/Member self-weight': export-opensees writes no element loads" \
  --set "Building 1/Member self-weight=distributed" --set "Building 1/Member unit weight=25000" "${fibre_pair[@]}"
refused pushover-frame "'Model/Geometric nonlinearity': export-opensees writes no P-Delta"
refused 3d-torsional-pair "'Building 1/Hinges/Locations': export-opensees writes 3D frames without hinges"
refused 3d-torsional-shear-pair "'Building 1/Type': export-opensees writes 3D frames only"
refused fibre-frame-3d "'Contact/Law': export-opensees writes no contact in plan (3D)"
refused spillway-abutment "'Nodal forces/File': export-opensees writes no nodal forces"
# laws whose OpenSees namesakes differ: refused, saying how
refused_law() { # LAW EXPECTED-MESSAGE-PART
  local dir="$work/refused-law-$1"
  "$poundfe" export-opensees "$inputs/shear-pair-pounding.prm" --output "$dir" \
    --set "Contact/Law=$1" > "$dir.out" 2> "$dir.err"
  [ $? = 1 ] || { cat "$dir.err"; fail "$1: not refused"; }
  grep -qF -- "$2" "$dir.err" || { cat "$dir.err"; fail "$1: message"; }
  [ ! -e "$dir/model.tcl" ] || fail "$1: model.tcl written"
}
# a Hysteretic fibre material: by the Materials entry that defines it
fibre_materials "$work/fibre-hysteretic.prm" \
  "m: Hysteretic s1p=3e8 e1p=0.0015 s2p=4e8 e2p=0.02 s1n=-3e8 e1n=-0.0015 s2n=-4e8 e2n=-0.02; $concrete"
inputs=$work refused_with fibre-hysteretic hysteretic "fibre-hysteretic.prm:22: parameter 'Sections/Materials': export-opensees writes no Hysteretic fibre material (material 'm', used by Section 2)" \
  "${fibre_pair[@]}"
refused_law hertz-damp "'Contact/Law': export-opensees writes the contact laws linear, hertz and jankowski; 'hertz-damp' not: OpenSees's Hertzdamp takes the approach velocity"
refused_law kelvin-voigt "ViscoelasticGap lets the force k d + c d' turn negative"
refused three-storey-free-vibration "'Building 1/Damping/Type': modal damping"
# white noise without an envelope: a_g(0) != 0, where the two Newmarks start apart
refused subset-drift "'Ground motion/Type': the ground motion starts at a_g(0) = "
echo "opensees_export: ok"
