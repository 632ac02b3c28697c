# A two-storey, one-bay (5 m x 4 m) RC frame in space of fibre members, the
# OpenSees twin of fibre-frame-3d.prm (poundfe run): forceBeamColumns (Lobatto
# 5 points) on fibre sections with patches and layers (Concrete02 and
# Steel02; columns 0.4 x 0.4 m with bars on all four faces, PDelta, vecxz
# along X; beams 0.3 x 0.5 m, Linear, their depth vertical), rigid floors
# (rigidDiaphragm to a master at the plan centre with the floor mass and its
# polar moment; each joint a quarter of the floor mass on uz), gravity
# (the joints' weight) by LoadControl in 10 steps held by loadConst, then
# 4 s of record_x.txt along X and record_y.txt along Y, Newmark average
# acceleration at 0.01 s, Newton with NormDispIncr 1e-12, Rayleigh damping
# a0 M + a1 K_initial.
#   OpenSees frame.tcl OUTPUT_DIR
set out [lindex $argv 0]
set here [file dirname [info script]]
wipe
model basic -ndm 3 -ndf 6
set Lx 5.0; set Ly 4.0; set H 3.0; set m 40000.0; set g 9.81
set J [expr {$m*($Lx*$Lx + $Ly*$Ly)/12.0}]
# joints: level k, corner c at (x, y): tag 10 k + c
foreach k {0 1 2} {
    set c 1
    foreach {x y} [list 0.0 0.0 $Lx 0.0 0.0 $Ly $Lx $Ly] {
        node [expr {10*$k + $c}] $x $y [expr {$k*$H}]
        incr c
    }
}
foreach c {1 2 3 4} { fix $c 1 1 1 1 1 1 }
# masters at the mass centre
foreach k {1 2} {
    set master [expr {100 + $k}]
    node $master [expr {$Lx/2}] [expr {$Ly/2}] [expr {$k*$H}] -mass $m $m 0.0 0.0 0.0 $J
    fix $master 0 0 1 1 1 0
    foreach c {1 2 3 4} { mass [expr {10*$k + $c}] 0.0 0.0 [expr {$m/4}] 0.0 0.0 0.0 }
    rigidDiaphragm 3 $master [expr {10*$k + 1}] [expr {10*$k + 2}] [expr {10*$k + 3}] [expr {10*$k + 4}]
}
uniaxialMaterial Concrete02 1 -30e6 -0.002 -6e6 -0.006 0.1 3e6 1.5e9
uniaxialMaterial Steel02 2 420e6 200e9 0.01 20 0.925 0.15
section Fiber 1 -GJ 2.7e7 {
    patch rect 1 8 8 -0.2 -0.2 0.2 0.2
    layer straight 2 3 3.14e-4 0.16 -0.16 0.16 0.16
    layer straight 2 3 3.14e-4 -0.16 -0.16 -0.16 0.16
    fiber 0.0 -0.16 3.14e-4 2
    fiber 0.0 0.16 3.14e-4 2
}
section Fiber 2 -GJ 2.2e7 {
    patch rect 1 10 4 -0.25 -0.15 0.25 0.15
    layer straight 2 3 2.01e-4 0.21 -0.11 0.21 0.11
    layer straight 2 3 2.01e-4 -0.21 -0.11 -0.21 0.11
}
geomTransf PDelta 1 1 0 0
geomTransf Linear 2 0 -1 0
geomTransf Linear 3 1 0 0
beamIntegration Lobatto 1 1 5
beamIntegration Lobatto 2 2 5
set e 1
foreach k {1 2} {
    foreach c {1 2 3 4} {
        element forceBeamColumn $e [expr {10*($k - 1) + $c}] [expr {10*$k + $c}] 1 1
        incr e
    }
    # beams along X (corners 1-2, 3-4) and along Y (1-3, 2-4)
    element forceBeamColumn $e [expr {10*$k + 1}] [expr {10*$k + 2}] 2 2; incr e
    element forceBeamColumn $e [expr {10*$k + 3}] [expr {10*$k + 4}] 2 2; incr e
    element forceBeamColumn $e [expr {10*$k + 1}] [expr {10*$k + 3}] 3 2; incr e
    element forceBeamColumn $e [expr {10*$k + 2}] [expr {10*$k + 4}] 3 2; incr e
}
recorder Node -file $out/roof.out -time -precision 12 -node 102 -dof 1 2 6 disp
recorder Node -file $out/base.out -time -precision 12 -node 1 2 3 4 -dof 1 2 3 reaction
timeSeries Linear 1
pattern Plain 1 1 {
    foreach k {1 2} {
        foreach c {1 2 3 4} { load [expr {10*$k + $c}] 0.0 0.0 [expr {-$m/4*$g}] 0.0 0.0 0.0 }
    }
}
constraints Transformation
numberer Plain
system UmfPack
test NormDispIncr 1.0e-12 50
algorithm Newton
integrator LoadControl 0.1
analysis Static
analyze 10
loadConst -time 0.0
wipeAnalysis
set a0 0.4; set a1 0.002
rayleigh $a0 0.0 $a1 0.0
timeSeries Path 2 -dt 0.01 -filePath [file join $here record_x.txt]
timeSeries Path 3 -dt 0.01 -filePath [file join $here record_y.txt]
pattern UniformExcitation 2 1 -accel 2
pattern UniformExcitation 3 2 -accel 3
constraints Transformation
numberer Plain
system UmfPack
test NormDispIncr 1.0e-12 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
set status [analyze 399 0.01]
puts "frame 3d: status $status roof [nodeDisp 102 1] [nodeDisp 102 2]"
