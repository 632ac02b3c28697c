# A two-storey, one-bay RC frame of fibre members (columns 0.4 m x 0.4 m,
# beams 0.3 m x 0.5 m, forceBeamColumns with Lobatto 5 points, the columns
# on P-Delta), gravity (nodal loads) by LoadControl in 10 steps, held by
# loadConst -time 0, then 6 s of the synthetic record of record.tcl scaled
# by 1.5 (a Path with -values), Newmark average acceleration, Newton with
# NormDispIncr, 5 % Rayleigh damping on the committed (or initial) stiffness and mass.
#   argv: OUTPUT_DIR <committed|initial> <ALGORITHM> <INTEGRATOR>: the
#   record's algorithm (Newton by default; e.g. NewtonLineSearch) and
#   integrator words (Newmark 0.5 0.25 by default; e.g. HHT 0.8); a fifth
#   word disp makes the members dispBeamColumns on Legendre points
set out [lindex $argv 0]
source [file join [file dirname [info script]] record.tcl]
source [file join [file dirname [info script]] rc_section.tcl]
wipe
model basic -ndm 2 -ndf 3
set W 6.0; set H 3.0
node 1 0.0 0.0
node 2 $W 0.0
node 3 0.0 $H -mass 30.0 30.0 0.0
node 4 $W $H -mass 30.0 30.0 0.0
node 5 0.0 [expr {2*$H}] -mass 25.0 25.0 0.0
node 6 $W [expr {2*$H}] -mass 25.0 25.0 0.0
fix 1 1 1 1
fix 2 1 1 1
rc_materials
rc_section 1 0.4 0.4 0.04 3 3.14e-4
rc_section 2 0.3 0.5 0.04 3 2.01e-4
geomTransf PDelta 1
geomTransf Linear 2
set disp [expr {$argc > 4 && [lindex $argv 4] eq "disp"}]
set rule [expr {$disp ? "Legendre" : "Lobatto"}]
set member [expr {$disp ? "dispBeamColumn" : "forceBeamColumn"}]
beamIntegration $rule 1 1 5
beamIntegration $rule 2 2 5
element $member 1 1 3 1 1
element $member 2 2 4 1 1
element $member 3 3 5 1 1
element $member 4 4 6 1 1
element $member 5 3 4 2 2
element $member 6 5 6 2 2
recorder Node -file $out/frame_disp.out -time -precision 12 -node 3 5 -dof 1 2 3 disp
recorder Node -file $out/frame_base.out -time -precision 12 -node 1 2 -dof 1 2 3 reaction
recorder Element -file $out/frame_section.out -time -precision 12 -ele 1 2 section 1 force
recorder Element -file $out/frame_beam.out -time -precision 12 -ele 5 localForce
timeSeries Linear 1
pattern Plain 1 1 {
    load 3 0.0 -300.0 0.0
    load 4 0.0 -300.0 0.0
    load 5 0.0 -250.0 0.0
    load 6 0.0 -250.0 0.0
}
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-12 50
algorithm Newton
integrator LoadControl 0.1
analysis Static
analyze 10
loadConst -time 0.0
wipeAnalysis
# 5 % at the first two modes' circular frequencies (fixed here: ~ 6.9 and 22 rad/s)
set w1 6.9; set w2 22.0; set zeta 0.05
# argv's second word: the stiffness part of the damping on the committed
# (default) or the initial stiffness
set on [expr {$argc > 1 ? [lindex $argv 1] : "committed"}]
set a0 [expr {2*$zeta*$w1*$w2/($w1 + $w2)}]; set a1 [expr {2*$zeta/($w1 + $w2)}]
if {$on eq "initial"} {
    rayleigh $a0 0.0 $a1 0.0
} else {
    rayleigh $a0 0.0 0.0 $a1
}
timeSeries Path 2 -dt 0.01 -values [synthetic_record 0.01 600 1.5]
pattern UniformExcitation 2 1 -accel 2
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-12 50
algorithm {*}[expr {$argc > 2 ? [lindex $argv 2] : "Newton"}]
integrator {*}[expr {$argc > 3 ? [lindex $argv 3] : "Newmark 0.5 0.25"}]
analysis Transient
set status [analyze 600 0.01]
puts "frame: status $status roof [nodeDisp 5 1] [expr {[namespace exists ::poundfe] ? [poundfe::report] : ""}]"
