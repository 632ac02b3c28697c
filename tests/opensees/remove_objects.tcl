# remove element, node, sp and timeSeries mid-analysis: the two sticks of
# pounding_sticks.tcl pounding through an ImpactMaterial gap, tied by a
# yielding Steel01 link, the first stick also tied by a spring to a third
# mass held by `fix`. After 1.5 s of the record the link is removed
# (element 5), then the spring (element 6) with the node that anchored it
# (node 6), the fixity of the third mass (sp 7 1: it then swings on a
# spring of its own from the ground) and the record's series (its pattern
# keeps it, as OpenSees's copy); the record runs on to 4 s.
# argv: the output directory.
set out [lindex $argv 0]
source [file join [file dirname [info script]] record.tcl]
wipe
model basic -ndm 1 -ndf 1
set pi 3.14159265358979
set m 1.0e5
node 1 0.0
node 2 0.0 -mass $m
node 3 0.0
node 4 0.0 -mass $m
node 6 0.0
node 7 0.0 -mass [expr {$m / 4}]
fix 1 1
fix 3 1
fix 6 1
fix 7 1
set k2 [expr {$m * pow(2 * $pi / 0.5, 2)}]
set k4 [expr {$m * pow(2 * $pi / 1.0, 2)}]
uniaxialMaterial Elastic 1 $k2 [expr {0.05 * 2 * sqrt($k2 * $m)}]
uniaxialMaterial Elastic 2 $k4 [expr {0.05 * 2 * sqrt($k4 * $m)}]
uniaxialMaterial ImpactMaterial 3 2.0e9 6.0e8 -0.002 -0.01
uniaxialMaterial Steel01 4 1.0e5 4.0e7 0.05
uniaxialMaterial Elastic 5 [expr {$k4 / 2}]
element zeroLength 1 1 2 -mat 1 -dir 1
element zeroLength 2 3 4 -mat 2 -dir 1
element zeroLength 3 2 4 -mat 3 -dir 1
element zeroLength 5 2 4 -mat 4 -dir 1
element zeroLength 6 6 2 -mat 5 -dir 1
element zeroLength 7 1 7 -mat 5 -dir 1
set dt 0.002
set n 2000
timeSeries Path 1 -dt $dt -values [synthetic_record $dt $n 0.6]
pattern UniformExcitation 1 1 -accel 1
recorder Node -file $out/disp.out -time -precision 16 -node 2 4 7 -dof 1 disp
recorder Element -file $out/gap.out -time -precision 16 -ele 3 7 force
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-10 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
set first [analyze 750 $dt]
remove element 5
remove element 6
remove node 6
remove sp 7 1
remove timeSeries 1
set second [analyze [expr {$n - 750}] $dt]
puts "remove_objects: status $first $second nodes [getNodeTags] elements [getEleTags]"
