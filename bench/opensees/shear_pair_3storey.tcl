# Two three-storey shear buildings (storey masses 1e5 kg, storey stiffness
# 1.2e8 and 4e7 N/m: first periods 0.41 s and 0.71 s, a dashpot in every
# storey spring) 10 mm apart at every floor, pounding through zero-length
# ImpactMaterial gaps (K1 5e8, K2 1.5e8 N/m, yield at 2 mm of closure);
# Node recorders of every floor's displacement and velocity, an Element
# recorder of the gaps' forces. A second pounding script for
# bench/opensees/speed.py beside the corpus's pounding_sticks.tcl.
# argv: the output directory.
set out [lindex $argv 0]
source [file join [file dirname [info script]] .. .. tests opensees record.tcl]
wipe
model basic -ndm 1 -ndf 1
set m 1.0e5
node 1 0.0
node 5 0.0
fix 1 1
fix 5 1
foreach {base k} {1 1.2e8 5 4.0e7} {
    for {set floor 1} {$floor <= 3} {incr floor} {
        node [expr {$base + $floor}] 0.0 -mass $m
        set tag [expr {10 * $base + $floor}]
        uniaxialMaterial Elastic $tag $k [expr {0.05 * 2 * sqrt($k * $m) / 3}]
        element zeroLength $tag [expr {$base + $floor - 1}] [expr {$base + $floor}] \
            -mat $tag -dir 1
    }
}
# the gaps close when building A's floor moves 10 mm more than B's
uniaxialMaterial ImpactMaterial 101 5.0e8 1.5e8 -0.002 -0.01
uniaxialMaterial ImpactMaterial 102 5.0e8 1.5e8 -0.002 -0.01
uniaxialMaterial ImpactMaterial 103 5.0e8 1.5e8 -0.002 -0.01
for {set floor 1} {$floor <= 3} {incr floor} {
    element zeroLength [expr {100 + $floor}] [expr {1 + $floor}] [expr {5 + $floor}] \
        -mat [expr {100 + $floor}] -dir 1
}
set dt 0.002
set n [expr {[info exists ::bench_steps] ? $::bench_steps : 4000}]
timeSeries Path 1 -dt $dt -values [synthetic_record $dt $n 0.6]
pattern UniformExcitation 1 1 -accel 1
recorder Node -file $out/floors_disp.out -time -precision 16 -node 2 3 4 6 7 8 -dof 1 disp
recorder Node -file $out/floors_vel.out -time -precision 16 -node 2 3 4 6 7 8 -dof 1 vel
recorder Element -file $out/gaps.out -time -precision 16 -ele 101 102 103 force
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-10 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
set status [analyze $n $dt]
set report [expr {[namespace exists ::poundfe] ? [poundfe::report] : ""}]
puts "shear pair 3 storeys: status $status time [getTime] $report"
