# A ViscousDamper (K 2e8, C 4e6, Alpha 0.3) between a fixed node and a node
# of 1e12 kg, which a ground acceleration of -60 m/s^2 over 0.005 s (ramped
# off over the next step) sets moving at 0.3 m/s: the damper's force rises
# from 0 to C v^Alpha at a velocity its own force barely changes (1.4e-6 of
# the inertia). argv: the output directory and the integration, ABM
# (Adams-Bashforth-Moulton, RelTol 1e-6, AbsTol 1e-10) or exact
# (Dormand-Prince, RelTol and AbsTol 1e-12, MaxHalf 20).
set out [lindex $argv 0]
set method [lindex $argv 1]
wipe
model basic -ndm 1 -ndf 1
node 1 0.0
node 2 0.0 -mass 1.0e12
fix 1 1
switch -- $method {
    ABM { uniaxialMaterial ViscousDamper 1 2.0e8 4.0e6 0.3 0.0 2 1.0e-6 1.0e-10 15 }
    exact { uniaxialMaterial ViscousDamper 1 2.0e8 4.0e6 0.3 0.0 1 1.0e-12 1.0e-12 20 }
    default { error "damper_onset.tcl: no method '$method'" }
}
element zeroLength 1 1 2 -mat 1 -dir 1
set dt 0.005
timeSeries Path 1 -dt $dt -values {-60.0 -60.0 0.0 0.0}
pattern UniformExcitation 1 1 -accel 1
recorder Node -file $out/damper_onset_vel.out -time -precision 16 -node 2 -dof 1 vel
recorder Element -file $out/damper_onset_force.out -time -precision 16 -ele 1 material 1 stress
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-12 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
set status [analyze 400 $dt]
puts "damper_onset $method: status $status time [getTime]"
