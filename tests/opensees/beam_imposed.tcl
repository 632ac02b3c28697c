# One force-based RC beam (0.3 x 0.5 m, 5 m, kN and m; Concrete02 with
# tension, Steel02 bars; Lobatto 4), node I fixed, node J's (uy, rz)
# imposed by sp commands of a Plain pattern (constraints Transformation),
# ux free under an axial load in the same pattern: out past cracking and
# yield in 10 load steps, back in 9, as
# bench/opensees/force_based_near_zero.tcl (whose N = 0 leaves nothing to
# compare in N and the axial reaction). argv: the output directory.
set out [lindex $argv 0]
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
recorder Element -file $out/beam_basic.out -time -precision 16 -ele 1 basicForce
recorder Node -file $out/beam_disp.out -time -precision 16 -node 2 -dof 1 2 3 disp
recorder Node -file $out/beam_reaction.out -time -precision 16 -node 1 -dof 1 2 3 reaction
timeSeries Linear 1
pattern Plain 1 1 {
    load 2 -100.0 0.0 0.0
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
puts "status $status time [getTime] basic [eleResponse 1 basicForce]"
