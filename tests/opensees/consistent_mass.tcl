# -cMass 1: the consistent mass rho L/6 [2 1; 1 2] of truss and corotTruss
# (OpenSees's Truss and CorotTruss::getMass): argv the output directory and
# the model.
#  truss (-ndm 2 -ndf 2): a yielding two-bay truss (Steel01 and Elastic
#     bars, each with its mass, -cMass 1 on three of the four, -doRayleigh 1
#     on two), nodes' own masses; its first two eigenvalues written, then
#     the synthetic record along X and 0.5 of it along Y, Rayleigh damping
#     on the mass and the committed stiffness; the supports' reactions take
#     the bars' ground-motion load M r a_g (Truss::getResistingForce
#     subtracts it).
#  corot (-ndm 3 -ndf 3): a tripod of corotTruss bars of -cMass 1 (one
#     -doRayleigh 1) under a 500 kg apex mass; the record along X and Y.
set out [lindex $argv 0]
set model [expr {$argc > 1 ? [lindex $argv 1] : "truss"}]
source [file join [file dirname [info script]] record.tcl]
wipe
if {$model eq "truss"} {
    model basic -ndm 2 -ndf 2
    node 1 0.0 0.0
    node 2 4.0 0.0
    node 3 2.0 3.0 -mass 5.0 5.0
    node 4 6.0 3.0 -mass 3.0 3.0
    fix 1 1 1
    fix 2 1 1
    uniaxialMaterial Steel01 1 2.0e5 2.0e8 0.02
    uniaxialMaterial Elastic 2 2.0e8
    element truss 1 1 3 0.001 1 -rho 8.0 -cMass 1
    element truss 2 2 3 0.001 1 -rho 8.0 -cMass 1 -doRayleigh 1
    element truss 3 3 4 0.001 2 -rho 15.0
    element truss 4 2 4 0.001 2 -rho 15.0 -doRayleigh 1 -cMass 1
    set nodes {3 4}
    set supports {1 2}
} else {
    model basic -ndm 3 -ndf 3
    set pi 3.14159265358979
    foreach i {1 2 3} {
        set a [expr {2.0 * $pi * ($i - 1) / 3.0 + 0.3}]
        node $i [expr {1.5 * cos($a)}] [expr {1.5 * sin($a)}] 0.0
        fix $i 1 1 1
    }
    node 4 0.1 -0.05 2.0 -mass 500.0 500.0 500.0
    uniaxialMaterial Steel01 1 2.5e8 2.0e11 0.02
    element corotTruss 1 1 4 2.0e-5 1 -rho 150.0 -cMass 1
    element corotTruss 2 2 4 2.0e-5 1 -rho 150.0 -cMass 1 -doRayleigh 1
    element corotTruss 3 3 4 2.5e-5 1 -rho 180.0 -cMass 1
    set nodes {4}
    set supports {1 2}
}
set lambda [eigen 2]
set file [open $out/cmass_${model}_eigen.out w]
puts $file "0.0 $lambda"
close $file
rayleigh 0.3 0.0 0.0 0.001
timeSeries Path 2 -dt 0.01 -values [synthetic_record 0.01 600 4.0]
pattern UniformExcitation 2 1 -accel 2
timeSeries Path 3 -dt 0.01 -values [synthetic_record 0.01 600 2.0]
pattern UniformExcitation 3 2 -accel 3
eval recorder Node -file $out/cmass_${model}_disp.out -time -precision 16 -node $nodes -dof 1 2 disp
eval recorder Node -file $out/cmass_${model}_reaction.out -time -precision 16 -node $supports -dof 1 2 reaction
recorder Element -file $out/cmass_${model}_force.out -time -precision 16 -ele 1 2 axialForce
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-11 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
puts "consistent mass $model: status [analyze 600 0.01] [nodeDisp [lindex $nodes end] 1]"
