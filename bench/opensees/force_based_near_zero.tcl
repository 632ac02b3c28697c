# One force-based RC beam (0.3 x 0.5 m, 5 m, kN and m; Concrete02 with
# tension, Steel02 bars 4 top, 3 bottom; Lobatto 4), node I fixed, node J's
# (uy, rz) prescribed along one direction (ux free: N = 0): out past cracking
# and yield in 10 steps, back in 9, then to 1e-16 of the direction and two
# steps of 1e-7 relative from there: the member back near v = 0 with
# residual section forces, as in the unit test
# force_based_element_takes_tiny_steps_near_zero_after_cracking.
#   OpenSees force_based_near_zero.tcl   (writes basic.out)
# OpenSees 3.8 (absolute |dW| < 1e-12 kN m) converges at every step: status 0,
# peak basic moment 152.59 kN m, at the near-zero state q = (-1.5e-15,
# -1.2178, -2.9418) (kN, kN m), unchanged by the two tiny steps.
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0
node 2 5.0 0.0
fix 1 1 1 1
uniaxialMaterial Concrete02 1 -30.0e3 -0.002 -6.0e3 -0.005 0.1 4.2e3 2.1e6
uniaxialMaterial Steel02 3 450.0e3 2.0e8 0.01 18.0 0.925 0.15
section Fiber 1 {
    patch rect 1 8 2 -0.25 -0.15 0.25 0.15
    layer straight 3 4 2.54e-4 0.196 -0.106 0.196 0.106
    layer straight 3 3 2.54e-4 -0.196 -0.106 -0.196 0.106
}
geomTransf Linear 1
beamIntegration Lobatto 1 1 4
element forceBeamColumn 1 1 2 1 1
recorder Element -file basic.out -time -precision 16 -ele 1 basicForce
timeSeries Linear 1
pattern Plain 1 1 {

    sp 2 2 [expr {0.4*3e-3}]
    sp 2 3 [expr {1.3*3e-3}]
}
constraints Transformation
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-12 50
algorithm Newton
analysis Static
set status 0
integrator LoadControl 0.1
set status [expr {$status + [analyze 10]}]
integrator LoadControl -0.1
set status [expr {$status + [analyze 9]}]
set now [getTime]
foreach target {1e-16 1.0000001e-16 1.0000002e-16} {
    integrator LoadControl [expr {$target - [getTime]}]
    set status [expr {$status + [analyze 1]}]
}
puts "status $status time [getTime] basic [eleResponse 1 basicForce]"
