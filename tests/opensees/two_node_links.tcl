# twoNodeLink in 2D and 3D: argv the output directory and the model.
#  2d (-ndm 2 -ndf 3): two elastic cantilevers of 3 m, 4 m apart, masses
#     at the tops; the second stands on a 0.5 m twoNodeLink bearing (axial
#     Elastic, shear Steel01, rotation Elastic, -shearDist 0.3, -pDelta 0.2
#     0.3); a horizontal twoNodeLink between the tops carries an
#     ElasticPPGap of 10 mm along its axis. Gravity (LoadControl), then the
#     synthetic record along X.
#  3d (-ndm 3 -ndf 6): two sticks of twoNodeLinks (six materials each:
#     axial, two yielding shears, torsion, two bending; -orient yp,
#     -shearDist, -pDelta; the second Rayleigh-damped by -doRayleigh), 2.5 m
#     apart along a diagonal, a twoNodeLink gap between the tops along that
#     diagonal (-orient x and yp), gravity, then the record along X and 0.7
#     of it along Y.
# Rayleigh: alphaM on the masses, betaKcomm on the beams and -doRayleigh links.
set out [lindex $argv 0]
set case [lindex $argv 1]
source [file join [file dirname [info script]] record.tcl]
set pi 3.14159265358979
set m 2.0e4
set dt 0.005
set n 1200
wipe
if {$case eq "2d"} {
    model basic -ndm 2 -ndf 3
    node 1 0.0 0.0
    node 2 0.0 3.0 -mass $m $m 0.0
    node 5 4.0 0.0
    node 3 4.0 0.5
    node 4 4.0 3.5 -mass $m $m 0.0
    fix 1 1 1 1
    fix 5 1 1 1
    geomTransf Linear 1
    element elasticBeamColumn 1 1 2 0.04 2.0e11 8.0e-5 1
    element elasticBeamColumn 2 3 4 0.04 2.0e11 4.0e-5 1
    uniaxialMaterial Elastic 10 5.0e9
    uniaxialMaterial Steel01 11 6.0e4 4.0e6 0.05
    uniaxialMaterial Elastic 12 1.0e7
    element twoNodeLink 3 5 3 -mat 10 11 12 -dir 1 2 3 -shearDist 0.3 -pDelta 0.2 0.3
    uniaxialMaterial ElasticPPGap 20 2.0e9 -4.0e6 -0.01 0.1 damage
    element twoNodeLink 4 2 4 -mat 20 -dir 1
    set gap 4
    set bearing 3
    set top {2 4}
    set dofs {1 2 3}
    pattern Plain 1 Linear { load 2 0.0 [expr {-$m * 9.81}] 0.0; load 4 0.0 [expr {-$m * 9.81}] 0.0 }
} elseif {$case eq "3d"} {
    model basic -ndm 3 -ndf 6
    node 1 0.0 0.0 0.0
    node 2 0.0 0.0 3.0 -mass $m $m $m 1.0e3 1.0e3 2.0e3
    node 3 1.5 2.0 0.0
    node 4 1.5 2.0 3.0 -mass $m $m $m 1.0e3 1.0e3 2.0e3
    fix 1 1 1 1 1 1 1
    fix 3 1 1 1 1 1 1
    uniaxialMaterial Elastic 10 5.0e9
    uniaxialMaterial Steel01 11 8.0e4 2.0e6 0.05
    uniaxialMaterial Steel01 12 6.0e4 1.0e6 0.02
    uniaxialMaterial Elastic 13 1.0e7
    uniaxialMaterial Elastic 14 4.0e7
    uniaxialMaterial Elastic 15 3.0e7
    # -orient's yp alone last: OpenSees 3.8 reads six values after -orient
    # whenever six words or more follow it
    element twoNodeLink 1 1 2 -mat 10 11 12 13 14 15 -dir 1 2 3 4 5 6 \
        -shearDist 0.4 0.6 -pDelta 0.1 0.2 0.3 0.1 -orient 1.0 0.0 0.0
    element twoNodeLink 2 3 4 -mat 10 12 11 13 15 14 -dir 1 2 3 4 5 6 \
        -pDelta 0.5 0.5 0.0 0.0 -doRayleigh -orient 0.0 1.0 0.0
    uniaxialMaterial ElasticPPGap 20 2.0e9 -4.0e6 -0.01 0.1 damage
    # the gap's axis along the diagonal, given as -orient's x and yp
    element twoNodeLink 3 2 4 -mat 20 -dir 1 -orient 0.6 0.8 0.0 -0.8 0.6 0.0
    set gap 3
    set bearing 1
    set top {2 4}
    set dofs {1 2 3 4 5 6}
    pattern Plain 1 Linear { load 2 0.0 0.0 [expr {-$m * 9.81}] 0.0 0.0 0.0
                             load 4 0.0 0.0 [expr {-$m * 9.81}] 0.0 0.0 0.0 }
} else {
    error "two_node_links.tcl: no case '$case'"
}
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-10 50
algorithm Newton
integrator LoadControl 0.1
analysis Static
analyze 10
loadConst -time 0.0
wipeAnalysis
rayleigh 0.2 0.0 0.0 0.002
timeSeries Path 2 -dt $dt -values [synthetic_record $dt $n 1.2]
pattern UniformExcitation 2 1 -accel 2
if {$case eq "3d"} {
    timeSeries Path 3 -dt $dt -values [synthetic_record $dt $n 0.84]
    pattern UniformExcitation 3 2 -accel 3
}
recorder Node -file $out/links_${case}_disp.out -time -precision 16 -node {*}$top -dof {*}$dofs disp
recorder Element -file $out/links_${case}_gap.out -time -precision 16 -ele $gap $bearing basicForce
recorder Element -file $out/links_${case}_local.out -time -precision 16 -ele $bearing localForce
recorder Element -file $out/links_${case}_force.out -time -precision 16 -ele 1 2 force
recorder Element -file $out/links_${case}_deformation.out -time -precision 16 -ele $bearing \
    basicDeformation
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-10 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
set status [analyze $n $dt]
puts "two_node_links $case: status $status time [getTime]"
