# A two-storey elastic portal frame (6 m bay, 3 m storeys) loaded by its
# members: gravity as element loads (eleLoad -beamUniform) on the beams
# (transverse, Wy = -30 and -25 kN/m) and on the columns (axial self-weight,
# Wx = -6 kN/m along them, with a small transverse Wy as a wind on the left
# column line), in ten LoadControl steps, loadConst, then the synthetic record
# with Rayleigh damping on the committed stiffness (the columns on PDelta, so
# that N from the element loads enters the P-Delta forces and the tangent).
# Units kN, m, t.   argv: the output directory and the members: elastic
# (elasticBeamColumn, the default), fibre (dispBeamColumns, Legendre 3, on
# the RC sections of rc_section.tcl) or force (forceBeamColumns, Lobatto 5,
# on the same sections: OpenSees's common gravity-then-record script, the
# element loads carried by the sections, s = b q + s_p) or aggregator (the
# same, the columns on section Aggregator: a Steel01 Mz that yields and
# Elastic P, declared in that order, which the columns of their section
# force recorder follow; the Steel01's re-trials inside DBL_EPSILON at each
# step must keep the committed tangent, as OpenSees's Steel01 does).
set out [lindex $argv 0]
set members [expr {$argc > 1 ? [lindex $argv 1] : "elastic"}]
source [file join [file dirname [info script]] record.tcl]
source [file join [file dirname [info script]] rc_section.tcl]
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0
node 2 6.0 0.0
node 3 0.0 3.0 -mass 20.0 20.0 0.0
node 4 6.0 3.0 -mass 20.0 20.0 0.0
node 5 0.0 6.0 -mass 15.0 15.0 0.0
node 6 6.0 6.0 -mass 15.0 15.0 0.0
fix 1 1 1 1
fix 2 1 1 1
geomTransf PDelta 1
geomTransf Linear 2
set E 3.0e7
foreach {tag i j transf} {1 1 3 1  2 2 4 1  3 3 5 1  4 4 6 1  5 3 4 2  6 5 6 2} {
    if {$members eq "fibre" || $members eq "force" || $members eq "aggregator"} {
        if {$tag == 1} {
            rc_materials
            if {$members eq "aggregator"} {
                uniaxialMaterial Elastic 11 [expr {$E * 0.16}]
                uniaxialMaterial Steel01 12 60.0 [expr {$E * 2.13e-3}] 0.02
                section Aggregator 1 12 Mz 11 P
            } else {
                rc_section 1 0.4 0.4 0.04 3 3.14e-4
            }
            rc_section 2 0.3 0.5 0.04 3 2.01e-4
            if {$members eq "fibre"} {
                beamIntegration Legendre 1 1 3
                beamIntegration Legendre 2 2 3
            } else {
                beamIntegration Lobatto 1 1 5
                beamIntegration Lobatto 2 2 5
            }
        }
        element [expr {$members eq "fibre" ? "dispBeamColumn" : "forceBeamColumn"}] \
            $tag $i $j $transf $transf
    } elseif {$transf == 1} {
        element elasticBeamColumn $tag $i $j 0.16 $E 2.13e-3 1
    } else {
        element elasticBeamColumn $tag $i $j 0.15 $E 3.13e-3 2
    }
}
timeSeries Linear 1
pattern Plain 1 1 {
    eleLoad -ele 5 -type -beamUniform -30.0
    eleLoad -ele 6 -type -beamUniform -25.0 0.0
    # columns from base to top: local x upwards, local y towards -X
    eleLoad -range 1 4 -type -beamUniform 0.0 -6.0
    eleLoad -ele 1 3 -type -beamUniform -2.0
    load 4 0.0 -40.0 0.0
}
recorder Node -file $out/loads_disp.out -time -precision 12 -node 3 5 6 -dof 1 2 3 disp
recorder Node -file $out/loads_base.out -time -precision 12 -node 1 2 -dof 1 2 3 reaction
recorder Element -file $out/loads_force.out -time -precision 12 -ele 1 5 6 force
if {$members ne "elastic"} {
    recorder Element -file $out/loads_local.out -time -precision 12 -ele 1 5 localForce
    recorder Element -file $out/loads_section.out -time -precision 12 -ele 5 section 1 force
    if {$members eq "aggregator"} {
        # declared Mz P: OpenSees writes the columns in that order
        recorder Element -file $out/loads_column_section.out -time -precision 12 -ele 1 section 1 force
    }
}
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-12 20
algorithm Newton
integrator LoadControl 0.1
analysis Static
analyze 10
loadConst -time 0.0
wipeAnalysis
rayleigh 0.6 0.0 0.0 0.003
timeSeries Path 2 -dt 0.01 -values [synthetic_record 0.01 400 1.0]
pattern UniformExcitation 2 1 -accel 2
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-12 20
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
set status [analyze 400 0.01]
puts "portal element loads: status $status roof [nodeDisp 5 1] base moment [eleForce 1 3]"
