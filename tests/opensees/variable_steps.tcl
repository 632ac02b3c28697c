# analysis VariableTransient and Path series of non-uniform times: the two
# sticks of pounding_sticks.tcl (T = 0.5 s and 1.0 s) pounding through an
# ImpactMaterial gap, whose contacts take Newton more iterations, under the
# synthetic record sampled at uneven times (-time and -values in the
# script; -fileTime and -filePath from files the script writes), and a
# Plain pattern of a PathSeries with -startTime, -prependZero and -useLast
# pushing one stick. `analyze n dt dtMin dtMax Jd` (OpenSees's
# VariableTimeStepDirectIntegrationAnalysis: each step the last times Jd
# over the test's iterations, within [dtMin, dtMax]): the recorders' time
# column holds the steps taken. argv: the output directory and the series'
# form (list, the default, or files).
set out [lindex $argv 0]
set form [expr {$argc > 1 ? [lindex $argv 1] : "list"}]
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
uniaxialMaterial ImpactMaterial 3 2.0e9 6.0e8 -0.002 -0.01
element zeroLength 1 1 2 -mat 1 -dir 1
element zeroLength 2 3 4 -mat 2 -dir 1
element zeroLength 3 2 4 -mat 3 -dir 1
# the record at times t_i = dt (i + 2 sin(i / 7)): spacing from 0.71 dt to 1.29 dt
set dt 0.004
set n 1000
set values [synthetic_record $dt $n 0.8]
set times {}
for {set i 0} {$i <= $n} {incr i} {
    lappend times [expr {$dt * ($i + 2.0 * sin($i / 7.0))}]
}
if {$form eq "files"} {
    foreach {name list} [list record_times.txt $times record_values.txt $values] {
        set f [open $out/$name w]
        foreach v $list { puts $f $v }
        close $f
    }
    timeSeries Path 1 -fileTime $out/record_times.txt -filePath $out/record_values.txt -factor 1.5
} else {
    timeSeries Path 1 -time $times -values $values -factor 1.5
}
pattern UniformExcitation 1 1 -accel 1
# a push of 2e5 N from 0.5 s: ramps over 0.2 s, then held past the end of its values
timeSeries Path 2 -dt 0.1 -values {1.0 1.0} -startTime 0.5 -prependZero -useLast -factor 2.0e5
pattern Plain 2 2 { load 4 1.0 }
recorder Node -file $out/disp.out -time -precision 16 -node 2 4 -dof 1 disp
recorder Node -file $out/accel.out -time -precision 16 -timeSeries 1 -node 2 -dof 1 accel
recorder Element -file $out/gap.out -time -precision 16 -ele 3 force
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-10 8
algorithm Newton
integrator Newmark 0.5 0.25
analysis VariableTransient
set status [analyze 400 0.01 0.0005 0.02 3]
puts "variable_steps: status $status time [getTime]"
