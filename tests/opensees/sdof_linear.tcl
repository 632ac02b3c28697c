# A linear SDOF (m = 2, k = 800: omega = 20 rad/s) on a zero-length elastic
# spring, 5 % Rayleigh damping, under the synthetic record; average
# acceleration, algorithm Linear. argv: the output directory.
set out [lindex $argv 0]
source [file join [file dirname [info script]] record.tcl]
wipe
model basic -ndm 1 -ndf 1
node 1 0.0
node 2 0.0 -mass 2.0
fix 1 1
uniaxialMaterial Elastic 1 800.0
element zeroLength 1 1 2 -mat 1 -dir 1 -doRayleigh 1
set dt 0.01
set n 1000
timeSeries Path 1 -dt $dt -values [synthetic_record $dt $n]
pattern UniformExcitation 1 1 -accel 1
set omega 20.0
set xi 0.05
rayleigh [expr {$xi * $omega}] [expr {$xi / $omega}] 0.0 0.0
recorder Node -file $out/sdof_disp.out -time -precision 16 -node 2 -dof 1 disp
recorder Node -file $out/sdof_accel.out -time -precision 16 -node 2 -dof 1 accel
constraints Plain
numberer Plain
system BandGeneral
algorithm Linear
integrator Newmark 0.5 0.25
analysis Transient
analyze $n $dt
puts "sdof: time [getTime] disp [nodeDisp 2 1]"
