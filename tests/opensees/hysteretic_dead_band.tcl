# Hysteretic's dead band (OpenSees 3.8, HystereticMaterial::setTrialStrain):
# a strain change below DBL_EPSILON from the committed strain keeps the
# committed history and takes the strain, with the last trial's stress,
# tangent and loading direction; at strain 0 with the last trial still
# virgin, the last trial is kept as it is. A Hysteretic spring with
# pinching, damage and degraded unloading (s1p 100 at 0.001, 150 at 0.01,
# 160 at 0.05; the negative side 80 % of it), in parallel with an Elastic
# spring of 100 on a zeroLength, gets a virgin step of 1e-17 and a step
# back to 0, each followed by one Linear LoadControl step of 0.1; then
# cycles to 0.004, -0.004, 0.012 and -0.012 by DisplacementControl, with a
# reversal of 1e-17 at each peak (inside the band: the spring keeps its
# loading tangent) and one Linear step of 1 in the direction of loading,
# which moves the spring by 1 over the tangent the band left (the loading
# branch's, where a taken reversal would give the unloading one's).
#   argv: the output directory.
set out [lindex $argv 0]
wipe
model basic -ndm 1 -ndf 1
node 1 0.0
node 2 0.0
fix 1 1
uniaxialMaterial Hysteretic 1 100.0 0.001 150.0 0.01 160.0 0.05 \
    -80.0 -0.001 -120.0 -0.01 -128.0 -0.05 0.8 0.2 0.01 0.02 0.3
uniaxialMaterial Elastic 2 100.0
element zeroLength 1 1 2 -mat 1 2 -dir 1 1
recorder Node -file $out/band_disp.out -time -precision 16 -node 2 -dof 1 disp
recorder Node -file $out/band_reaction.out -time -precision 16 -node 1 -dof 1 reaction
recorder Element -file $out/band_stress.out -time -precision 16 -ele 1 material 1 stressStrainTangent
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-14 30
integrator LoadControl 0.1
analysis Static
timeSeries Linear 1
pattern Plain 1 1 { load 2 1.0 }

proc step_then_linear {step load} {
    algorithm Newton
    integrator DisplacementControl 2 1 $step
    analyze 1
    algorithm Linear
    integrator LoadControl $load
    analyze 1
    algorithm Newton
}
step_then_linear 1.0e-17 0.1
step_then_linear [expr {-[nodeDisp 2 1]}] 0.1
set u [nodeDisp 2 1]
foreach target {0.004 -0.004 0.012 -0.012} {
    set n [expr {int(round(abs($target - $u) / 0.0005))}]
    set step [expr {($target - $u) / $n}]
    integrator DisplacementControl 2 1 $step
    if {[analyze $n] != 0} { puts "failed at u $u"; exit 2 }
    set sign [expr {$step > 0 ? 1.0 : -1.0}]
    step_then_linear [expr {-$sign * 1.0e-17}] $sign
    set u [nodeDisp 2 1]
}
puts "hysteretic dead band: u [nodeDisp 2 1]"
