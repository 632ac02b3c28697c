# OpenSees's bookkeeping commands on a yielding two-storey shear stick:
# fixX/fixY with -tol, the tags `recorder` returns, `remove recorder` and
# `remove recorders` (the files written then), `remove loadPattern` (the
# record stops acting), `record`, testIter and testNorm after a step, getNP, getPID.
# Each query's answer goes to queries.out, one row per analyze call.
# argv: the output directory.
set out [lindex $argv 0]
source [file join [file dirname [info script]] record.tcl]
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0
node 2 0.0 3.0 -mass 2.0e4 0.0 0.0
node 3 0.0 6.0 -mass 1.5e4 0.0 0.0
node 4 5.0 0.0
# the base at y = 0 (node 4 too) within the tolerance, the storeys' vertical
# and rotational DOFs by their x
fixY 1.0e-12 1 1 1 -tol 1.0e-9
fixX 0.0 0 1 1
uniaxialMaterial Steel01 1 4.0e5 2.0e7 0.05
uniaxialMaterial Steel01 2 3.0e5 1.5e7 0.05
element zeroLength 1 1 2 -mat 1 -dir 1
element zeroLength 2 2 3 -mat 2 -dir 1
set dt 0.01
set n 400
timeSeries Path 1 -dt $dt -values [synthetic_record $dt $n 2.0]
pattern UniformExcitation 1 1 -accel 1
set r0 [recorder Node -file $out/disp.out -time -precision 16 -node 2 3 -dof 1 disp]
set r1 [recorder EnvelopeNode -file $out/env_first.out -time -precision 16 -node 2 3 -dof 1 disp]
set r2 [recorder Element -file $out/force.out -time -precision 16 -ele 1 2 basicForce]
rayleigh 0.3 0.0 0.0 0.0
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-10 20
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
set f [open $out/queries.out w]
puts $f "$r0 $r1 $r2 [getNP] [getPID] [lrepeat 17 0.0]"
for {set i 0} {$i < 6} {incr i} {
    analyze 50 $dt
    puts $f "[getTime] [testIter] [testNorm]"
    # after 100 steps the first envelope stops: its rows hold the first 1 s
    if {$i == 1} { remove recorder $r1 }
    # after 200 steps the record stops: free vibration from there
    if {$i == 3} { remove loadPattern 1 }
}
close $f
remove recorders
set r3 [recorder Node -file $out/last.out -node 2 3 -dof 1 disp]
record
set f [open $out/tags.out w]
puts $f "$r3 [llength [getNodeTags]] [nodeDisp 3 1]"
close $f
