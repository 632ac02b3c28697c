# reset, reactions -dynamic and -rayleigh, and the force of members with
# mass under a record: a braced 2D portal whose columns carry their mass per
# length (elasticBeamColumn -mass: OpenSees 3.8's ElasticBeam2d takes its
# ground-motion load twice), a yielding Steel01 brace with its mass (truss
# -rho, not Rayleigh-damped in the analysis), nodal masses and Rayleigh
# damping on the current and initial stiffness. Every 10 steps the three
# kinds of reactions at the supports go to reactions.out; the columns' and
# the brace's `force` (OpenSees's getResistingForce: with their ground-motion
# load) to force.out. Halfway through the record, `reset` sends the model
# back to its start (yielded brace, time 0, the EnvelopeNode recorder's
# extremes) and the record runs again from 0.   argv: the output directory.
set out [lindex $argv 0]
source [file join [file dirname [info script]] record.tcl]
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0
node 2 5.0 0.0
node 3 0.0 3.0 -mass 1.0e4 1.0e4 0.0
node 4 5.0 3.0 -mass 8.0e3 8.0e3 0.0
fix 1 1 1 1
fix 2 1 1 1
geomTransf Linear 1
element elasticBeamColumn 1 1 3 0.01 2.0e11 1.0e-5 1 -mass 600.0
element elasticBeamColumn 2 2 4 0.01 2.0e11 1.0e-5 1 -mass 600.0
element elasticBeamColumn 3 3 4 0.02 2.0e11 4.0e-4 1
uniaxialMaterial Steel01 1 2.5e8 2.0e11 0.02
element truss 4 1 4 4.0e-4 1 -rho 300.0
recorder Node -file $out/disp.out -time -precision 16 -node 3 4 -dof 1 2 3 disp
recorder EnvelopeNode -file $out/envelope.out -precision 16 -node 3 4 -dof 1 disp
recorder Element -file $out/force.out -time -precision 16 -ele 1 2 4 force
rayleigh 0.3 0.0005 0.001 0.0
set dt 0.01
set n 300
timeSeries Path 1 -dt $dt -values [synthetic_record $dt $n 3.0]
pattern UniformExcitation 1 1 -accel 1
constraints Plain
numberer RCM
system BandGeneral
test NormDispIncr 1.0e-12 20
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
set f [open $out/reactions.out w]
foreach run {1 2} {
    for {set i 0} {$i < $n / 10} {incr i} {
        if {[analyze 10 $dt] != 0} { error "analyze failed at [getTime]" }
        set line [format %.16g [getTime]]
        foreach flag {{} -dynamic -rayleigh} {
            reactions {*}$flag
            foreach node {1 2} {
                foreach dof {1 2 3} { append line " " [format %.16g [nodeReaction $node $dof]] }
            }
        }
        foreach ele {1 4} {
            foreach v [eleForce $ele] { append line " " [format %.16g $v] }
        }
        puts $f $line
    }
    if {$run == 1} { reset }
}
close $f
