# Beam-columns made on nodes that have moved, in the plane (2d) and in space
# (3d): a portal of yielding fibre columns (forceBeamColumn and
# dispBeamColumn, Steel01 fibres) and an elastic beam sways under the
# synthetic record; after 0.8 s the beam is removed and made again as a
# forceBeamColumn between the moved joints, and a gable of an
# elasticBeamColumn and a dispBeamColumn (2d: Corotational; 3d: PDelta and
# Linear) joins a joint that has moved to a new apex node, and 1.2 s more.
# OpenSees's transformations (LinearCrdTransf2d/3d, PDeltaCrdTransf2d/3d,
# CorotCrdTransf2d::initialize: nodeIInitialDisp, nodeJInitialDisp) take each
# member along and as long as it is then and measure its displacements from
# then. argv: the output directory, then 2d or 3d.
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
    uniaxialMaterial Steel01 1 2.5e8 2.0e11 0.02
    section Fiber 1 { patch rect 1 8 1 -0.15 -0.1 0.15 0.1 }
    geomTransf Linear 1
    geomTransf PDelta 2
    geomTransf Corotational 3
    set beam "0.02 2.1e11 4.0e-4 1"
    set gable {3 3}
    set apex {3.0 7.0 -mass 5.0e3 5.0e3 10.0}
    set dofs {1 2 3}
} else {
    model basic -ndm 3 -ndf 6
    node 1 0.0 0.0 0.0
    node 2 6.0 0.0 0.0
    node 3 0.0 0.0 4.0 -mass 2.0e4 2.0e4 2.0e4 0.0 0.0 0.0
    node 4 6.0 0.0 4.0 -mass 2.0e4 2.0e4 2.0e4 0.0 0.0 0.0
    fix 1 1 1 1 1 1 1
    fix 2 1 1 1 1 1 1
    uniaxialMaterial Steel01 1 2.5e8 2.0e11 0.02
    section Fiber 1 -GJ 2.7e7 { patch rect 1 8 6 -0.15 -0.1 0.15 0.1 }
    geomTransf PDelta 2 1 0 0
    geomTransf Linear 1 0 -1 0
    geomTransf PDelta 3 0 1 0
    set beam "0.02 2.1e11 8.1e10 5.0e-4 3.0e-4 4.0e-4 1"
    set gable {3 1}
    set apex {3.0 0.5 7.0 -mass 5.0e3 5.0e3 5.0e3 10.0 10.0 10.0}
    set dofs {1 2 3 4 5 6}
}
beamIntegration Lobatto 1 1 5
element forceBeamColumn 1 1 3 2 1
element dispBeamColumn 2 2 4 2 1
eval element elasticBeamColumn 3 3 4 $beam
timeSeries Path 1 -dt 0.01 -values [synthetic_record 0.01 300 0.6] -factor 9.81
pattern UniformExcitation 1 1 -accel 1
if {$variant eq "3d"} {
    timeSeries Path 2 -dt 0.01 -values [synthetic_record 0.01 300 0.25] -factor 9.81
    pattern UniformExcitation 2 2 -accel 2
}
rayleigh 0.4 0.0 0.0 0.0
recorder Node -file $out/disp.out -time -precision 16 -node 3 4 -dof {*}$dofs disp
constraints Plain
numberer RCM
system BandGeneral
test NormDispIncr 1.0e-10 25
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
analyze 80 0.01
remove element 3
element forceBeamColumn 3 3 4 1 1
eval node 5 $apex
lassign $gable elastic disp
eval element elasticBeamColumn 4 3 5 [lrange $beam 0 end-1] $elastic
element dispBeamColumn 5 4 5 $disp 1
# the factors of the members and node made now (OpenSees's rayleigh sets
# those that exist)
rayleigh 0.4 0.0 0.0 0.0
recorder Node -file $out/apex.out -time -precision 16 -node 5 -dof {*}$dofs disp
recorder Element -file $out/force.out -time -precision 16 -ele 3 4 5 force
recorder Element -file $out/basic.out -time -precision 16 -ele 3 5 basicDeformation
analyze 120 0.01
