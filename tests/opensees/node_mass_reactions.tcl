# Reactions at nodes that carry their own mass under UniformExcitation: a
# two-bay 2D frame whose left support (fixed) and right roller (fixed in Y
# only) carry nodal mass, beside free storey nodes with mass, Rayleigh
# alpha_M damping, the record along X and 0.4 of it along Y. OpenSees's
# reaction at a node subtracts its unbalanced load, which holds the node's
# ground-motion load -m a_g (Node::addInertiaLoadToUnbalance), in fixed
# DOFs too. Read by the Node and EnvelopeNode recorders' `reaction` and by
# `reactions` with nodeReaction every 10 steps. argv: the output directory.
set out [lindex $argv 0]
source [file join [file dirname [info script]] record.tcl]
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0 -mass 800.0 800.0 0.0
node 2 6.0 0.0
node 3 0.0 3.0 -mass 1.0e4 1.0e4 0.0
node 4 6.0 3.0 -mass 1.2e4 1.2e4 0.0
node 5 11.0 3.0 -mass 5.0e3 5.0e3 40.0
fix 1 1 1 1
fix 2 1 1 1
fix 5 0 1 0
geomTransf Linear 1
element elasticBeamColumn 1 1 3 0.01 2.0e11 2.0e-4 1
element elasticBeamColumn 2 2 4 0.01 2.0e11 2.0e-4 1
element elasticBeamColumn 3 3 4 0.01 2.0e11 1.5e-4 1
element elasticBeamColumn 4 4 5 0.01 2.0e11 1.5e-4 1
recorder Node -file $out/reaction.out -time -precision 16 -node 1 2 3 4 5 -dof 1 2 3 reaction
recorder EnvelopeNode -file $out/env_reaction.out -time -precision 16 -node 1 3 5 -dof 1 2 reaction
set dt 0.01
set n 400
rayleigh 0.25 0.0 0.002 0.0
timeSeries Path 1 -dt $dt -values [synthetic_record $dt $n 1.0]
timeSeries Path 2 -dt $dt -values [synthetic_record $dt $n 0.4]
pattern UniformExcitation 1 1 -accel 1
pattern UniformExcitation 2 2 -accel 2
constraints Plain
numberer RCM
system BandGeneral
test NormDispIncr 1.0e-12 10
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
set f [open $out/node_reaction.out w]
for {set i 0} {$i < $n / 10} {incr i} {
    analyze 10 $dt
    reactions
    puts $f "[getTime] [nodeReaction 1] [nodeReaction 3] [nodeReaction 5 1] [nodeReaction 5 2]"
}
close $f
