# A one-storey, one-bay (5 m x 4 m) RC frame in space of fibre members:
# forceBeamColumn columns (Lobatto 5 points, Concrete02 and Steel02, bars on
# all four faces, PDelta, vecxz along X) and dispBeamColumn beams (Legendre 3
# points, Linear, depth vertical), the floor's mass at its four joints (no
# diaphragm), gravity by LoadControl in 10 steps held by loadConst, then
# 3 s of the synthetic record along X and 0.8 of it along Y, Newmark
# average acceleration at 0.01 s, Newton with NormDispIncr 1e-10,
# Rayleigh damping on mass and initial stiffness.
# argv: the output directory, then the variant: fibre (the default), loads
# (the members' own weight and a lateral pressure as element loads,
# eleLoad -beamUniform Wy Wz Wx, on the columns and beams in the gravity
# pattern) or aggregator (those loads on members whose sections are
# Aggregators of uniaxial laws: P and T elastic, Mz and My Steel01).
set out [lindex $argv 0]
set variant [expr {$argc > 1 ? [lindex $argv 1] : "fibre"}]
source [file join [file dirname [info script]] record.tcl]
wipe
model basic -ndm 3 -ndf 6
set Lx 5.0; set Ly 4.0; set H 3.0; set m 10000.0; set g 9.81
set c 1
foreach {x y} [list 0.0 0.0 $Lx 0.0 0.0 $Ly $Lx $Ly] {
    node $c $x $y 0.0
    fix $c 1 1 1 1 1 1
    node [expr {10 + $c}] $x $y $H -mass $m $m $m 0.0 0.0 0.0
    incr c
}
uniaxialMaterial Concrete02 1 -30e6 -0.002 -6e6 -0.006 0.1 3e6 1.5e9
uniaxialMaterial Steel02 2 420e6 200e9 0.01 20 0.925 0.15
if {$variant eq "aggregator"} {
    # column: EA, Mz 120 kNm (EI 5e7), My 140 kNm (EI 4e7), GJ; beam: EA, Mz, My, GJ
    uniaxialMaterial Elastic 11 4.8e9
    uniaxialMaterial Steel01 12 1.2e5 5.0e7 0.02
    uniaxialMaterial Steel01 13 1.4e5 4.0e7 0.03
    uniaxialMaterial Elastic 14 2.7e7
    section Aggregator 1 11 P 12 Mz 13 My 14 T
    uniaxialMaterial Elastic 21 4.5e9
    uniaxialMaterial Steel01 22 3.0e5 6.0e7 0.02
    uniaxialMaterial Steel01 23 1.5e5 2.5e7 0.02
    uniaxialMaterial Elastic 24 2.2e7
    section Aggregator 2 21 P 23 My 22 Mz 24 T
} else {
    section Fiber 1 -GJ 2.7e7 {
        patch rect 1 8 8 -0.2 -0.2 0.2 0.2
        layer straight 2 3 3.14e-4 0.16 -0.16 0.16 0.16
        layer straight 2 3 3.14e-4 -0.16 -0.16 -0.16 0.16
        fiber 0.0 -0.16 3.14e-4 2
        fiber 0.0 0.16 3.14e-4 2
    }
    section Fiber 2 -GJ 2.2e7 {
        patch rect 1 10 4 -0.25 -0.15 0.25 0.15
        layer straight 2 3 2.01e-4 0.21 -0.11 0.21 0.11
        layer straight 2 3 2.01e-4 -0.21 -0.11 -0.21 0.11
    }
}
geomTransf PDelta 1 1 0 0
geomTransf Linear 2 0 -1 0
geomTransf Linear 3 1 0 0
beamIntegration Lobatto 1 1 5
beamIntegration Legendre 2 2 3
foreach c {1 2 3 4} { element forceBeamColumn $c $c [expr {10 + $c}] 1 1 }
element dispBeamColumn 5 11 12 2 2
element dispBeamColumn 6 13 14 2 2
element dispBeamColumn 7 11 13 3 2
element dispBeamColumn 8 12 14 3 2
recorder Node -file $out/frame3d_roof.out -time -precision 16 -node 11 14 -dof 1 2 3 disp
recorder Node -file $out/frame3d_base.out -time -precision 16 -node 1 2 -dof 1 2 3 reaction
recorder Element -file $out/frame3d_column.out -time -precision 16 -ele 1 localForce
recorder Element -file $out/frame3d_section.out -time -precision 16 -ele 1 section 1 deformation
if {$variant eq "aggregator"} {
    # a beam's section, declared P My Mz T: OpenSees writes its columns so
    recorder Element -file $out/frame3d_beam_section.out -time -precision 16 -ele 5 section 1 force
}
timeSeries Linear 1
pattern Plain 1 1 {
    foreach c {11 12 13 14} { load $c 0.0 0.0 [expr {-$m * $g}] 0.0 0.0 0.0 }
    if {$variant ne "fibre"} {
        # columns: local x up, y along -Y, z along X; beams: local y up
        eleLoad -ele 1 2 3 4 -type -beamUniform 500.0 -800.0 -4.0e3
        eleLoad -range 5 8 -type -beamUniform -2.0e4 1.5e3 600.0
        eleLoad -ele 5 -type -beamUniform -5.0e3 0.0
    }
}
constraints Plain
numberer Plain
system UmfPack
test NormDispIncr 1.0e-10 50
algorithm Newton
integrator LoadControl 0.1
analysis Static
analyze 10
loadConst -time 0.0
wipeAnalysis
rayleigh 0.4 0.0 0.002 0.0
set dt 0.01
# bench/opensees/speed.py sets ::bench_steps for a longer run
set n [expr {[info exists ::bench_steps] ? $::bench_steps : 300}]
timeSeries Path 2 -dt $dt -values [synthetic_record $dt $n 1.5]
timeSeries Path 3 -dt $dt -values [synthetic_record $dt $n 1.2]
pattern UniformExcitation 2 1 -accel 2
pattern UniformExcitation 3 2 -accel 3
constraints Plain
numberer Plain
system UmfPack
test NormDispIncr 1.0e-10 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
set status [analyze $n $dt]
set report [expr {[namespace exists ::poundfe] ? [poundfe::report] : ""}]
puts "fibre_frame_3d: status $status time [getTime] $report"
