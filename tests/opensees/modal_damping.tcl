# modalDamping after eigen (OpenSees 3.8: C = sum_i 2 zeta_i omega_i
# (M phi_i)(M phi_i)^T with M-normalised modes phi_i, its force -C v in the
# unbalance and, for modalDamping (not modalDampingQ), C in the tangent):
# a three-storey, one-bay frame of 6 m bays and 3.2 m storeys,
# elasticBeamColumn columns and beams, the floors' mass at the joints,
# storey one's columns on Steel01 zeroLength hinges (they yield under the
# record, so the tangent changes while the modes stay the first ones).
# argv: the output directory, then the variant: one (modalDamping 0.05 on
# every mode of eigen 3), each (modalDamping 0.02 0.05 0.08), fewer
# (modalDamping 0.03 0.06 with eigen 3: the third mode undamped) or
# quasi (modalDampingQ 0.05: the force only, not the tangent), and
# rayleigh (modalDamping 0.03 beside rayleigh 0.2 0 0 0); hht and
# hht_quasi: each's and quasi's factors under HHT 0.8 (OpenSees's modal
# force takes HHT's velocity at t + dt, not at t + alpha dt, and HHT keeps
# the matrix out of the tangent), with system FullGeneral; mass: each's
# factors, the roof's mass doubled after 400 steps (OpenSees keeps M phi
# of the time of `eigen`), with system FullGeneral.
set out [lindex $argv 0]
set variant [expr {$argc > 1 ? [lindex $argv 1] : "one"}]
source [file join [file dirname [info script]] record.tcl]
wipe
model basic -ndm 2 -ndf 3
set L 6.0; set H 3.2; set m 1.5e4
foreach c {0 1} {
    set x [expr {$L * $c}]
    node [expr {$c + 1}] $x 0.0
    node [expr {$c + 101}] $x 0.0
    fix [expr {$c + 1}] 1 1 1
    equalDOF [expr {$c + 1}] [expr {$c + 101}] 1 2
    for {set f 1} {$f <= 3} {incr f} {
        node [expr {10 * $f + $c + 1}] $x [expr {$H * $f}] -mass $m $m 0.0
    }
}
uniaxialMaterial Steel01 1 1.6e5 6.0e7 0.03
element zeroLength 1 1 101 -mat 1 -dir 6
element zeroLength 2 2 102 -mat 1 -dir 6
geomTransf Linear 1
foreach c {0 1} {
    element elasticBeamColumn [expr {10 + $c + 1}] [expr {$c + 101}] [expr {$c + 11}] 0.09 2.5e10 6.75e-4 1
    for {set f 2} {$f <= 3} {incr f} {
        element elasticBeamColumn [expr {10 * $f + $c + 1}] [expr {10 * ($f - 1) + $c + 1}] \
            [expr {10 * $f + $c + 1}] 0.09 2.5e10 6.75e-4 1
    }
}
for {set f 1} {$f <= 3} {incr f} {
    element elasticBeamColumn [expr {100 + $f}] [expr {10 * $f + 1}] [expr {10 * $f + 2}] 0.12 2.5e10 1.6e-3 1
}
set lambda [eigen 3]
puts "modal damping $variant: periods [lmap l $lambda {expr {2 * 3.14159265358979 / sqrt($l)}}]"
switch $variant {
    one { modalDamping 0.05 }
    each - hht - mass { modalDamping 0.02 0.05 0.08 }
    fewer { modalDamping 0.03 0.06 }
    quasi - hht_quasi { modalDampingQ 0.05 }
    rayleigh { modalDamping 0.03; rayleigh 0.2 0.0 0.0 0.0 }
}
timeSeries Path 1 -dt 0.01 -values [synthetic_record 0.01 800 1.2]
pattern UniformExcitation 1 1 -accel 1
recorder Node -file $out/modal_${variant}_disp.out -time -precision 16 -node 11 21 31 -dof 1 disp
recorder Node -file $out/modal_${variant}_vel.out -time -precision 16 -node 31 -dof 1 2 vel
recorder Node -file $out/modal_${variant}_reaction.out -time -precision 16 -node 1 2 -dof 1 2 3 reaction
recorder Element -file $out/modal_${variant}_hinge.out -time -precision 16 -ele 1 force
constraints Transformation
numberer Plain
set hht [string match hht* $variant]
system [expr {$hht || $variant eq "mass" ? "FullGeneral" : "BandGeneral"}]
test NormDispIncr 1.0e-10 50
algorithm Newton
if {$hht} { integrator HHT 0.8 } else { integrator Newmark 0.5 0.25 }
analysis Transient
if {$variant eq "mass"} {
    analyze 400 0.01
    mass 31 3.0e4 3.0e4 0.0
    mass 32 3.0e4 3.0e4 0.0
    puts "modal damping $variant: status [analyze 400 0.01] roof [nodeDisp 31 1]"
} else {
    puts "modal damping $variant: status [analyze 800 0.01] roof [nodeDisp 31 1]"
}
