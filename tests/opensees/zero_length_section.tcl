# zeroLengthSection in 2D and 3D: argv the output directory and the model.
#  2d (-ndm 2 -ndf 3): three elastic columns of 3 m, 5 m apart, joined at
#     the top by elastic beams, the floor's mass at their tops; each stands
#     on a zeroLengthSection at its base (equalDOF holds the translation the
#     section leaves free): a Fiber section of Steel01 fibres with x up
#     (-orient 0 1 0 -1 0 0), an Aggregator (Elastic P, Steel01 Mz) with x
#     up and -doRayleigh 0, an Elastic section along the default x (its P
#     a horizontal spring). Gravity (LoadControl), then the synthetic record
#     along X, Rayleigh damping on the mass and the initial stiffness.
#  3d (-ndm 3 -ndf 6): two elastic columns of 3 m, 4 m apart along Y, an
#     elastic beam between their tops; bases on zeroLengthSections with x
#     up: a 3D Fiber section (-GJ) with yp along X, an Aggregator (Elastic
#     P and T, Steel01 Mz and My) with yp along Y; the record along X and
#     0.7 of it along Y.
set out [lindex $argv 0]
set model [expr {$argc > 1 ? [lindex $argv 1] : "2d"}]
source [file join [file dirname [info script]] record.tcl]
wipe
set m 2.0e4; set g 9.81; set H 3.0
if {$model eq "2d"} { model basic -ndm 2 -ndf 3 } else { model basic -ndm 3 -ndf 6 }
uniaxialMaterial Steel01 1 3.0e7 2.0e11 0.02
uniaxialMaterial Elastic 2 1.0e10
uniaxialMaterial Steel01 3 1.5e5 2.0e7 0.03
uniaxialMaterial Steel01 4 1.2e5 1.6e7 0.02
uniaxialMaterial Elastic 5 5.0e6
if {$model eq "2d"} {
    section Fiber 1 {
        patch rect 1 10 1 -0.15 -0.15 0.15 0.15
    }
    section Aggregator 2 2 P 3 Mz
    section Elastic 3 2.0e10 0.01 1.0e-3
    geomTransf Linear 1
    foreach c {0 1 2} {
        set x [expr {5.0 * $c}]
        set base [expr {10 * $c + 1}]
        node $base $x 0.0
        node [expr {$base + 1}] $x 0.0
        node [expr {$base + 2}] $x $H -mass $m $m 0.0
        fix $base 1 1 1
        element elasticBeamColumn [expr {$base + 1}] [expr {$base + 1}] [expr {$base + 2}] \
            0.02 2.0e10 1.0e-3 1
    }
    element zeroLengthSection 1 1 2 1 -orient 0 1 0 -1 0 0
    equalDOF 1 2 1
    element zeroLengthSection 11 11 12 2 -orient 0 1 0 -1 0 0 -doRayleigh 0
    equalDOF 11 12 1
    element zeroLengthSection 21 21 22 3
    equalDOF 21 22 2
    element elasticBeamColumn 100 3 13 0.02 2.0e10 2.0e-3 1
    element elasticBeamColumn 101 13 23 0.02 2.0e10 2.0e-3 1
    timeSeries Linear 1
    pattern Plain 1 1 {
        foreach n {3 13 23} { load $n 0.0 [expr {-$m * $g}] 0.0 }
    }
    set tops {3 13 23}
    set dofs {1 2 3}
    set directions {1}
} else {
    section Fiber 1 -GJ 5.0e6 {
        patch rect 1 8 8 -0.15 -0.15 0.15 0.15
    }
    section Aggregator 2 2 P 3 Mz 4 My 5 T
    geomTransf Linear 1 1 0 0
    geomTransf Linear 2 1 0 0
    foreach c {0 1} {
        set y [expr {4.0 * $c}]
        set base [expr {10 * $c + 1}]
        node $base 0.0 $y 0.0
        node [expr {$base + 1}] 0.0 $y 0.0
        node [expr {$base + 2}] 0.0 $y $H -mass $m $m $m 0.0 0.0 0.0
        fix $base 1 1 1 1 1 1
        equalDOF $base [expr {$base + 1}] 1 2
        element elasticBeamColumn [expr {$base + 1}] [expr {$base + 1}] [expr {$base + 2}] \
            0.02 2.0e10 8.0e9 2.0e-3 1.0e-3 1.2e-3 1
    }
    element zeroLengthSection 1 1 2 1 -orient 0 0 1 1 0 0
    element zeroLengthSection 11 11 12 2 -orient 0 0 1 0 1 0
    element elasticBeamColumn 100 3 13 0.02 2.0e10 8.0e9 2.0e-3 1.0e-3 2.0e-3 2
    timeSeries Linear 1
    pattern Plain 1 1 {
        foreach n {3 13} { load $n 0.0 0.0 [expr {-$m * $g}] 0.0 0.0 0.0 }
    }
    set tops {3 13}
    set dofs {1 2 3 4 5 6}
    set directions {1 2}
}
constraints Transformation
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-10 50
algorithm Newton
integrator LoadControl 0.1
analysis Static
analyze 10
loadConst -time 0.0
wipeAnalysis
rayleigh 0.3 0.0 0.002 0.0
timeSeries Path 2 -dt 0.01 -values [synthetic_record 0.01 600 1.5]
pattern UniformExcitation 2 1 -accel 2
if {$model eq "3d"} {
    timeSeries Path 3 -dt 0.01 -values [synthetic_record 0.01 600 1.05]
    pattern UniformExcitation 3 2 -accel 3
}
eval recorder Node -file $out/zls_${model}_disp.out -time -precision 16 -node $tops -dof $dofs disp
recorder Element -file $out/zls_${model}_force.out -time -precision 16 -ele 1 11 force
recorder Element -file $out/zls_${model}_basic.out -time -precision 16 -ele 1 11 basicForce
recorder Element -file $out/zls_${model}_deformation.out -time -precision 16 -ele 1 11 deformation
recorder Element -file $out/zls_${model}_section.out -time -precision 16 -ele 11 section force
recorder Element -file $out/zls_${model}_section1.out -time -precision 16 -ele 1 section 1 deformation
constraints Transformation
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-10 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
puts "zeroLengthSection $model: status [analyze 600 0.01] top [nodeDisp 3 1]"
