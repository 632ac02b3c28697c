# Members on geomTransf Corotational in space (OpenSees's CorotCrdTransf3d).
# argv: the output directory, then the variant:
#   circle   a cantilever of 16 elasticBeamColumns along (1, 2, 2)/3 under
#            a tip moment about (2, 1, -2)/3 (its local z: vecxz), raised
#            to 2 pi EI/L in 40 steps of LoadControl: it rolls into a circle
#            in a plane that holds no global axis (Iy = 3 Iz: bending about
#            the wrong axis would not close it);
#   column ELEMENT  a cantilever column (4 m, four members of ELEMENT:
#            elasticBeamColumn, forceBeamColumn or dispBeamColumn on an
#            elastic section, vecxz (1, 0.3, 0)) under an axial load of
#            0.3 of its Euler load, then a lateral load along X and 0.6 of
#            it along Y and a torque, in 30 steps of LoadControl: the top
#            moves by about a third of the height;
#   frame    a two-storey frame of forceBeamColumn columns on a fibre
#            section (Steel01, Corotational, vecxz along X) and Linear
#            elasticBeamColumn beams, the floors' mass at the joints, gravity
#            then 3 s of the synthetic record along X and 0.7 of it along Y,
#            Newmark average acceleration at 0.01 s, Rayleigh damping on the
#            mass and the committed stiffness;
#   frame initial  the same with columns of each kind (forceBeamColumn,
#            dispBeamColumn, elasticBeamColumn) and Rayleigh damping on the
#            initial stiffness: OpenSees takes it through CorotCrdTransf3d's
#            current T, at each step for the displacement-based and elastic
#            members, at the first step for the force-based ones;
#   modes ELEMENT  a skew cantilever of four members of ELEMENT with -mass
#            and a tip mass, and a second (elastic) post, under a tip load
#            that bends it: `eigen -fullGenLapack 3` before the load and
#            after it, when the members' tangent is no longer symmetric;
#            `modes ELEMENT modal`: then modalDamping 0.05 on those modes
#            and 1.5 s of the synthetic record (FullGeneral, in which
#            OpenSees keeps the whole modal matrix in the tangent: the
#            triads follow Newton's iterates).
set out [lindex $argv 0]
set variant [lindex $argv 1]
source [file join [file dirname [info script]] record.tcl]
wipe
model basic -ndm 3 -ndf 6
if {$variant eq "circle"} {
    set n 16; set L 4.0; set E 2.0e8; set A 0.01; set Iz 1.0e-4; set G 8.0e7; set J 2.0e-4
    set pi 3.14159265358979
    set d {0.333333333333333 0.666666666666667 0.666666666666667}
    for {set i 0} {$i <= $n} {incr i} {
        set s [expr {$L * $i / $n}]
        node [expr {$i + 1}] [expr {$s / 3.0}] [expr {2.0 * $s / 3.0}] [expr {2.0 * $s / 3.0}]
    }
    fix 1 1 1 1 1 1 1
    geomTransf Corotational 1 2.0 1.0 -2.0
    for {set i 1} {$i <= $n} {incr i} {
        element elasticBeamColumn $i $i [expr {$i + 1}] $A $E $G $J [expr {3 * $Iz}] $Iz 1
    }
    set M [expr {2 * $pi * $E * $Iz / $L}]
    recorder Node -file $out/circle_nodes.out -time -precision 16 -nodeRange 1 [expr {$n + 1}] -dof 1 2 3 disp
    recorder Node -file $out/circle_tip_rotation.out -time -precision 16 -node [expr {$n + 1}] -dof 4 5 6 disp
    timeSeries Linear 1
    pattern Plain 1 1 {
        load [expr {$n + 1}] 0.0 0.0 0.0 [expr {2.0 * $M / 3}] [expr {$M / 3}] [expr {-2.0 * $M / 3}]
    }
    constraints Plain
    numberer Plain
    system UmfPack
    test NormDispIncr 1.0e-12 50
    algorithm Newton
    integrator LoadControl 0.025
    analysis Static
    set status [analyze 40]
    puts "corotational_3d circle: status $status"
} elseif {$variant eq "column"} {
    set element [lindex $argv 2]
    set H 4.0; set E 2.0e8; set A 0.01; set Iz 1.2e-4; set Iy 0.8e-4; set G 8.0e7; set J 1.5e-4
    set pi 3.14159265358979
    set Pe [expr {$pi * $pi * $E * $Iy / (4 * $H * $H)}]
    for {set i 0} {$i <= 4} {incr i} { node [expr {$i + 1}] 0.0 0.0 [expr {$H * $i / 4}] }
    fix 1 1 1 1 1 1 1
    geomTransf Corotational 1 1.0 0.3 0.0
    section Elastic 1 $E $A $Iz $Iy $G $J
    beamIntegration Lobatto 1 1 4
    beamIntegration Legendre 2 1 3
    for {set i 1} {$i <= 4} {incr i} {
        switch $element {
            elasticBeamColumn { element elasticBeamColumn $i $i [expr {$i + 1}] $A $E $G $J $Iy $Iz 1 }
            forceBeamColumn { element forceBeamColumn $i $i [expr {$i + 1}] 1 1 }
            dispBeamColumn { element dispBeamColumn $i $i [expr {$i + 1}] 1 2 }
        }
    }
    recorder Node -file $out/column_top.out -time -precision 16 -node 5 -dof 1 2 3 4 5 6 disp
    recorder Node -file $out/column_base.out -time -precision 16 -node 1 -dof 1 2 3 4 5 6 reaction
    recorder Element -file $out/column_force.out -time -precision 16 -ele 1 4 force
    recorder Element -file $out/column_basic.out -time -precision 16 -ele 1 4 basicForce
    timeSeries Linear 1
    pattern Plain 1 1 { load 5 0.0 0.0 [expr {-0.3 * $Pe}] 0.0 0.0 0.0 }
    constraints Plain
    numberer Plain
    system UmfPack
    test NormDispIncr 1.0e-12 50
    algorithm Newton
    integrator LoadControl 0.25
    analysis Static
    analyze 4
    loadConst -time 0.0
    set F [expr {0.9 * $E * $Iy / ($H * $H)}]
    pattern Plain 2 1 { load 5 $F [expr {0.6 * $F}] 0.0 0.0 0.0 [expr {0.05 * $F * $H}] }
    integrator LoadControl [expr {1.0 / 30}]
    set status [analyze 30]
    puts "corotational_3d column $element: status $status top [nodeDisp 5 1] [nodeDisp 5 2] [nodeDisp 5 3]"
} elseif {$variant eq "modes"} {
    set element [lindex $argv 2]
    for {set i 0} {$i <= 4} {incr i} { node [expr {$i + 1}] [expr {0.3 * $i}] [expr {-0.2 * $i}] [expr {1.0 * $i}] }
    node 10 2.0 0.0 0.0
    node 11 2.0 -0.5 3.0
    fix 1 1 1 1 1 1 1
    fix 10 1 1 1 1 1 1
    section Elastic 1 2.0e8 0.01 8.0e-5 5.0e-5 8.0e7 6.0e-5
    geomTransf Corotational 1 0.2 1.0 0.3
    beamIntegration Lobatto 1 1 4
    beamIntegration Legendre 2 1 2
    for {set i 1} {$i <= 4} {incr i} {
        switch $element {
            elasticBeamColumn { element elasticBeamColumn $i $i [expr {$i + 1}] 0.01 2.0e8 8.0e7 6.0e-5 5.0e-5 8.0e-5 1 -mass 40.0 }
            forceBeamColumn { element forceBeamColumn $i $i [expr {$i + 1}] 1 1 -mass 40.0 }
            dispBeamColumn { element dispBeamColumn $i $i [expr {$i + 1}] 1 2 -mass 40.0 }
        }
    }
    element elasticBeamColumn 9 10 11 0.01 2.0e8 8.0e7 6.0e-5 5.0e-5 8.0e-5 1 -mass 30.0
    mass 5 200.0 200.0 200.0 2.0 2.0 2.0
    set file [open $out/modes_eigen.out w]
    puts $file "0.0 [eigen -fullGenLapack 3]"
    timeSeries Linear 1
    pattern Plain 1 1 { load 5 0.0 0.0 -2000.0 0.0 0.0 0.0 }
    constraints Plain
    numberer Plain
    system UmfPack
    test NormDispIncr 1.0e-11 40
    algorithm Newton
    integrator LoadControl 0.25
    analysis Static
    set status [analyze 4]
    puts $file "1.0 [eigen -fullGenLapack 3]"
    close $file
    if {[lindex $argv 3] eq "modal"} {
        modalDamping 0.05
        recorder Node -file $out/modes_tip.out -time -precision 16 -node 5 11 -dof 1 2 3 4 5 6 disp
        timeSeries Path 2 -dt 0.01 -values [synthetic_record 0.01 150 3.0]
        pattern UniformExcitation 2 1 -accel 2
        system FullGeneral
        test NormDispIncr 1.0e-11 60
        integrator Newmark 0.5 0.25
        analysis Transient
        set status [analyze 150 0.01]
    }
    puts "corotational_3d modes $element: status $status tip [nodeDisp 5 1] [nodeDisp 5 2] [nodeDisp 5 3]"
} elseif {$variant eq "frame"} {
    set Lx 5.0; set Ly 4.0; set H 3.0; set m 16000.0; set g 9.81
    set c 1
    foreach {x y} [list 0.0 0.0 $Lx 0.0 0.0 $Ly $Lx $Ly] {
        node $c $x $y 0.0
        fix $c 1 1 1 1 1 1
        node [expr {10 + $c}] $x $y $H -mass $m $m $m 0.0 0.0 0.0
        node [expr {20 + $c}] $x $y [expr {2 * $H}] -mass $m $m $m 0.0 0.0 0.0
        incr c
    }
    uniaxialMaterial Steel01 1 350.0e6 200.0e9 0.02
    section Fiber 1 -GJ 1.0e6 {
        patch rect 1 6 6 -0.09 -0.09 0.09 0.09
        patch rect 1 4 4 -0.08 -0.08 0.08 0.08
    }
    geomTransf Corotational 1 1.0 0.0 0.0
    geomTransf Linear 2 0.0 0.0 1.0
    beamIntegration Lobatto 1 1 4
    set damping [lindex $argv 2]
    set kinds {force force force force force force force force}
    if {$damping eq "initial"} {
        set kinds {force disp elastic force disp elastic force disp}
        beamIntegration Legendre 3 1 3
    }
    set e 1
    foreach {i j} {1 11 2 12 3 13 4 14 11 21 12 22 13 23 14 24} {
        switch [lindex $kinds [expr {$e - 1}]] {
            force { element forceBeamColumn $e $i $j 1 1 }
            disp { element dispBeamColumn $e $i $j 1 3 }
            elastic { element elasticBeamColumn $e $i $j 6.8e-3 2.0e11 8.0e10 1.25e-5 3.3e-5 3.3e-5 1 }
        }
        incr e
    }
    foreach {i j} {11 12 13 14 11 13 12 14 21 22 23 24 21 23 22 24} {
        element elasticBeamColumn $e $i $j 0.02 2.0e11 8.0e10 2.0e-4 2.0e-4 3.0e-4 2
        incr e
    }
    recorder Node -file $out/frame_roof.out -time -precision 16 -node 21 24 -dof 1 2 3 4 5 6 disp
    recorder Node -file $out/frame_base.out -time -precision 16 -node 1 4 -dof 1 2 3 reaction
    recorder Element -file $out/frame_column.out -time -precision 16 -ele 1 localForce
    recorder Element -file $out/frame_section.out -time -precision 16 -ele 5 section 1 deformation
    timeSeries Linear 1
    pattern Plain 1 1 {
        foreach c {11 12 13 14 21 22 23 24} { load $c 0.0 0.0 [expr {-$m * $g}] 0.0 0.0 0.0 }
    }
    constraints Plain
    numberer Plain
    system UmfPack
    test NormDispIncr 1.0e-10 50
    algorithm Newton
    integrator LoadControl 0.1
    analysis Static
    analyze 10
    loadConst -time 0.0
    wipeAnalysis
    if {$damping eq "initial"} {
        rayleigh 0.3 0.0 0.003 0.0
        recorder Element -file $out/frame_members.out -time -precision 16 -ele 2 3 6 localForce
    } else {
        rayleigh 0.3 0.0 0.0 0.003
    }
    set dt 0.01
    set n 300
    timeSeries Path 2 -dt $dt -values [synthetic_record $dt $n 6.0]
    timeSeries Path 3 -dt $dt -values [synthetic_record $dt $n 4.2]
    pattern UniformExcitation 2 1 -accel 2
    pattern UniformExcitation 3 2 -accel 3
    constraints Plain
    numberer Plain
    system UmfPack
    test NormDispIncr 1.0e-10 50
    algorithm Newton
    integrator Newmark 0.5 0.25
    analysis Transient
    set status [analyze $n $dt]
    puts "corotational_3d frame: status $status time [getTime] roof [nodeDisp 21 1] [nodeDisp 21 2]"
}
