# The 2D portal frame with P-Delta columns under ten times the gravity load
# (about a fifth of the sway buckling load): gravity by LoadControl with
# Newton, loadConst, then the synthetic record (Newmark, Newton,
# NormDispIncr), 2 % Rayleigh damping on the initial stiffness.
# argv: the output directory.
set out [lindex $argv 0]
source [file join [file dirname [info script]] record.tcl]
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0
node 2 6.0 0.0
node 3 0.0 3.0 -mass 2.0e4 2.0e4 0.0
node 4 6.0 3.0 -mass 2.0e4 2.0e4 0.0
fix 1 1 1 1
fix 2 1 1 1
geomTransf PDelta 1
geomTransf Linear 2
element elasticBeamColumn 1 1 3 0.01 2.0e11 2.0e-4 1
element elasticBeamColumn 2 2 4 0.01 2.0e11 2.0e-4 1
element elasticBeamColumn 3 3 4 0.012 2.0e11 4.0e-4 2
pattern Plain 1 Linear {
    load 3 0.0 -1.962e6 0.0
    load 4 0.0 -1.962e6 0.0
}
recorder Node -file $out/pdelta_disp.out -time -precision 16 -node 3 4 -dof 1 2 3 disp
constraints Transformation
numberer RCM
system ProfileSPD
test NormDispIncr 1.0e-12 10
algorithm Newton
integrator LoadControl 0.1
analysis Static
analyze 10
loadConst -time 0.0
rayleigh 0.0 0.0 0.002 0.0
timeSeries Path 2 -dt 0.01 -values [synthetic_record 0.01 600]
pattern UniformExcitation 2 1 -accel 2
wipeAnalysis
test NormDispIncr 1.0e-12 10
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
set status [analyze 600 0.01]
puts "pdelta: $status [expr {[namespace exists ::poundfe] ? [poundfe::report] : ""}]"
