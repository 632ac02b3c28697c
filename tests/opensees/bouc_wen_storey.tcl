# A single-storey stick (m = 1e5 kg, T = 0.5 s, u_y = 10 mm) whose storey is
# OpenSees's BoucWen (alpha 0.1, n 2, beta = gamma = 0.5 / u_y^2, Ao 1) with
# a dashpot beside it, under the synthetic record scaled to yield it.
# argv: the output directory, then "degrading" for Baber-Noori degradation
# (deltaA = deltaNu = deltaEta = 0.05 per (1 - alpha) k u_y^2 of energy).
set out [lindex $argv 0]
set degrading [expr {$argc > 1 && [lindex $argv 1] eq "degrading"}]
source [file join [file dirname [info script]] record.tcl]
wipe
model basic -ndm 1 -ndf 1
set pi 3.14159265358979
set m 1.0e5
set uy 0.01
set k [expr {$m * pow(2 * $pi / 0.5, 2)}]
set delta [expr {$degrading ? 0.05 / (0.9 * $k * $uy * $uy) : 0.0}]
node 1 0.0
node 2 0.0 -mass $m
fix 1 1
set shape [expr {0.5 / ($uy * $uy)}]
uniaxialMaterial BoucWen 1 0.1 $k 2.0 $shape $shape 1.0 $delta $delta $delta 1.0e-10 30
uniaxialMaterial Elastic 2 0.0 [expr {0.02 * 2 * sqrt($k * $m)}]
element zeroLength 1 1 2 -mat 1 -dir 1
element zeroLength 2 1 2 -mat 2 -dir 1
set dt 0.005
set n 1600
timeSeries Path 1 -dt $dt -values [synthetic_record $dt $n 0.4]
pattern UniformExcitation 1 1 -accel 1
recorder Node -file $out/bouc_wen_disp.out -time -precision 16 -node 2 -dof 1 disp
recorder Element -file $out/bouc_wen_storey.out -time -precision 16 -ele 1 \
    material 1 stressStrainTangent
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-12 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
set status [analyze $n $dt]
puts "bouc_wen_storey: status $status time [getTime]"
