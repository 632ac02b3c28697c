# The cost of poundfe::energy and poundfe::impacts (doc/benchmarks.md): a 1D
# pounding pair (two masses on springs, an ImpactMaterial gap), 2000 steps
# of 5 ms under a ramp of ground acceleration. argv: loop (a Tcl loop of
# `analyze 1 dt`) or single (one `analyze 2000 dt`), then on (both observers
# on) or off (none: the script is OpenSees's).
lassign $argv stepping observers
wipe
model basic -ndm 1 -ndf 1
node 1 0.0; node 2 0.0 -mass 2.0e3; node 3 0.0; node 4 0.0 -mass 3.0e3
fix 1 1; fix 3 1
uniaxialMaterial Elastic 1 2.0e6; uniaxialMaterial Elastic 2 5.0e5
uniaxialMaterial ImpactMaterial 3 5e7 1e7 -0.0005 -0.002
element zeroLength 1 1 2 -mat 1 -dir 1
element zeroLength 2 3 4 -mat 2 -dir 1
element zeroLength 3 2 4 -mat 3 -dir 1
timeSeries Path 1 -time {0.0 0.3 0.6 20.0} -values {0.0 3.0 -3.0 0.0}
pattern UniformExcitation 1 1 -accel 1
rayleigh 0.2 0.0 0.001 0.0
constraints Plain; numberer Plain; system UmfPack; test NormDispIncr 1e-12 50; algorithm Newton
integrator Newmark 0.5 0.25; analysis Transient
if {$observers eq "on"} { poundfe::energy on; poundfe::impacts on }
if {$stepping eq "loop"} {
    for {set i 0} {$i < 2000} {incr i} { analyze 1 0.005 }
} else {
    analyze 2000 0.005
}
puts "u4 [nodeDisp 4 1]"
