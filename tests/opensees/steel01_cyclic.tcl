# A Steel01 zero-length spring (Fy = 100, E0 = 1000, b = 0.05) under a
# cyclic force protocol of growing amplitude (a Path series in load-factor
# time), LoadControl with Newton and NormUnbalance. argv: the output
# directory.
set out [lindex $argv 0]
wipe
model basic -ndm 1 -ndf 1
node 1 0.0
node 2 0.0
fix 1 1
uniaxialMaterial Steel01 1 100.0 1000.0 0.05
element zeroLength 1 1 2 -mat 1 -dir 1
set protocol {0.0}
foreach amplitude {50 90 110 130 150 150 170} {
    lappend protocol $amplitude [expr {-$amplitude}]
}
lappend protocol 0.0
timeSeries Path 1 -dt 1.0 -values $protocol
pattern Plain 1 1 {
    load 2 1.0
}
recorder Node -file $out/steel01_disp.out -time -precision 16 -node 2 -dof 1 disp
recorder Node -file $out/steel01_force.out -time -precision 16 -node 1 -dof 1 reaction
constraints Plain
numberer Plain
system BandGeneral
test NormUnbalance 1.0e-10 25
algorithm Newton
integrator LoadControl 0.02
analysis Static
analyze [expr {50 * ([llength $protocol] - 1)}]
