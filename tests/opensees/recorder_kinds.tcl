# OpenSees's recorders beyond Node and Element: Drift, EnvelopeNode and
# EnvelopeElement (three rows: min, max, max |.|, with -time the time of
# each), -dT (a record when the time is at least dT past the last, within
# OpenSees's relative tolerance -rTolDt) and -timeSeries (absolute
# accelerations; more tags than DOFs: the first ones, as OpenSees). A
# two-storey elastic frame (6 m bay, 3 m storeys) pounds through an
# ElasticPPGap link on a stick beside its roof (a mass on a
# spring, both nodes where the roof's corner is): gravity, then the
# synthetic record with Rayleigh damping. argv: the output directory.
set out [lindex $argv 0]
source [file join [file dirname [info script]] record.tcl]
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0
node 2 6.0 0.0
node 3 0.0 3.0 -mass 2.0e4 2.0e4 0.0
node 4 6.0 3.0 -mass 2.0e4 2.0e4 0.0
node 5 0.0 6.0 -mass 1.5e4 1.5e4 0.0
node 6 6.0 6.0 -mass 1.5e4 1.5e4 0.0
node 7 6.0 6.0
node 8 6.0 6.0 -mass 3.0e4 3.0e4 0.0
fix 1 1 1 1
fix 2 1 1 1
fix 7 1 1 1
fix 8 0 1 1
geomTransf Linear 1
set E 2.0e11
element elasticBeamColumn 1 1 3 0.01 $E 2.0e-4 1
element elasticBeamColumn 2 2 4 0.01 $E 2.0e-4 1
element elasticBeamColumn 3 3 4 0.012 $E 4.0e-4 1
element elasticBeamColumn 4 3 5 0.01 $E 1.5e-4 1
element elasticBeamColumn 5 4 6 0.01 $E 1.5e-4 1
element elasticBeamColumn 6 5 6 0.012 $E 3.0e-4 1
uniaxialMaterial Elastic 1 2.0e7
element zeroLength 7 7 8 -mat 1 -dir 1
# the gap closes when the roof moves 5 mm more towards the stick than it
uniaxialMaterial ElasticPPGap 2 2.0e8 -3.0e6 -0.005 0.1 damage
element zeroLength 8 6 8 -mat 2 -dir 1
timeSeries Linear 1
pattern Plain 1 1 {
    foreach n {3 4} { load $n 0.0 -1.962e5 0.0 }
    foreach n {5 6} { load $n 0.0 -1.47e5 0.0 }
}
set dt 0.01
set n 600
timeSeries Path 2 -dt $dt -values [synthetic_record $dt $n 3.0]
# every record, against which -dT is checked
recorder Node -file $out/disp.out -time -precision 16 -node 3 5 6 8 -dof 1 2 disp
# -dT as a multiple of the step (times sum to 0.0499999... below it) and not
recorder Node -file $out/disp_dT.out -time -precision 16 -dT 0.05 -node 5 6 -dof 1 disp
recorder Node -file $out/vel_dT.out -time -precision 16 -dT 0.025 -node 5 8 -dof 1 vel
recorder Node -file $out/accel_abs.out -time -precision 16 -timeSeries 2 0 -node 5 8 -dof 1 2 accel
recorder Element -file $out/force_dT.out -time -precision 16 -dT 0.03 -ele 1 8 force
# pair 3-4 lies along perpDirn's normal: OpenSees leaves it out
recorder Drift -file $out/drift.out -time -precision 16 -iNode 1 3 3 -jNode 3 5 4 -dof 1 -perpDirn 2
recorder Drift -file $out/drift_dT.out -precision 16 -dT 0.1 -rTolDt 0.001 -iNode 2 -jNode 6 -dof 1 -perpDirn 2
recorder EnvelopeNode -file $out/env_disp.out -precision 16 -node 3 5 6 8 -dof 1 2 3 disp
recorder EnvelopeNode -file $out/env_vel.out -time -precision 16 -node 5 8 -dof 1 vel
recorder EnvelopeNode -file $out/env_accel.out -time -precision 16 -timeSeries 2 0 2 -node 5 8 -dof 1 accel
recorder EnvelopeNode -file $out/env_reaction.out -time -precision 16 -dT 0.02 -node 1 2 7 -dof 1 2 3 reaction
recorder EnvelopeElement -file $out/env_local.out -time -precision 16 -ele 1 4 6 localForce
recorder EnvelopeElement -file $out/env_force.out -precision 16 -eleRange 7 8 force
recorder EnvelopeElement -file $out/env_basic.out -time -precision 16 -dT 0.05 -ele 3 8 basicForce
constraints Plain
numberer RCM
system BandGeneral
test NormDispIncr 1.0e-12 10
algorithm Newton
integrator LoadControl 0.1
analysis Static
analyze 10
loadConst -time 0.0
rayleigh 0.3 0.0 0.002 0.0
pattern UniformExcitation 2 1 -accel 2
wipeAnalysis
constraints Plain
numberer RCM
system BandGeneral
test NormDispIncr 1.0e-10 20
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
analyze $n $dt
