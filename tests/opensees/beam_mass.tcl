# Members' own mass (-mass, lumped rho L/2 on each end's translations)
# under UniformExcitation: a portal frame (6 m bay, 3 m columns) whose beam
# and columns carry their mass per length, beside nodal masses, with
# Rayleigh damping; the record along X (and Z in 3D). The reactions at the
# supports take the columns' ground-motion load (getResistingForce
# subtracts the element's inertia load). argv: the output directory, the
# members (elasticBeamColumn, forceBeamColumn, dispBeamColumn), the
# model's dimension (2d, the default, or 3d) and, with -cMass, the members'
# consistent mass (ElasticBeam2d/3d, DispBeamColumn2d/3d::getMass; in 3D
# the roof's rotations then free, so that the twists' mass acts): the first
# three eigenvalues are written before the record.
set out [lindex $argv 0]
set type [lindex $argv 1]
set dim [expr {$argc > 2 ? [lindex $argv 2] : "2d"}]
set cmass [expr {$argc > 3 && [lindex $argv 3] eq "-cMass" ? "-cMass" : ""}]
source [file join [file dirname [info script]] record.tcl]
wipe
set E 2.0e11
set A 0.01
set Iz 2.0e-4
set rho_beam 1200.0
set rho_column 800.0
if {$dim == "2d"} {
    model basic -ndm 2 -ndf 3
    node 1 0.0 0.0
    node 2 6.0 0.0
    node 3 0.0 3.0 -mass 1.0e4 1.0e4 0.0
    node 4 6.0 3.0 -mass 1.0e4 1.0e4 0.0
    fix 1 1 1 1
    fix 2 1 1 1
    geomTransf Linear 1
    geomTransf Linear 2
    section Elastic 1 $E $A $Iz
    set props "$A $E $Iz"
    set dofs {1 2 3}
    set directions {1}
} else {
    model basic -ndm 3 -ndf 6
    node 1 0.0 0.0 0.0
    node 2 6.0 0.0 0.0
    node 3 0.0 3.0 0.0 -mass 1.0e4 1.0e4 1.0e4 0.0 0.0 0.0
    node 4 6.0 3.0 0.0 -mass 1.0e4 1.0e4 1.0e4 0.0 0.0 0.0
    fix 1 1 1 1 1 1 1
    fix 2 1 1 1 1 1 1
    if {$cmass eq ""} {
        fix 3 0 0 0 1 1 0
        fix 4 0 0 0 1 1 0
    }
    geomTransf Linear 1 0.0 0.0 1.0
    geomTransf Linear 2 0.0 0.0 1.0
    set G 8.0e10
    section Elastic 1 $E $A $Iz 1.5e-4 $G 1.0e-4
    set props "$A $E $G 1.0e-4 1.5e-4 $Iz"
    set dofs {1 2 3 4 5 6}
    set directions {1 3}
}
beamIntegration Lobatto 1 1 5
beamIntegration Legendre 2 1 3
proc member {tag i j transf rho} {
    global type props cmass
    switch -- $type {
        elasticBeamColumn {
            element elasticBeamColumn $tag $i $j {*}$props $transf -mass $rho {*}$cmass
        }
        forceBeamColumn { element forceBeamColumn $tag $i $j $transf 1 -mass $rho }
        dispBeamColumn { element dispBeamColumn $tag $i $j $transf 2 -mass $rho {*}$cmass }
        default { error "beam_mass.tcl: no member type '$type'" }
    }
}
member 1 1 3 1 $rho_column
member 2 2 4 1 $rho_column
member 3 3 4 2 $rho_beam
if {$cmass ne ""} {
    set file [open $out/eigen.out w]
    puts $file "0.0 [eigen -fullGenLapack 3]"
    close $file
}
recorder Node -file $out/roof.out -time -precision 16 -node 3 4 -dof {*}$dofs disp
recorder Node -file $out/base.out -time -precision 16 -node 1 2 -dof {*}$dofs reaction
set dt 0.01
set n 500
rayleigh 0.2 0.0 0.001 0.0
foreach d $directions {
    timeSeries Path $d -dt $dt -values [synthetic_record $dt $n [expr {$d == 1 ? 1.0 : 0.6}]]
    pattern UniformExcitation $d $d -accel $d
}
constraints Plain
numberer RCM
system BandGeneral
test NormDispIncr 1.0e-12 10
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
analyze $n $dt
