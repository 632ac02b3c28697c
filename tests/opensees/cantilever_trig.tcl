# A 2D cantilever of two elasticBeamColumn elements with distributed mass
# (-mass: lumped) under a harmonic tip load (timeSeries Trig with a phase
# shift and a -factor, pattern Plain), 3 % Rayleigh damping on the current
# stiffness; Newmark with gamma 0.6 (numerical damping), Newton, EnergyIncr.
# argv: the output directory.
set out [lindex $argv 0]
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0
node 2 0.0 2.0
node 3 0.0 4.0 -mass 500.0 500.0 0.0
fix 1 1 1 1
geomTransf Linear 1
element elasticBeamColumn 1 1 2 0.02 2.0e11 1.0e-4 1 -mass 150.0
element elasticBeamColumn 2 2 3 0.02 2.0e11 1.0e-4 1 -mass 150.0
timeSeries Trig 1 0.1 1.5 0.25 -factor 2.0e4 -shift 0.3
pattern Plain 1 1 {
    load 3 1.0 0.0 0.0
}
rayleigh 0.0 0.0015 0.0 0.0
recorder Node -file $out/cantilever_disp.out -time -precision 16 -node 2 3 -dof 1 3 disp
recorder Node -file $out/cantilever_vel.out -time -precision 16 -node 3 -dof 1 vel
test EnergyIncr 1.0e-20 10
algorithm Newton
integrator Newmark 0.6 0.3025
analysis Transient
analyze 400 0.005
puts "cantilever: tip [nodeDisp 3 0]"
