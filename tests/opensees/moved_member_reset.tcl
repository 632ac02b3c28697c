# `reset` after a forceBeamColumn was made on nodes that have moved: two
# elastic columns (2d: Corotational; 3d: Linear) carry a tip load to a
# moved state, `loadConst`, then a fibre forceBeamColumn (Steel01 fibres,
# Lobatto 5, on the transformation argv names) joins the moved tip to a new
# pinned node and a second static stage follows; `reset` and the same stage
# again. OpenSees's ForceBeamColumn2d/3d::revertToStart sets initialFlag = 0,
# so the domain's update after the reset, at the nodes' zero displacements,
# is the member's linear first one (q = F_0^-1 v with the sections at zero,
# v measured from the displacements when it was made): Newton then comes
# back to the state before the reset. argv: the output directory, 2d or 3d,
# Linear, PDelta or Corotational (2d only).
set out [lindex $argv 0]
set variant [lindex $argv 1]
set transformation [lindex $argv 2]
wipe
if {$variant eq "2d"} {
    model basic -ndm 2 -ndf 3
    uniaxialMaterial Steel01 1 2.5e8 2.0e11 0.01
    node 1 0.0 0.0
    node 2 0.3 3.1
    node 3 0.1 6.2
    fix 1 1 1 1
    geomTransf Corotational 9
    element elasticBeamColumn 1 1 2 0.01 2.0e11 1.2e-5 9
    element elasticBeamColumn 2 2 3 0.01 2.0e11 1.2e-5 9
    set first {1.0e3 -5.0e2 1.55e4}
    set second {-3.0e4 2.0e4 -1.0e5}
    set apex {4.3 4.7}
    set pin {1 1 0}
    set orientation {}
    set dofs {1 2 3}
} else {
    model basic -ndm 3 -ndf 6
    uniaxialMaterial Steel01 1 2.5e8 2.0e11 0.01
    node 1 0.0 0.0 0.0
    node 2 0.2 -0.1 3.1
    node 3 0.1 0.3 6.2
    fix 1 1 1 1 1 1 1
    geomTransf Linear 9 1 0 0
    element elasticBeamColumn 1 1 2 0.01 2.0e11 8.0e10 2.0e-5 1.2e-5 1.5e-5 9
    element elasticBeamColumn 2 2 3 0.01 2.0e11 8.0e10 2.0e-5 1.2e-5 1.5e-5 9
    set first {2.0e4 -1.5e4 -1.0e4 3.0e4 -2.0e4 4.0e4}
    set second {-3.0e4 2.0e4 1.0e4 -1.0e4 2.0e4 -3.0e4}
    set apex {4.3 -2.1 4.7}
    set pin {1 1 1 0 0 0}
    set orientation {0.3 0.2 1.0}
    set dofs {1 2 3 4 5 6}
}
timeSeries Linear 1
eval pattern Plain 1 1 \{ load 3 $first \}
constraints Plain
numberer RCM
system BandGeneral
test NormDispIncr 1.0e-11 50
algorithm Newton
integrator LoadControl 0.05
analysis Static
analyze 20
loadConst -time 0.0
eval geomTransf $transformation 5 $orientation
eval node 4 $apex
eval fix 4 $pin
if {$variant eq "2d"} {
    section Fiber 1 { patch rect 1 10 1 -0.1 -0.05 0.1 0.05 }
} else {
    section Fiber 1 -GJ 4.0e6 { patch rect 1 10 6 -0.1 -0.05 0.1 0.05 }
}
beamIntegration Lobatto 1 1 5
element forceBeamColumn 3 3 4 5 1
recorder Node -file $out/disp.out -time -precision 16 -node 2 3 4 -dof {*}$dofs disp
recorder Element -file $out/force.out -time -precision 16 -ele 3 force
recorder Element -file $out/basic.out -time -precision 16 -ele 3 basicDeformation
timeSeries Linear 2
eval pattern Plain 2 2 \{ load 3 $second \}
integrator LoadControl 0.1
analyze 10
reset
analyze 10
