# corotTruss (OpenSees's CorotTruss): argv the output directory and the model.
#  2d (-ndm 2 -ndf 2): a shallow two-bar truss (span 4 m, rise 0.2 m,
#     Elastic bars) whose apex DisplacementControl pushes down 0.5 m, past
#     its snap-through to the mirrored shape: the bars' force goes through
#     zero, a compression peak and a tension branch (large rotations), and
#     a third, stiffer bar (Steel01) hangs the apex from a support 1 m
#     above it.
#  3d (-ndm 3 -ndf 6): a tripod of three Steel01 bars (-rho lumped, one
#     -doRayleigh 1, -cMass 0) carrying a 2 t mass at its apex 2 m above
#     the supports; gravity (LoadControl), then the synthetic record along
#     X and 0.6 of it along Y, Rayleigh damping on the mass and the initial
#     stiffness.
set out [lindex $argv 0]
set model [expr {$argc > 1 ? [lindex $argv 1] : "2d"}]
source [file join [file dirname [info script]] record.tcl]
wipe
if {$model eq "2d"} {
    model basic -ndm 2 -ndf 2
    node 1 0.0 0.0
    node 2 4.0 0.0
    node 3 2.0 0.2
    node 4 2.0 1.2
    fix 1 1 1
    fix 2 1 1
    fix 4 1 1
    uniaxialMaterial Elastic 1 2.0e11
    uniaxialMaterial Steel01 2 2.5e8 2.0e11 0.01
    element corotTruss 1 1 3 1.0e-3 1
    element corotTruss 2 3 2 1.0e-3 1
    element CorotTruss 3 4 3 2.0e-5 2
    recorder Node -file $out/corot_2d_disp.out -time -precision 16 -node 3 -dof 1 2 disp
    recorder Node -file $out/corot_2d_reaction.out -time -precision 16 -node 1 4 -dof 1 2 reaction
    recorder Element -file $out/corot_2d_force.out -time -precision 16 -ele 1 3 force
    recorder Element -file $out/corot_2d_axial.out -time -precision 16 -ele 1 2 3 axialForce
    recorder Element -file $out/corot_2d_deformation.out -time -precision 16 -ele 1 3 deformation
    timeSeries Linear 1
    pattern Plain 1 1 { load 3 0.0 -1.0 }
    constraints Plain
    numberer Plain
    system BandGeneral
    test NormDispIncr 1.0e-10 50
    algorithm Newton
    integrator DisplacementControl 3 2 -0.005
    analysis Static
    puts "corotTruss 2d: status [analyze 100] apex [nodeDisp 3 2]"
} else {
    model basic -ndm 3 -ndf 6
    set pi 3.14159265358979
    foreach i {1 2 3} {
        set a [expr {2.0 * $pi * ($i - 1) / 3.0 + 0.3}]
        node $i [expr {1.5 * cos($a)}] [expr {1.5 * sin($a)}] 0.0
        fix $i 1 1 1 1 1 1
    }
    node 4 0.1 -0.05 2.0 -mass 2000.0 2000.0 2000.0 0.0 0.0 0.0
    fix 4 0 0 0 1 1 1
    uniaxialMaterial Steel01 1 2.5e8 2.0e11 0.02
    element corotTruss 1 1 4 2.0e-4 1 -rho 20.0
    element corotTruss 2 2 4 2.0e-4 1 -rho 20.0 -doRayleigh 1
    element corotTruss 3 3 4 2.5e-4 1 -rho 25.0 -cMass 0
    timeSeries Linear 1
    pattern Plain 1 1 { load 4 0.0 0.0 [expr {-2000.0 * 9.81}] 0.0 0.0 0.0 }
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
    rayleigh 0.4 0.0 0.001 0.0
    timeSeries Path 2 -dt 0.01 -values [synthetic_record 0.01 600 6.0]
    pattern UniformExcitation 2 1 -accel 2
    timeSeries Path 3 -dt 0.01 -values [synthetic_record 0.01 600 3.6]
    pattern UniformExcitation 3 2 -accel 3
    recorder Node -file $out/corot_3d_disp.out -time -precision 16 -node 4 -dof 1 2 3 disp
    recorder Node -file $out/corot_3d_reaction.out -time -precision 16 -node 1 2 -dof 1 2 3 reaction
    recorder Element -file $out/corot_3d_force.out -time -precision 16 -ele 1 2 force
    recorder Element -file $out/corot_3d_axial.out -time -precision 16 -ele 1 2 3 axialForce
    recorder Element -file $out/corot_3d_deformation.out -time -precision 16 -ele 3 deformation
    constraints Plain
    numberer Plain
    system BandGeneral
    test NormDispIncr 1.0e-10 50
    algorithm Newton
    integrator Newmark 0.5 0.25
    analysis Transient
    puts "corotTruss 3d: status [analyze 600 0.01] apex [nodeDisp 4 1]"
}
