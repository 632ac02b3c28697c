# A zeroLength added between two analyze calls to nodes that have moved:
# OpenSees measures its strains and rates from the nodes' displacements and
# velocities at that moment (ZeroLength::setDomain's d0 and v0). Two masses on
# springs under the synthetic record; after 300 steps a spring with viscous
# damping (Elastic E eta) joins the top mass to the ground, and a stiff
# spring joins the two masses. With argv "truss" the stiff spring is a truss
# (the top mass 1 m higher), which OpenSees takes as long as it is then and
# measures its strains (not its rates) from then (Truss::setDomain,
# -useInitialDisp). argv: the output directory <truss>.
set out [lindex $argv 0]
set truss [expr {[lindex $argv 1] eq "truss"}]
source [file join [file dirname [info script]] record.tcl]
wipe
model basic -ndm 1 -ndf 1
node 1 0.0
node 2 0.0 -mass 2.0
node 3 [expr {$truss ? 1.0 : 0.0}] -mass 1.0
fix 1 1
uniaxialMaterial Elastic 1 800.0
uniaxialMaterial Steel01 2 3.0 600.0 0.05
uniaxialMaterial Elastic 3 500.0 4.0
uniaxialMaterial Elastic 4 2000.0
element zeroLength 1 1 2 -mat 1 -dir 1
element zeroLength 2 2 3 -mat 2 -dir 1
set dt 0.01
timeSeries Path 1 -dt $dt -values [synthetic_record $dt 1000]
pattern UniformExcitation 1 1 -accel 1
recorder Node -file $out/late_disp.out -time -precision 16 -node 2 3 -dof 1 disp
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-12 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
analyze 300 $dt
element zeroLength 3 1 3 -mat 3 -dir 1
if {$truss} {
  element truss 4 2 3 0.5 4
} else {
  element zeroLength 4 2 3 -mat 4 -dir 1
}
recorder Element -file $out/late_force.out -time -precision 16 -ele 3 4 force
analyze 700 $dt
puts "late: time [getTime] disp [nodeDisp 3 1]"
