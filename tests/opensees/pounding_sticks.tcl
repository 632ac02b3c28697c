# Two single-storey sticks (T = 0.5 s and 1.0 s, 5 % Rayleigh damping in
# their own springs) 10 mm apart, pounding through a zero-length gap under
# the synthetic record. argv: the output directory and the gap material,
# ElasticPPGap (elastic-plastic gap that stays damaged), ElasticPPGapK0 (the
# same gap with -doRayleigh 1 under damping on the initial stiffness), ImpactMaterial
# (Muthukumar-DesRoches bilinear contact), Hertzdamp, JankowskiImpact,
# ViscoelasticGap, Viscous (a nonlinear damper between the two, no gap),
# Parallel (half an ElasticPPGap beside half a ViscoelasticGap) or MinMax
# (the ImpactMaterial failing for good at 4 mm of closure, in its third
# impact), ViscousDamper (a brace and nonlinear damper linking the two,
# Dormand-Prince), ViscousDamperABM (Adams-Bashforth-Moulton, a pin's play
# LGap), ViscousDamperROS (Rosenbrock), Series (a yielding Steel01 link in
# series with an elastic brace) or SeriesIter (Steel01 and Steel02 links in
# series, -iter 10 1e-12); optionally the algorithm
# (Newton, the default, or ModifiedNewton) and the test (NormDispIncr, the
# default, EnergyIncr or RelativeNormDispIncr) and the integrator's words (Newmark 0.5 0.25, the
# default, or e.g. HHT 0.7).
set out [lindex $argv 0]
set law [lindex $argv 1]
set algorithm [expr {$argc > 2 ? [lindex $argv 2] : "Newton"}]
set test [expr {$argc > 3 ? [lindex $argv 3] : "NormDispIncr"}]
set integrator [expr {$argc > 4 ? [lindex $argv 4] : "Newmark 0.5 0.25"}]
source [file join [file dirname [info script]] record.tcl]
wipe
model basic -ndm 1 -ndf 1
set pi 3.14159265358979
set m 1.0e5
node 1 0.0
node 2 0.0 -mass $m
node 3 0.0
node 4 0.0 -mass $m
fix 1 1
fix 3 1
set k2 [expr {$m * pow(2 * $pi / 0.5, 2)}]
set k4 [expr {$m * pow(2 * $pi / 1.0, 2)}]
uniaxialMaterial Elastic 1 $k2 [expr {0.05 * 2 * sqrt($k2 * $m)}]
uniaxialMaterial Elastic 2 $k4 [expr {0.05 * 2 * sqrt($k4 * $m)}]
element zeroLength 1 1 2 -mat 1 -dir 1
element zeroLength 2 3 4 -mat 2 -dir 1
# the gap closes when node 2 moves 10 mm more than node 4 (u4 - u2 < -0.01);
# the gap's recorders: its material's stress, strain and tangent;
# the rate-dependent gaps with e = 0.6 for the effective mass m/2;
# Viscous: a fluid damper linking the two (no gap)
switch -- $law {
    ElasticPPGap { uniaxialMaterial ElasticPPGap 3 2.0e9 -4.0e6 -0.01 0.1 damage }
    ImpactMaterial { uniaxialMaterial ImpactMaterial 3 2.0e9 6.0e8 -0.002 -0.01 }
    Hertzdamp { uniaxialMaterial Hertzdamp 3 5.0e10 0.48 -0.01 }
    JankowskiImpact { uniaxialMaterial JankowskiImpact 3 5.0e10 0.35 [expr {$m / 2}] -0.01 1.5 }
    ViscoelasticGap { uniaxialMaterial ViscoelasticGap 3 2.0e9 4.0e6 -0.01 }
    Viscous { uniaxialMaterial Viscous 3 2.0e6 0.5 }
    Parallel {
        uniaxialMaterial ElasticPPGap 4 2.0e9 -4.0e6 -0.01 0.1 damage
        uniaxialMaterial ViscoelasticGap 5 2.0e9 4.0e6 -0.01
        uniaxialMaterial Parallel 3 4 5 -factors 0.5 0.5
    }
    ParallelViscous {
        uniaxialMaterial ElasticPPGap 4 2.0e9 -4.0e6 -0.01 0.1 damage
        uniaxialMaterial Viscous 5 2.0e6 0.8
        uniaxialMaterial Parallel 3 4 5 -factors 1.0 0.7
    }
    ElasticPPGapSigns { uniaxialMaterial ElasticPPGap 3 2.0e9 2.0e5 -0.01 }
    ElasticPPGapK0 { uniaxialMaterial ElasticPPGap 3 2.0e9 -4.0e6 -0.01 0.1 damage }
    MinMax {
        uniaxialMaterial ImpactMaterial 4 2.0e9 6.0e8 -0.002 -0.01
        uniaxialMaterial MinMax 3 4 -min -0.014
    }
    ViscousDamper { uniaxialMaterial ViscousDamper 3 1.0e8 2.0e6 0.5 }
    ViscousDamperABM { uniaxialMaterial ViscousDamper 3 1.0e8 2.0e6 0.35 0.002 2 1.0e-6 1.0e-10 15 }
    ViscousDamperROS { uniaxialMaterial ViscousDamper 3 1.0e8 2.0e6 0.5 0.0 3 1.0e-6 1.0e-10 15 }
    Series {
        uniaxialMaterial Steel01 4 2.0e5 5.0e7 0.05
        uniaxialMaterial Elastic 5 1.0e8
        uniaxialMaterial Series 3 4 5
    }
    SeriesIter {
        uniaxialMaterial Steel01 4 2.0e5 5.0e7 0.05
        uniaxialMaterial Steel02 5 2.5e5 1.0e8 0.02
        uniaxialMaterial Series 3 4 5 -iter 10 1.0e-12
    }
    default { error "pounding_sticks.tcl: no gap material '$law'" }
}
if {$law eq "ElasticPPGapK0"} {
    # damping on the initial stiffness, the gap's too: an open gap's is 0, not E
    element zeroLength 3 2 4 -mat 3 -dir 1 -doRayleigh 1
    rayleigh 0.0 0.0 2.0e-3 0.0
} else {
    element zeroLength 3 2 4 -mat 3 -dir 1
}
set dt 0.002
# bench/opensees/speed.py sets ::bench_steps for a longer run
set n [expr {[info exists ::bench_steps] ? $::bench_steps : 4000}]
timeSeries Path 1 -dt $dt -values [synthetic_record $dt $n 0.6]
pattern UniformExcitation 1 1 -accel 1
recorder Node -file $out/pounding_$law.out -time -precision 16 -node 2 4 -dof 1 disp
recorder Node -file $out/pounding_${law}_vel.out -time -precision 16 -node 2 4 -dof 1 vel
if {$law eq "MinMax"} {
    # OpenSees's MinMax reports its material's strain, frozen at the failure
    recorder Element -file $out/pounding_${law}_gap.out -time -precision 16 -ele 3 \
        material 1 stress
    recorder Element -file $out/pounding_${law}_gap_tangent.out -time -precision 16 -ele 3 \
        material 1 tangent
} else {
    recorder Element -file $out/pounding_${law}_gap.out -time -precision 16 -ele 3 \
        material 1 stressStrainTangent
}
constraints Plain
numberer Plain
system BandGeneral
if {$test eq "EnergyIncr"} {
    test EnergyIncr 1.0e-14 50
} elseif {$test eq "RelativeNormDispIncr"} {
    test RelativeNormDispIncr 1.0e-8 50
} else {
    test NormDispIncr 1.0e-10 50
}
algorithm {*}$algorithm
integrator {*}$integrator
analysis Transient
set status [analyze $n $dt]
# poundfe::report where poundfe runs the script (OpenSees has no poundfe::)
set report [expr {[namespace exists ::poundfe] ? [poundfe::report] : ""}]
puts "pounding $law: status $status time [getTime] $report"
