# The modes after gravity of a two-storey, two-bay frame of fibre members with
# PDelta columns and the members' self-weight as element loads, in OpenSees 3.8
# (doc/verification.md, "Element loads"): the frame of p_delta_modes.prm, for
# `poundfe modal p_delta_modes.prm`. Run:
#   OpenSees p_delta_modes.tcl [forceBeamColumn|dispBeamColumn] [unit weight]
set etype [expr {[llength $argv] > 0 ? [lindex $argv 0] : "forceBeamColumn"}]
set gamma [expr {[llength $argv] > 1 ? [lindex $argv 1] : 25e3}]
wipe
model basic -ndm 2 -ndf 3
node 1 0 0; node 2 6 0; node 3 10 0
fix 1 1 1 1; fix 2 1 1 1; fix 3 1 1 1
node 4 0 3.5 -mass 6666.666666666667 6666.666666666667 0
node 5 6 3.5 -mass 6666.666666666667 6666.666666666667 0
node 6 10 3.5 -mass 6666.666666666667 6666.666666666667 0
node 7 0 6.5 -mass 5000 5000 0
node 8 6 6.5 -mass 5000 5000 0
node 9 10 6.5 -mass 5000 5000 0
geomTransf Linear 1
geomTransf PDelta 2
uniaxialMaterial Elastic 13 3e10
section Fiber 1 {
  fiber 0.115470053837925 0 0.08 13
  fiber -0.115470053837925 0 0.08 13
}
section Fiber 2 {
  fiber 0.115470053837925 0 0.06 13
  fiber -0.115470053837925 0 0.06 13
}
beamIntegration Lobatto 1 1 5
beamIntegration Lobatto 2 2 5
element $etype 7 1 4 2 1
element $etype 8 2 5 2 1
element $etype 9 3 6 2 1
element $etype 10 4 5 1 2
element $etype 11 5 6 1 2
element $etype 12 4 7 2 1
element $etype 13 5 8 2 1
element $etype 14 6 9 2 1
element $etype 15 7 8 1 2
element $etype 16 8 9 1 2
set g 9.81
pattern Plain 2 Linear {
  foreach n {4 5 6} { load $n 0 [expr {-20000*$g/3}] 0 }
  foreach n {7 8 9} { load $n 0 [expr {-15000*$g/3}] 0 }
  # columns: local x up, self-weight along -x; beams: local y up
  eleLoad -ele 7 8 9 12 13 14 -type -beamUniform 0 [expr {-$gamma*0.16}]
  eleLoad -ele 10 11 15 16 -type -beamUniform [expr {-$gamma*0.12}] 0
}
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-14 50
algorithm Newton
integrator LoadControl 0.1
analysis Static
set status [analyze 10]
puts "gravity status $status"
set lambda [eigen -fullGenLapack 4]
foreach l $lambda { puts [format "f %.12f" [expr {sqrt($l)/(2*acos(-1))}]] }
foreach e {7 12} { puts "ele $e basic [eleResponse $e basicForce]" }
