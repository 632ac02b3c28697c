# Snap-through of a shallow two-member arch (a von Mises truss of
# corotational elastic beams pinned at the supports) under a load at its
# apex, followed past its limit point, down the unstable branch and up again
# by ArcLength s alpha. The recorder's time is the load factor lambda.
# argv: the output directory <s alpha <steps <the constraints handler's words>>>.
set out [lindex $argv 0]
set s [expr {[llength $argv] > 1 ? [lindex $argv 1] : 0.01}]
set alpha [expr {[llength $argv] > 2 ? [lindex $argv 2] : 0.0005}]
set steps [expr {[llength $argv] > 3 ? [lindex $argv 3] : 45}]
set handler [expr {[llength $argv] > 4 ? [lrange $argv 4 end] : "Plain"}]
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0
node 2 1.0 0.1
node 3 2.0 0.0
fix 1 1 1 0
fix 3 1 1 0
geomTransf Corotational 1
element elasticBeamColumn 1 1 2 1.0 200000.0 1.0e-4 1
element elasticBeamColumn 2 2 3 1.0 200000.0 1.0e-4 1
timeSeries Linear 1
pattern Plain 1 1 {
    load 2 0.0 -1.0 0.0
}
recorder Node -file $out/apex.out -time -precision 16 -node 2 -dof 2 disp
recorder Node -file $out/support.out -time -precision 16 -node 1 -dof 1 2 reaction
constraints {*}$handler
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-12 30
algorithm Newton
integrator ArcLength $s $alpha
analysis Static
set ok [analyze $steps]
puts "arch: analyze $ok lambda [getTime] apex [nodeDisp 2 2]"
