#!/usr/bin/env bash
# `poundfe opensees` with fibre sections and beam-columns (Running OpenSees
# scripts in doc/user-guide.md):
#  1. closed forms (tests/opensees/beam_column_checks.tcl): elastic members
#     of every element, integration and section kind against the exact
#     cantilever, a layered fibre section's inertia, the responses (eleForce,
#     eleResponse), DisplacementControl reaching its displacements exactly,
#     the plastic moment of a yielded section, a corotational quarter circle,
#     ArcLength's load factors in equilibrium with the reactions past the limit point,
#     an sp imposed by constraints Lagrange and Penalty (OpenSees 3.8's numbers),
#     two cantilevers tied by rigidLink bar;
#  2. the recorder Element file layout against eleResponse;
#  3. side by side with OpenSees 3.8: the scripts of tests/opensees/fibre_*.tcl
#     against OpenSees's own recorder output committed in
#     tests/opensees/reference/ (bench/opensees/compare.py, tolerance per
#     case in its CASES: 1e-10 of the peak linear, 1e-6 nonlinear, 1e-9 for
#     the frame with committed-stiffness damping, HHT, NewtonLineSearch
#     (whose searches' etas are compared too), KrylovNewton, BFGS, element
#     loads and a beam's end displacements imposed by sp; ViscousDamper,
#     Series, twoNodeLink and the 3D beam-columns; ArcLength, constraints
#     Lagrange and Penalty; geomTransf Corotational in space, and its
#     circle against the elastica); a kept value moved by ten times its
#     case's tolerance must fail that check (six cases);
#  4. refusals by name: an unsupported option, a patch outside a section, a
#     section without fibres, a missing integration, a line search other than
#     InitialInterpolated, HHT's alpha outside (0, 1] or an infinite number,
#     NewtonLineSearch with -maxIter < 1 or -minEta > -maxEta or with
#     DisplacementControl, KrylovNewton with a tangent other than the current
#     one, -maxDim < 0 or DisplacementControl, eleLoad on a beam-column, of another type, or
#     outside a pattern, BFGS -secant or -count 0, sp in a transient
#     analysis, on a fixed DOF or outside a pattern, ArcLength or an adaptive
#     DisplacementControl under constraints Lagrange; sp imposed (Transformation) and
#     held at zero (Plain) on an elastic cantilever; a refused command caught
#     by catch leaves the settings before it; constraints after analysis
#     waits for the next analysis (OpenSees 3.8's line); rigidLink beam's
#     and remove mp's and -cMass's hostile words (extra, missing, unknown
#     node, NaN, a tie's constrained node with mass, -cMass on Corotational).
#  5. OpenSees's 3D RC frame script (bench/opensees/fibre_frame_3d/frame.tcl:
#     rigidDiaphragm, 3D forceBeamColumns on fibre sections) against its peaks.
#   opensees_fibre.sh POUNDFE CORPUS_DIR PYTHON3
set -u
poundfe=$1 corpus=$2 python=$3
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$here/helpers.sh"
# a failure inside a pipeline's function ends only its subshell: remember it
fail() { echo "FAIL $*"; touch "$work/failed"; exit 1; }
"$python" -c "import numpy" 2> /dev/null || python=/usr/bin/python3

# 1. closed forms
"$poundfe" opensees "$corpus/beam_column_checks.tcl" > "$work/checks" 2>&1 \
  || { status=$?; cat "$work/checks"; fail "beam_column_checks.tcl: exit $status"; }
grep FAIL "$work/checks" && fail "beam_column_checks.tcl: a check failed"
[ "$(grep -c '^ok ' "$work/checks")" -ge 40 ] || { cat "$work/checks"; fail "checks missing"; }
grep -qx 'failures 0' "$work/checks" || fail "beam_column_checks.tcl did not finish"

# 2. recorder Element: -time then each element's values, as eleResponse
cat > "$work/rec.tcl" <<'TCL'
set out [lindex $argv 0]
model basic -ndm 2 -ndf 3
node 1 0.0 0.0
node 2 0.0 3.0
node 3 0.0 6.0
fix 1 1 1 1
geomTransf Linear 1
uniaxialMaterial Steel01 1 300.0e3 2.0e8 0.02
section Fiber 1 {
    patch quad 1 4 2 -0.2 -0.1 0.2 -0.1 0.2 0.1 -0.2 0.1
    layer straight 1 3 1.0e-3 -0.15 0.0 0.15 0.0
    fiber 0.0 0.0 1.0e-3 1
}
beamIntegration Legendre 1 1 3
element dispBeamColumn 1 1 2 1 1
element dispBeamColumn 2 2 3 1 1
recorder Element -file $out/force.out -time -precision 12 -ele 1 2 force
recorder Element -file $out/local.out -precision 12 -eleRange 1 2 localForce
recorder Element -file $out/section.out -precision 12 -ele 1 section 2 deformation
timeSeries Linear 1
pattern Plain 1 1 { load 3 1.0 0.0 0.0 }
integrator DisplacementControl 3 1 0.01
analysis Static
analyze 3
puts "time [getTime %.17g]"
puts "force [eleResponse 1 force] [eleResponse 2 force]"
puts "local [eleResponse 1 localForce] [eleResponse 2 localForce]"
puts "section [eleResponse 1 section 2 deformation]"
TCL
"$poundfe" opensees "$work/rec.tcl" "$work" > "$work/rec.log" 2>&1 \
  || { status=$?; cat "$work/rec.log"; fail "rec.tcl: exit $status"; }
"$python" - "$work" <<'PY' || fail "recorder Element layout"
import sys
import numpy as np
w = sys.argv[1]
log = {l.split()[0]: np.array(l.split()[1:], float) for l in open(w + "/rec.log")
       if l.split()[0] in ("time", "force", "local", "section")}
force, local, section = (np.loadtxt(f"{w}/{n}.out", ndmin=2) for n in ("force", "local", "section"))
assert force.shape == (3, 13) and local.shape == (3, 12) and section.shape == (3, 2), \
    (force.shape, local.shape, section.shape)
assert abs(force[-1, 0] - log["time"][0]) <= 1e-10 * log["time"][0], (force[:, 0], log["time"])
for name, table, last in (("force", force[:, 1:], log["force"]), ("local", local, log["local"]),
                          ("section", section, log["section"])):
    assert np.allclose(table[-1], last, rtol=1e-10, atol=1e-9 * abs(last).max()), (name, table[-1], last)
PY

# 4. refusals by name, at the script's line
bad() { # NAME EXPECTED-MESSAGE-TAIL, the script's body on stdin
  local dir="$work/bad-$1"
  mkdir -p "$dir"
  { echo "model basic -ndm 2 -ndf 3"
    echo "node 1 0.0 0.0"
    echo "node 2 0.0 3.0"
    echo "geomTransf Linear 1"
    echo "uniaxialMaterial Elastic 1 2.0e8"
    cat; } > "$dir/s.tcl"
  "$poundfe" opensees "$dir/s.tcl" > "$dir/out" 2> "$dir/err"
  local status=$?
  [ "$status" = 1 ] || fail "$1: exit status $status"
  grep -qxF -- "poundfe: error: $dir/s.tcl:$2" "$dir/err" || { cat "$dir/err"; fail "$1: message"; }
}
printf 'section Elastic 1 2.0e8 0.01 1.0e-4\nelement forceBeamColumn 1 1 2 3 1 1 -subdivide 4 10.0\n' \
  | bad subdivide "7: element forceBeamColumn option '-subdivide': poundfe does not support it"
printf 'section Elastic 1 2.0e8 0.01 1.0e-4\nelement dispBeamColumn 1 1 2 3 1 1 -iter 10 1e-12\n' \
  | bad disp-iter "7: element dispBeamColumn option '-iter': poundfe does not support it"
echo "patch rect 1 2 2 -0.1 -0.1 0.1 0.1" | bad patch-outside \
  '6: patch belongs in the body of a section Fiber'
echo "section Fiber 1 { }" | bad no-fibre '6: section Fiber 1 has no fibre'
echo "section Fiber 1 { patch rect 7 2 2 -0.1 -0.1 0.1 0.1 }" | bad missing-material \
  '6: section: patch: uniaxialMaterial 7 does not exist'
echo "element forceBeamColumn 1 1 2 1 4" | bad missing-integration \
  '6: element: beamIntegration 4 does not exist'
echo "beamIntegration NewtonCotes 1 1 3" | bad unsupported-rule \
  '6: beamIntegration NewtonCotes: poundfe does not support it'
echo "integrator DisplacementControl 2 1 0.1 -initial" | bad dc-initial \
  '6: integrator DisplacementControl -initial: poundfe does not support it'
echo "algorithm NewtonLineSearch -type Bisection" | bad line-search-type \
  '6: algorithm NewtonLineSearch -type Bisection: poundfe does not support it'
echo "algorithm NewtonLineSearch -tol 0.5 -beta 2" | bad line-search-option \
  "6: algorithm NewtonLineSearch option '-beta': poundfe does not support it"
printf 'section Elastic 1 2.0e8 0.01 1.0e-4\ngeomTransf Corotational 2\nelement forceBeamColumn 1 1 2 3 1 2\ntimeSeries Linear 1\npattern Plain 1 1 { eleLoad -ele 1 -type -beamUniform -1.0 }\n' \
  | bad element-load-beam-column '10: pattern: eleLoad on element 1 (only elasticBeamColumn in the plane, and forceBeamColumn and dispBeamColumn, on a Linear or PDelta transformation take it): poundfe does not support it'
printf 'section Elastic 1 2.0e8 0.01 1.0e-4\nsection Aggregator 2 1 Mz -section 1\n' \
  | bad aggregator-base-dof '7: section Aggregator 2: dof Mz is in the -section already (OpenSees 3.8 then has two Mz resultants: in series in forceBeamColumn, in parallel in dispBeamColumn)'
printf 'section Aggregator 2 1 Mz 1 Vy\n' \
  | bad aggregator-shear "6: section Aggregator dof 'Vy' in the plane (it takes P and Mz): poundfe does not support it"
printf 'section Aggregator 2 1 Mz 1 Mz\n' \
  | bad aggregator-twice '6: section Aggregator 2: dof Mz given twice'
printf 'section Aggregator 2 1 Mz\n' \
  | bad aggregator-missing '6: section Aggregator without P and without an Elastic -section: poundfe does not support it'
printf 'element elasticBeamColumn 1 1 2 0.01 2.0e8 1.0e-4 1\ntimeSeries Linear 1\npattern Plain 1 1 { eleLoad -ele 1 -type -beamPoint -1.0 0.5 }\n' \
  | bad element-load-point '8: pattern: eleLoad -type -beamPoint: poundfe does not support it'
printf 'element elasticBeamColumn 1 1 2 0.01 2.0e8 1.0e-4 1\neleLoad -ele 1 -type -beamUniform -1.0\n' \
  | bad element-load-outside '7: eleLoad: an eleLoad belongs in the body of a Plain pattern'
printf 'node 3 1.0 3.0\nrigidLink beam 2 3 1\n' | bad rigid-link-beam-extra \
  "7: rigidLink: '1' after the constrained node: rigidLink beam takes two nodes"
printf 'rigidLink beam 2 9\n' | bad rigid-link-beam-node '6: rigidLink: node 9 does not exist'
printf 'rigidLink beam 2 2\n' | bad rigid-link-beam-same \
  '6: rigidLink: the retained and the constrained node are the same'
printf 'rigidLink beam 2\n' | bad rigid-link-beam-missing '6: rigidLink: missing the constrained node'
printf 'rigidLink pin 1 2\n' | bad rigid-link-pin '6: rigidLink pin: poundfe does not support it'
printf 'node 3 1.0 3.0 -mass 1.0 1.0 0.0\nrigidLink beam 2 3\nfix 1 1 1 1\nelement elasticBeamColumn 1 1 2 0.01 2.0e8 1.0e-4 1\nintegrator LoadControl 1.0\nanalysis Static\nanalyze 1\n' \
  | bad rigid-link-beam-mass '12: analyze: rigidLink beam (s.tcl:7): node 3 has mass along DOF 1: poundfe takes a rigid link'"'"'s mass at its retained node'
# chains through a rigid tie: a loop is refused by name, and so is mass
# (lumped or -cMass) on an equalDOF's node that follows a tie's node
printf 'node 3 1.0 3.0\nrigidLink beam 2 3\nequalDOF 3 2 1\nfix 1 1 1 1\nelement elasticBeamColumn 1 1 2 0.01 2.0e8 1.0e-4 1\nintegrator LoadControl 1.0\nanalysis Static\nanalyze 1\n' \
  | bad tie-loop '13: analyze: rigidLink beam (s.tcl:7): the retained node 2 is constrained in a loop of constraints'
printf 'node 3 1.0 3.0\nnode 4 2.0 3.0 -mass 1.0 1.0 0.0\nrigidLink beam 2 3\nequalDOF 3 4 1 2\nfix 1 1 1 1\nelement elasticBeamColumn 1 1 2 0.01 2.0e8 1.0e-4 1\nelement elasticBeamColumn 2 3 4 0.01 2.0e8 1.0e-4 1\nintegrator LoadControl 1.0\nanalysis Static\nanalyze 1\n' \
  | bad tie-chain-mass "15: analyze: equalDOF 3 4: node 4 DOF 1 has mass and follows a rigid tie's constrained node: poundfe takes a tie's mass at its retained node"
printf 'node 3 1.0 3.0\nnode 4 2.0 3.0\nnode 5 2.0 0.0\nrigidLink beam 2 3\nequalDOF 3 4 1 2\nfix 1 1 1 1\nfix 5 1 1 1\nelement elasticBeamColumn 1 1 2 0.01 2.0e8 1.0e-4 1\nelement elasticBeamColumn 2 5 4 0.01 2.0e8 1.0e-4 1 -mass 5.0 -cMass\nintegrator LoadControl 1.0\nanalysis Static\nanalyze 1\n' \
  | bad tie-chain-cmass "17: analyze: element 2: a consistent mass (-cMass) on node 4, whose DOF 1 follows a rigid tie's constrained node"
printf 'geomTransf Corotational 2\nelement elasticBeamColumn 1 1 2 0.01 2.0e8 1.0e-4 2 -mass 5.0 -cMass\n' \
  | bad cmass-corotational '7: element 1 -cMass on geomTransf Corotational: poundfe does not support it'
printf 'element elasticBeamColumn 1 1 2 0.01 2.0e8 1.0e-4 1 -mass 5.0 -cMass 1\n' \
  | bad cmass-value "6: element elasticBeamColumn option '1': poundfe does not support it"
printf 'element elasticBeamColumn 1 1 2 0.01 2.0e8 1.0e-4 1 -mass nan -cMass\n' \
  | bad cmass-nan "6: element: expected a number for the mass per length, got 'nan'"
echo "integrator HHT 1.5" | bad hht-alpha '6: integrator: HHT needs 0 < alpha <= 1'
echo "integrator HHT 0.9 inf 0.25" | bad hht-infinite "6: integrator: expected a finite number for gamma, got 'inf'"
echo "constraints Penalty 1.0e12" | bad penalty-alpha '6: constraints: missing alphaMP'
echo "constraints Penalty 0.0 1.0e12" | bad penalty-zero \
  '6: constraints: Penalty needs alphaSP > 0 and alphaMP > 0'
echo "constraints Auto" | bad handler-auto '6: constraints Auto: poundfe does not support it'
echo "integrator ArcLength 0.01" | bad arc-length-alpha '6: integrator: missing alpha'
echo "integrator ArcLength 0.0 1.0" | bad arc-length-zero '6: integrator: ArcLength needs an arc length > 0'
printf 'fix 1 1 1 1\nelement elasticBeamColumn 1 1 2 0.01 2.0e8 1.0e-4 1\ntimeSeries Linear 1\npattern Plain 1 1 { load 2 1.0 0.0 0.0 }\nalgorithm BFGS\nintegrator ArcLength 0.001 1.0\nanalysis Static\nanalyze 1\n' \
  | bad bfgs-arc-length '13: analyze: algorithm BFGS with integrator ArcLength is not supported'
printf 'fix 1 1 1 1\nelement elasticBeamColumn 1 1 2 0.01 2.0e8 1.0e-4 1\ntimeSeries Linear 1\npattern Plain 1 1 { load 2 1.0 0.0 0.0 }\nconstraints Lagrange\nintegrator ArcLength 0.001 1.0\nanalysis Static\nanalyze 1\n' \
  | bad lagrange-arc-length "13: analyze: integrator ArcLength with constraints Lagrange (OpenSees's multipliers enter the arc) is not supported"
printf 'fix 1 1 1 1\nelement elasticBeamColumn 1 1 2 0.01 2.0e8 1.0e-4 1\ntimeSeries Linear 1\npattern Plain 1 1 { load 2 1.0 0.0 0.0 }\nconstraints Lagrange\nintegrator DisplacementControl 2 1 0.001 3 0.0001 0.01\nanalysis Static\nanalyze 1\n' \
  | bad lagrange-adaptive-dc "13: analyze: integrator DisplacementControl with an adaptive increment (minIncr != maxIncr) with constraints Lagrange (OpenSees's multipliers enter the iteration counts) is not supported"
echo "algorithm NewtonLineSearch -maxIter -5" | bad line-search-iterations \
  '6: algorithm: NewtonLineSearch needs -maxIter >= 1'
echo "algorithm NewtonLineSearch -minEta 10 -maxEta 0.1" | bad line-search-eta \
  '6: algorithm: NewtonLineSearch needs 0 < -minEta <= -maxEta'
printf 'fix 1 1 1 1\nelement elasticBeamColumn 1 1 2 0.01 2.0e8 1.0e-4 1\ntimeSeries Linear 1\npattern Plain 1 1 { load 2 1.0 0.0 0.0 }\nalgorithm NewtonLineSearch\nintegrator DisplacementControl 2 1 0.001\nanalysis Static\nanalyze 1\n' \
  | bad line-search-dc '13: analyze: algorithm NewtonLineSearch with integrator DisplacementControl is not supported'
echo "algorithm KrylovNewton -iterate initial" | bad krylov-tangent \
  '6: algorithm KrylovNewton -iterate initial: poundfe does not support it'
echo "algorithm KrylovNewton -maxDim -1" | bad krylov-dimension \
  '6: algorithm: KrylovNewton needs -maxDim >= 0'
printf 'fix 1 1 1 1\nelement elasticBeamColumn 1 1 2 0.01 2.0e8 1.0e-4 1\ntimeSeries Linear 1\npattern Plain 1 1 { load 2 1.0 0.0 0.0 }\nalgorithm KrylovNewton\nintegrator DisplacementControl 2 1 0.001\nanalysis Static\nanalyze 1\n' \
  | bad krylov-dc '13: analyze: algorithm KrylovNewton with integrator DisplacementControl is not supported'
printf 'section Elastic 1 2.0e8 0.01 1.0e-4\nelement forceBeamColumn 1 1 2 3 1 1\nrecorder Element -file x.out -ele 1 plasticRotation\n' \
  | bad unknown-response "8: recorder: element 1 has no response 'plasticRotation' in poundfe"
echo "algorithm BFGS -secant" | bad bfgs-secant \
  "6: algorithm BFGS option '-secant': poundfe does not support it"
echo "algorithm BFGS -count 0" | bad bfgs-count '6: algorithm: BFGS needs -count >= 1'
printf 'fix 1 1 1 1\nelement elasticBeamColumn 1 1 2 0.01 2.0e8 1.0e-4 1\ntimeSeries Linear 1\npattern Plain 1 1 { sp 2 1 0.001 }\nanalysis Transient\nanalyze 1 0.01\n' \
  | bad sp-transient '11: analyze: sp in a transient analysis is not supported'
printf 'fix 2 1 1 1\ntimeSeries Linear 1\npattern Plain 1 1 { sp 2 1 0.001 }\n' \
  | bad sp-fixed '8: pattern: sp: node 2 DOF 1 is fixed'
echo "sp 2 1 0.001" | bad sp-outside '6: sp: an sp belongs in the body of a Plain pattern'

# sp on an elastic cantilever (L = 3, EI = 2e4), its tip's ux imposed at
# 0.001 times the factor: Transformation imposes it (two steps: 0.002, the
# tip turning by -3 u / 2L, the base's reaction 3 EI u / L^3), Plain holds
# it at zero with OpenSees's warning
sp_check() { # CONSTRAINTS EXPECTED-LINE
  printf 'model basic -ndm 2 -ndf 3\nnode 1 0.0 0.0\nnode 2 0.0 3.0\nfix 1 1 1 1\ngeomTransf Linear 1\nelement elasticBeamColumn 1 1 2 0.01 2.0e8 1.0e-4 1\ntimeSeries Linear 1\npattern Plain 1 1 { sp 2 1 0.001 }\nconstraints %s\nsystem BandGeneral\ntest NormDispIncr 1e-12 10\nalgorithm Newton\nintegrator LoadControl 1.0\nanalysis Static\nanalyze 2\nreactions\nputs [format "u %%.12g %%.12g r %%.12g" [nodeDisp 2 1] [nodeDisp 2 3] [nodeReaction 1 1]]\n' \
    "$1" > "$work/sp.tcl"
  "$poundfe" opensees "$work/sp.tcl" > "$work/sp.out" 2>&1 || { cat "$work/sp.out"; fail "sp $1"; }
  grep -qx -- "$2" "$work/sp.out" || { cat "$work/sp.out"; fail "sp $1: response"; }
}
sp_check Transformation "u 0.002 -0.001 r -4.44444444444"
sp_check Plain "u 0 0 r 0"
grep -q "homogeneous constraint assumed" "$work/sp.out" || fail "sp Plain: no warning"
# Lagrange imposes it exactly, Penalty 1e12 to its error: OpenSees 3.8's
# lines, to its 12 digits
sp_check Lagrange "u 0.002 -0.001 r -4.44444444444"
sp_check "Penalty 1.0e12 1.0e12" "u 0.00199999999556 -0.000999999988889 r -4.4444443358"

# a refused command leaves the settings before it: Transformation keeps
# the equalDOF (node 3's uy is node 2's), LoadControl 1.0 two steps (t 2)
# on a linear frame, the column shortened by 2 L / EA = 3e-6
two_bays='model basic -ndm 2 -ndf 3\nnode 1 0.0 0.0\nnode 2 0.0 3.0\nnode 3 4.0 3.0\nfix 1 1 1 1\ngeomTransf Linear 1\nelement elasticBeamColumn 1 1 2 0.01 2.0e8 1.0e-4 1\nelement elasticBeamColumn 2 2 3 0.01 2.0e8 1.0e-4 1\nequalDOF 2 3 2\ntimeSeries Linear 1\npattern Plain 1 1 { load 3 1.0 -1.0 0.0 }\nsystem BandGeneral\ntest NormDispIncr 1e-10 20\n'
printf "$two_bays"'constraints Transformation\ncatch {constraints Penalty 1.0e10}\nalgorithm Newton\ncatch {algorithm NewtonLineSearch -tol 0.5 -beta 2}\nintegrator LoadControl 1.0\ncatch {integrator ArcLength -1.0 0.0}\ncatch {integrator DisplacementControl 3 2 0.1 0 0.1 0.1}\nanalysis Static\nputs [format "analyze %%d t %%g uy %%.6g %%.6g" [analyze 2] [getTime] [nodeDisp 3 2] [nodeDisp 2 2]]\n' \
  > "$work/kept.tcl"
"$poundfe" opensees "$work/kept.tcl" > "$work/kept.out" 2>&1 || { cat "$work/kept.out"; fail "refused commands"; }
grep -qx "analyze 0 t 2 uy -3e-06 -3e-06" "$work/kept.out" || { cat "$work/kept.out"; fail "a refused command changed the settings"; }
# constraints after analysis: the next analysis's handler, as OpenSees 3.8's
# (its line: the fixed base moved 2e-10 by Penalty, Transformation's uy)
printf "$two_bays"'constraints Penalty 1.0e10 1.0e10\nanalysis Static\nanalyze 1\nconstraints Transformation\nanalyze 1\nset kept [nodeDisp 1 1]\nanalysis Static\nanalyze 1\nputs [format "Penalty kept %%.3g, then Transformation %%.3g" $kept [nodeDisp 3 2]]\n' \
  > "$work/switch.tcl"
"$poundfe" opensees "$work/switch.tcl" > "$work/switch.out" 2>&1 || { cat "$work/switch.out"; fail "constraints after analysis"; }
grep -qx "Penalty kept 2e-10, then Transformation -4.5e-06" "$work/switch.out" \
  || { cat "$work/switch.out"; fail "constraints after analysis: not the next analysis's"; }

# 3. side by side with OpenSees 3.8: its committed numbers (every 10th row)
"$python" "$here/../../bench/opensees/compare.py" "$poundfe" --check "$corpus/reference" \
  "$work/vs" > "$work/vs.log" 2>&1 || { cat "$work/vs.log"; fail "against OpenSees 3.8's numbers"; }
files=$(find "$corpus/reference" -type f | wc -l)
grep -c '^ok ' "$work/vs.log" | grep -qx "$files" || { cat "$work/vs.log"; fail "not every file compared"; }
# ArcLength's load factor (the recorder's time) is the load the supports
# carry: each takes half the apex load of the symmetric arch (1e-10 of the
# peak: the residual left by NormDispIncr 1e-12), past its limit point
"$python" - "$work/vs/arc_length_arch/support.out" <<'PY' || fail "ArcLength: load factor and reactions"
import sys
import numpy as np
support = np.loadtxt(sys.argv[1])
lam = support[:, 0]
worst = abs(2 * support[:, 2] - lam).max() / abs(lam).max()
print(f"ArcLength: 2 R_y - lambda {worst:.1e} of the peak, lambda from {lam.max():.4g} to {lam.min():.4g}")
sys.exit(0 if worst <= 1e-10 and lam.max() > 80 and lam.min() < -50 else 1)
PY
# geomTransf Corotational in space: the skew cantilever under the tip moment
# M = 2 pi EI/L about n (its local z) rolls into a circle, Euler's elastica in
# the plane normal to n. Each chord keeps its length l and turns by M l/EI,
# so the nodes lie on the circle of radius l/(2 sin(pi/n)) about the base
# moved by that radius along n x d, the tip back at the base (the continuum's
# radius EI/M = L/2 pi within 0.7 %, about (pi/n)^2/6); the tip's rotation DOFs add up to
# 2 pi n (increments about one axis). 1e-8 of L and 1e-9 of 2 pi: Newton's
# tolerance (NormDispIncr 1e-12 over 40 steps)
"$python" - "$work/vs/corot3d_circle" <<'PY' || fail "Corotational 3D: the circle"
import math
import sys
import numpy as np
nodes = np.loadtxt(sys.argv[1] + "/circle_nodes.out")[-1, 1:].reshape(-1, 3)
rotation = np.loadtxt(sys.argv[1] + "/circle_tip_rotation.out")[-1, 1:]
count, length = len(nodes) - 1, 4.0
d, n = np.array([1.0, 2.0, 2.0]) / 3, np.array([2.0, 1.0, -2.0]) / 3
x = np.outer(np.arange(count + 1) * length / count, d) + nodes
radius = length / count / (2 * math.sin(math.pi / count))
centre = radius * np.cross(n, d)
radii = np.abs(np.linalg.norm(x - centre, axis=1) - radius).max() / length
tip = np.linalg.norm(x[-1]) / length
turn = np.abs(rotation - 2 * math.pi * n).max() / (2 * math.pi)
polygon = radius / (length / (2 * math.pi)) - 1
print(f"circle: radii {radii:.1e} L, tip {tip:.1e} L, rotation {turn:.1e}, polygon {polygon:.2e}")
sys.exit(0 if radii < 1e-8 and tip < 1e-8 and turn < 1e-9 and polygon < 0.007 else 1)
PY
# the check can fail: one of OpenSees's kept values (a file's largest, past
# the time column) moved by ten times its case's tolerance of its column's
# peak is reported by name: the pounding pair's displacement with Viscous
# (1e-9), the 3D elastic column's local forces (1e-9), the 3D twoNodeLinks'
# gap force (1e-6) and the 3D fibre frame's section (1e-6)
perturbed_fails() {
  mkdir -p "$work/perturbed-$1"
  cp -r "$corpus/reference/$1" "$work/perturbed-$1/"
  "$python" - "$work/perturbed-$1/$1/$2" "$3" <<'PY' || fail "perturbing a reference of $1"
import sys
import numpy as np
table = np.loadtxt(sys.argv[1], ndmin=2)
row, col = np.unravel_index(np.abs(table[:, 1:]).argmax(), table[:, 1:].shape)
table[row, col + 1] *= 1 + float(sys.argv[2])
np.savetxt(sys.argv[1], table, fmt="%.12g")
PY
  "$python" "$here/../../bench/opensees/compare.py" "$poundfe" --check "$work/perturbed-$1" \
    "$work/vs-perturbed-$1" > "$work/perturbed-$1.log" 2>&1 \
    && { cat "$work/perturbed-$1.log"; fail "a perturbed reference value of $1 passed"; }
  grep -q "^FAIL $1/$2" "$work/perturbed-$1.log" \
    || { cat "$work/perturbed-$1.log"; fail "the perturbed file $1/$2 not named"; }
}
perturbed_fails pounding_Viscous pounding_Viscous.out 1e-8
perturbed_fails frame_3d_elastic frame3d_column.out 1e-8
perturbed_fails links_3d links_3d_gap.out 1e-5
perturbed_fails frame_3d_fibre frame3d_section.out 1e-5
perturbed_fails handlers_penalty handler_disp.out 1e-8
perturbed_fails corot3d_frame frame_roof.out 1e-5

# 5. OpenSees's script of a 3D RC frame (bench/opensees/fibre_frame_3d/frame.tcl:
#    rigidDiaphragm, forceBeamColumn on 3D fibre sections, PDelta with vecxz) against
#    OpenSees's peaks as doc/verification.md gives them to ten digits (2e-10: their rounding)
mkdir -p "$work/frame3d"
program=$(cd "$(dirname "$poundfe")" && pwd)/$(basename "$poundfe")
(cd "$here/../../bench/opensees/fibre_frame_3d" && "$program" opensees frame.tcl "$work/frame3d") \
  > "$work/frame3d/log" 2>&1 || { cat "$work/frame3d/log"; fail "frame.tcl"; }
"$python" - "$work/frame3d" <<'PY' || fail "frame.tcl against OpenSees 3.8's peaks"
import sys
import numpy as np
roof = np.loadtxt(sys.argv[1] + "/roof.out")
base = np.loadtxt(sys.argv[1] + "/base.out")
ours = [abs(roof[:, 1]).max(), abs(roof[:, 2]).max(),
        abs(base[:, 1::3].sum(axis=1)).max(), abs(base[:, 2::3].sum(axis=1)).max()]
theirs = [0.06782418398, 0.04362209415, 490211.7732, 419184.4819]
worst = max(abs(a - b) / b for a, b in zip(ours, theirs))
print(f"frame.tcl peaks against OpenSees 3.8: {worst:.1e}")
sys.exit(0 if worst <= 2e-10 else 1)
PY

[ -e "$work/failed" ] && exit 1
echo "opensees_fibre: ok"
