# Rayleigh factors of nodes and elements made after `rayleigh`, in the plane
# (2d) and in space (3d). OpenSees's rayleigh sets the factors of the nodes
# and elements that exist when it runs (Domain::setRayleighDampingFactors);
# one made later is undamped (its constructor's zeros) until the next
# rayleigh, and `region -rayleigh` sets its members' alone. A portal of
# elastic members sways under the synthetic record with rayleigh given
# before a gable (a node with mass and a member with -mass) is made. After
# 0.8 s the beam is removed and made again (undamped: a new element), so
# are a cantilever arm and its tip node (remove element, remove node), a
# region damps the gable's member and its nodes, and (2d) a truss with a
# consistent mass joins two joints that have moved (Truss takes its length,
# and so its mass, from the moved nodes; -doRayleigh 1 but made after both),
# a node with mass on a spring is made; 1.2 s more.
# argv: the output directory, then 2d or 3d.
set out [lindex $argv 0]
set variant [lindex $argv 1]
source [file join [file dirname [info script]] record.tcl]
wipe
if {$variant eq "2d"} {
    model basic -ndm 2 -ndf 3
    node 1 0.0 0.0
    node 2 6.0 0.0
    node 3 0.0 4.0 -mass 2.0e4 2.0e4 0.0
    node 4 6.0 4.0 -mass 2.0e4 2.0e4 0.0
    fix 1 1 1 1
    fix 2 1 1 1
    geomTransf Linear 1
    set column "0.06 2.1e11 4.5e-4 1"
    set beam "0.02 2.1e11 4.0e-4 1 -mass 300.0"
    set apex {3.0 7.0 -mass 5.0e3 5.0e3 10.0}
    set tip {7.5 4.0 -mass 4.0e3 4.0e3 5.0}
    set dofs {1 2 3}
} else {
    model basic -ndm 3 -ndf 6
    node 1 0.0 0.0 0.0
    node 2 6.0 0.0 0.0
    node 3 0.0 0.0 4.0 -mass 2.0e4 2.0e4 2.0e4 0.0 0.0 0.0
    node 4 6.0 0.0 4.0 -mass 2.0e4 2.0e4 2.0e4 0.0 0.0 0.0
    fix 1 1 1 1 1 1 1
    fix 2 1 1 1 1 1 1
    geomTransf Linear 1 0 -1 0
    geomTransf Linear 2 1 0 0
    set column "0.06 2.1e11 8.1e10 5.0e-4 4.5e-4 3.0e-4 2"
    set beam "0.02 2.1e11 8.1e10 5.0e-4 3.0e-4 4.0e-4 1 -mass 300.0"
    set apex {3.0 0.5 7.0 -mass 5.0e3 5.0e3 5.0e3 10.0 10.0 10.0}
    set tip {7.5 0.0 4.0 -mass 4.0e3 4.0e3 4.0e3 5.0 5.0 5.0}
    set dofs {1 2 3 4 5 6}
}
eval element elasticBeamColumn 1 1 3 $column
eval element elasticBeamColumn 2 2 4 $column
eval element elasticBeamColumn 3 3 4 $beam
eval node 6 $tip
eval element elasticBeamColumn 6 4 6 $beam
timeSeries Path 1 -dt 0.01 -values [synthetic_record 0.01 300 0.6] -factor 9.81
pattern UniformExcitation 1 1 -accel 1
if {$variant eq "3d"} {
    timeSeries Path 2 -dt 0.01 -values [synthetic_record 0.01 300 0.25] -factor 9.81
    pattern UniformExcitation 2 2 -accel 2
}
rayleigh 0.4 0.002 0.0 0.0
# made after rayleigh: undamped
eval node 5 $apex
eval element elasticBeamColumn 4 3 5 $beam
recorder Node -file $out/disp.out -time -precision 16 -node 3 4 5 -dof {*}$dofs disp
constraints Plain
numberer RCM
system BandGeneral
test NormDispIncr 1.0e-10 25
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
analyze 80 0.01
remove element 3
eval element elasticBeamColumn 3 3 4 $beam
remove element 6
remove node 6
eval node 6 $tip
eval element elasticBeamColumn 6 4 6 $beam
region 1 -ele 4 -rayleigh 0.3 0.003 0.0 0.0
if {$variant eq "2d"} {
    uniaxialMaterial Elastic 1 2.1e11
    element truss 5 4 5 5.0e-4 1 -rho 400.0 -cMass 1 -doRayleigh 1
}
recorder Node -file $out/tip.out -time -precision 16 -node 6 -dof {*}$dofs disp
recorder Element -file $out/force.out -time -precision 16 -ele 3 4 6 force
analyze 120 0.01
