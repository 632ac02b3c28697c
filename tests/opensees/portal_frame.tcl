# A 2D elastic portal frame (6 m bay, 3 m columns): gravity in ten
# LoadControl steps, loadConst, then the synthetic record with Rayleigh
# damping (Newton, NormDispIncr). argv: the output directory.
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
geomTransf Linear 1
set E 2.0e11
element elasticBeamColumn 1 1 3 0.01 $E 2.0e-4 1
element elasticBeamColumn 2 2 4 0.01 $E 2.0e-4 1
element elasticBeamColumn 3 3 4 0.012 $E 4.0e-4 1
timeSeries Linear 1
pattern Plain 1 1 {
    load 3 0.0 -1.962e5 0.0
    load 4 0.0 -1.962e5 0.0
}
recorder Node -file $out/portal_disp.out -time -precision 16 -node 3 4 -dof 1 2 3 disp
recorder Node -file $out/portal_base.out -time -precision 16 -node 1 2 -dof 1 2 3 reaction
constraints Plain
numberer RCM
system BandGeneral
test NormDispIncr 1.0e-12 10
algorithm Newton
integrator LoadControl 0.1
analysis Static
analyze 10
loadConst -time 0.0
set lambda [eigen 2]
set w1 [expr {sqrt([lindex $lambda 0])}]
set w2 [expr {sqrt([lindex $lambda 1])}]
set xi 0.02
rayleigh [expr {2 * $xi * $w1 * $w2 / ($w1 + $w2)}] 0.0 [expr {2 * $xi / ($w1 + $w2)}] 0.0
set dt 0.01
set n 800
timeSeries Path 2 -dt $dt -values [synthetic_record $dt $n]
pattern UniformExcitation 2 1 -accel 2
wipeAnalysis
constraints Plain
numberer RCM
system BandGeneral
test NormDispIncr 1.0e-12 10
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
analyze $n $dt
set f [open $out/portal_eigen.out w]
puts $f $lambda
close $f
