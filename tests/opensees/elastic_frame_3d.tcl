# A one-storey, one-bay-by-one-bay 3D frame of elastic members (columns
# geomTransf PDelta with vecxz along X, beams Linear with vecxz along Z),
# masses and rotational inertia at the four top nodes, beside a single 3D
# column (a stick of the neighbour) reached through a twoNodeLink gap of
# 20 mm along X; gravity by LoadControl, then the synthetic record along X
# and 0.6 of it along Y, Rayleigh on mass and committed stiffness.
# argv: the output directory.
set out [lindex $argv 0]
source [file join [file dirname [info script]] record.tcl]
wipe
model basic -ndm 3 -ndf 6
set h 3.2
set b 5.0
set m 1.5e4
set g 9.81
set A 0.16; set E 3.0e10; set G 1.25e10; set J 3.6e-3; set I 2.13e-3
set n 1
foreach {x y} [list 0.0 0.0 $b 0.0 $b $b 0.0 $b] {
    node $n $x $y 0.0
    fix $n 1 1 1 1 1 1
    node [expr {$n + 10}] $x $y $h -mass $m $m $m 0.0 0.0 0.0
    incr n
}
# the neighbour: one column at 0.3 m beyond the frame's x = b side
node 21 [expr {$b + 0.3}] [expr {$b / 2}] 0.0
fix 21 1 1 1 1 1 1
node 22 [expr {$b + 0.3}] [expr {$b / 2}] $h -mass [expr {2 * $m}] [expr {2 * $m}] [expr {2 * $m}] \
    1.0e3 1.0e3 1.0e3
geomTransf PDelta 1 1.0 0.0 0.0
geomTransf Linear 2 0.0 0.0 1.0
for {set i 1} {$i <= 4} {incr i} {
    element elasticBeamColumn $i $i [expr {$i + 10}] $A $E $G $J $I $I 1
}
element elasticBeamColumn 5 11 12 $A $E $G $J $I [expr {2 * $I}] 2
element elasticBeamColumn 6 12 13 $A $E $G $J $I [expr {2 * $I}] 2
element elasticBeamColumn 7 13 14 $A $E $G $J $I [expr {2 * $I}] 2 -mass 400.0
element elasticBeamColumn 8 14 11 $A $E $G $J $I [expr {2 * $I}] 2 -mass 400.0
element elasticBeamColumn 9 21 22 0.09 $E $G 1.1e-3 6.75e-4 6.75e-4 1
# the gap: from the frame's corner 12 to the neighbour's top, along X
uniaxialMaterial ElasticPPGap 1 4.0e8 -2.0e6 -0.02 0.1
element twoNodeLink 10 12 22 -mat 1 -dir 1 -orient 1.0 0.0 0.0 0.0 1.0 0.0
pattern Plain 1 Linear {
    foreach node {11 12 13 14} { load $node 0.0 0.0 [expr {-$m * $g}] 0.0 0.0 0.0 }
    load 22 0.0 0.0 [expr {-2 * $m * $g}] 0.0 0.0 0.0
}
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-10 50
algorithm Newton
integrator LoadControl 0.1
analysis Static
analyze 10
loadConst -time 0.0
wipeAnalysis
rayleigh 0.3 0.0 0.0 0.003
set dt 0.005
set steps 1600
timeSeries Path 2 -dt $dt -values [synthetic_record $dt $steps 1.5]
timeSeries Path 3 -dt $dt -values [synthetic_record $dt $steps 0.9]
pattern UniformExcitation 2 1 -accel 2
pattern UniformExcitation 3 2 -accel 3
recorder Node -file $out/frame3d_disp.out -time -precision 16 -node 11 12 13 22 -dof 1 2 3 6 disp
recorder Node -file $out/frame3d_base.out -time -precision 16 -node 1 2 21 -dof 1 2 6 reaction
recorder Element -file $out/frame3d_gap.out -time -precision 16 -ele 10 basicForce
recorder Element -file $out/frame3d_column.out -time -precision 16 -ele 1 localForce
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-10 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
set status [analyze $steps $dt]
puts "elastic_frame_3d: status $status time [getTime]"
