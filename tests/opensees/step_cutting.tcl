# Two sticks pounding through an ImpactMaterial gap (pounding_sticks.tcl's
# pair, Rayleigh damping in the sticks' springs) at a step at which
# Newton fails (50 iterations, NormDispIncr 1e-12) in the first impact.
# argv: the output directory, the mode (off: OpenSees's behaviour; on:
# poundfe::stepCutting on 6; fine: dt/16 throughout) and optionally the step.
set out [lindex $argv 0]
set mode [lindex $argv 1]
set dt [expr {$argc > 2 ? [lindex $argv 2] : 0.002}]
source [file join [file dirname [info script]] record.tcl]
wipe
model basic -ndm 1 -ndf 1
set pi 3.14159265358979
set m 1.0e5
node 1 0.0; node 2 0.0 -mass $m; node 3 0.0; node 4 0.0 -mass $m
fix 1 1; fix 3 1
uniaxialMaterial Elastic 1 [expr {$m * pow(2 * $pi / 0.5, 2)}]
uniaxialMaterial Elastic 2 [expr {$m * pow(2 * $pi / 1.0, 2)}]
uniaxialMaterial ImpactMaterial 3 2.0e9 6.0e8 -0.002 -0.01
element zeroLength 1 1 2 -mat 1 -dir 1 -doRayleigh 1
element zeroLength 2 3 4 -mat 2 -dir 1 -doRayleigh 1
rayleigh 0.3 1.0e-3 0.0 0.0
element zeroLength 3 2 4 -mat 3 -dir 1
set duration 4.0
set record_dt 0.002
timeSeries Path 1 -dt $record_dt -values [synthetic_record $record_dt [expr {int($duration / $record_dt)}] 0.6]
pattern UniformExcitation 1 1 -accel 1
recorder Node -file $out/cut_$mode.out -time -precision 16 -node 2 4 -dof 1 disp
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-12 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
if {$mode eq "on"} { poundfe::stepCutting on 6 }
if {$mode eq "fine"} { set dt [expr {$dt / 16}] }
set status [analyze [expr {int(round($duration / $dt))}] $dt]
puts "step_cutting $mode: status $status time [getTime]"
