# A 3-storey linear shear stick (ndm 1): storey springs, floor masses,
# Rayleigh damping at 5 % in modes 1 and 3 from `eigen`, the synthetic
# record written to a file and read back by Path -filePath -factor;
# Newton with NormDispIncr. argv: the output directory.
set out [lindex $argv 0]
source [file join [file dirname [info script]] record.tcl]
wipe
model basic -ndm 1 -ndf 1
node 0 0.0
fix 0 1
set masses {1.0e5 1.0e5 0.8e5}
set stiffness {2.0e8 1.8e8 1.5e8}
foreach i {1 2 3} {
    node $i 0.0 -mass [lindex $masses [expr {$i - 1}]]
    uniaxialMaterial Elastic $i [lindex $stiffness [expr {$i - 1}]]
    element zeroLength $i [expr {$i - 1}] $i -mat $i -dir 1 -doRayleigh
}
set lambda [eigen -fullGenLapack 3]
set w1 [expr {sqrt([lindex $lambda 0])}]
set w3 [expr {sqrt([lindex $lambda 2])}]
set xi 0.05
rayleigh [expr {2 * $xi * $w1 * $w3 / ($w1 + $w3)}] [expr {2 * $xi / ($w1 + $w3)}] 0.0 0.0
set dt 0.005
set n 1600
set f [open $out/record.txt w]
foreach a [synthetic_record $dt $n 0.1] { puts $f $a }
close $f
timeSeries Path 2 -dt $dt -filePath $out/record.txt -factor 9.81
pattern UniformExcitation 1 1 -accel 2
recorder Node -file $out/stick3_disp.out -time -precision 16 -nodeRange 1 3 -dof 1 disp
recorder Node -file $out/stick3_base.out -time -precision 16 -node 0 -dof 1 reaction
constraints Transformation
numberer RCM
system UmfPack
test NormDispIncr 1.0e-12 10
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
analyze $n $dt
set f [open $out/stick3_eigen.out w]
puts $f $lambda
close $f
