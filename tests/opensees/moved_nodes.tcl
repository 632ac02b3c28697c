# Members added on nodes that have moved: a portal frame with a gable
# (elasticBeamColumn with -mass on a Linear geomTransf, a Steel01 truss
# brace with -rho) under the synthetic record; at 0.8 s, while it sways, a
# new node and an elasticBeamColumn on the moved apex (P-Delta), and a
# second truss with -rho across the frame are added. OpenSees's
# transformations (LinearCrdTransf2d, PDeltaCrdTransf2d::initialize:
# nodeIInitialDisp, nodeJInitialDisp) and Truss (initialDisp) take the
# member along and as long as it is then, measure its displacements from
# then, and lump rho L / 2 of that length. argv: the output directory.
set out [lindex $argv 0]
source [file join [file dirname [info script]] record.tcl]
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0
node 2 6.0 0.0
node 3 0.0 4.0 -mass 2.0e4 2.0e4 0.0
node 4 6.0 4.0 -mass 2.0e4 2.0e4 0.0
node 5 3.0 7.0 -mass 5.0e3 5.0e3 10.0
fix 1 1 1 1
fix 2 1 1 1
equalDOF 3 4 1
geomTransf Linear 1
geomTransf PDelta 2
element elasticBeamColumn 1 1 3 0.01 2.1e11 1.0e-4 1 -mass 500.0
element elasticBeamColumn 2 2 4 0.01 2.1e11 1.0e-4 1 -mass 500.0
element elasticBeamColumn 3 3 4 0.02 2.1e11 4.0e-4 1
element elasticBeamColumn 4 3 5 0.01 2.1e11 1.0e-4 1 -mass 300.0
element elasticBeamColumn 5 4 5 0.01 2.1e11 1.0e-4 1 -mass 300.0
uniaxialMaterial Steel01 7 2.5e8 2.0e11 0.02
element truss 6 1 4 4.0e-4 7 -rho 300.0
timeSeries Path 1 -dt 0.01 -values [synthetic_record 0.01 300 1.0] -factor 9.81
pattern UniformExcitation 1 1 -accel 1
recorder Node -file $out/disp.out -time -precision 16 -node 3 4 5 -dof 1 2 3 disp
constraints Transformation
numberer RCM
system BandGeneral
test NormDispIncr 1.0e-10 25
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
analyze 80 0.01
node 6 3.0 9.0 -mass 6.0e3 6.0e3 10.0
element elasticBeamColumn 7 5 6 0.01 2.1e11 1.0e-4 2 -mass 200.0
element truss 8 2 3 4.0e-4 7 -rho 200.0
recorder Node -file $out/apex.out -time -precision 16 -node 6 -dof 1 2 3 disp
recorder Element -file $out/force.out -time -precision 16 -ele 4 6 7 8 force
set f [open $out/reactions.out w]
for {set i 0} {$i < 16} {incr i} {
    analyze 10 0.01
    reactions
    set line [format %.16g [getTime]]
    foreach node {1 2} { foreach dof {1 2 3} { append line " " [format %.16g [nodeReaction $node $dof]] } }
    puts $f $line
}
close $f
