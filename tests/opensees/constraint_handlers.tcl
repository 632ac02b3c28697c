# One storey of a 3D frame of elastic members whose floor is a
# rigidDiaphragm about its centre node (which carries the storey's mass and
# rotational inertia), beside a neighbour column whose top follows the
# centre's Y by equalDOF and carries, by rigidLink bar, the top of a second
# column: gravity by LoadControl, then the synthetic record along X and 0.6
# of it along Y with mass-proportional Rayleigh damping. The constraints are
# imposed by the handler of the script's argv: Transformation,
# Lagrange <alphaSP alphaMP> or Penalty alphaSP alphaMP; with -cornerMass m
# each corner carries m in the floor's plane, which only Penalty takes;
# with -release, halfway through the record `remove mp 11` takes a corner
# out of the diaphragm and `remove mp 22` frees the neighbour's top.
# argv: the output directory <-cornerMass m> <-release> <handler words>.
set out [lindex $argv 0]
set words [lrange $argv 1 end]
set corner_mass 0.0
if {[lindex $words 0] eq "-cornerMass"} {
    set corner_mass [lindex $words 1]
    set words [lrange $words 2 end]
}
set release 0
if {[lindex $words 0] eq "-release"} {
    set release 1
    set words [lrange $words 1 end]
}
set handler [expr {[llength $words] > 0 ? $words : "Transformation"}]
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
    node [expr {$n + 10}] $x $y $h -mass $corner_mass $corner_mass 0.0 0.0 0.0 0.0
    incr n
}
node 15 [expr {$b / 2}] [expr {$b / 2}] $h -mass [expr {4 * $m}] [expr {4 * $m}] 0.0 0.0 0.0 \
    [expr {4 * $m * $b * $b / 6}]
fix 15 0 0 1 1 1 0
rigidDiaphragm 3 15 11 12 13 14
# the neighbour: its top follows the centre's Y; a second column's top
# follows it by a rigid bar
node 21 [expr {$b + 1.0}] [expr {$b / 2}] 0.0
node 22 [expr {$b + 1.0}] [expr {$b / 2}] $h -mass $m $m $m 0.0 0.0 0.0
node 23 [expr {$b + 1.0}] [expr {$b / 2 + 2.0}] 0.0
node 24 [expr {$b + 1.0}] [expr {$b / 2 + 2.0}] $h -mass $m $m $m 0.0 0.0 0.0
fix 21 1 1 1 1 1 1
fix 23 1 1 1 1 1 1
equalDOF 15 22 2
rigidLink bar 22 24
geomTransf Linear 1 1.0 0.0 0.0
geomTransf Linear 2 0.0 0.0 1.0
for {set i 1} {$i <= 4} {incr i} {
    element elasticBeamColumn $i $i [expr {$i + 10}] $A $E $G $J $I $I 1
}
element elasticBeamColumn 5 11 12 $A $E $G $J $I [expr {2 * $I}] 2
element elasticBeamColumn 6 12 13 $A $E $G $J $I [expr {2 * $I}] 2
element elasticBeamColumn 7 13 14 $A $E $G $J $I [expr {2 * $I}] 2
element elasticBeamColumn 8 14 11 $A $E $G $J $I [expr {2 * $I}] 2
element elasticBeamColumn 9 21 22 0.09 $E $G 1.1e-3 6.75e-4 6.75e-4 1
element elasticBeamColumn 10 23 24 0.09 $E $G 1.1e-3 6.75e-4 6.75e-4 1
pattern Plain 1 Linear {
    foreach node {11 12 13 14} { load $node 0.0 0.0 [expr {-$m * $g}] 0.0 0.0 0.0 }
    load 22 0.0 0.0 [expr {-$m * $g}] 0.0 0.0 0.0
    load 24 0.0 0.0 [expr {-$m * $g}] 0.0 0.0 0.0
}
constraints {*}$handler
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-8 50
algorithm Newton
integrator LoadControl 0.1
analysis Static
analyze 10
loadConst -time 0.0
wipeAnalysis
rayleigh 0.3 0.0 0.0 0.0
set dt 0.005
set steps 1200
timeSeries Path 2 -dt $dt -values [synthetic_record $dt $steps 1.5]
timeSeries Path 3 -dt $dt -values [synthetic_record $dt $steps 0.9]
pattern UniformExcitation 2 1 -accel 2
pattern UniformExcitation 3 2 -accel 3
recorder Node -file $out/handler_disp.out -time -precision 16 -node 15 11 22 24 -dof 1 2 3 6 disp
recorder Node -file $out/handler_base.out -time -precision 16 -node 1 21 23 -dof 1 2 3 reaction
recorder Element -file $out/handler_column.out -time -precision 16 -ele 1 9 10 localForce
constraints {*}$handler
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-8 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
if {$release} {
    set status [analyze [expr {$steps / 2}] $dt]
    remove mp 11
    remove mp 22
    incr status [analyze [expr {$steps / 2}] $dt]
} else {
    set status [analyze $steps $dt]
}
puts "constraint_handlers: status $status time [getTime] centre [nodeDisp 15 1]"
