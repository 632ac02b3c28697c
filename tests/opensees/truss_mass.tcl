# A yielding two-bay truss with its bars' mass (truss -rho, lumped: rho L/2
# on each end's translations) under the synthetic record: the supports'
# reactions take the bars' ground-motion load, -m a_g at the support's end
# (OpenSees's Truss::getResistingForce subtracts it), besides the nodes'
# own masses; Rayleigh damping with alpha_M on the bars of -doRayleigh 1
# only.   argv: the output directory.
set out [lindex $argv 0]
source [file join [file dirname [info script]] record.tcl]
wipe
model basic -ndm 2 -ndf 2
node 1 0.0 0.0
node 2 4.0 0.0
node 3 2.0 3.0 -mass 5.0 5.0
node 4 6.0 3.0 -mass 3.0 3.0
fix 1 1 1
fix 2 1 1
uniaxialMaterial Steel01 1 2.0e5 2.0e8 0.02
uniaxialMaterial Elastic 2 2.0e8
element truss 1 1 3 0.001 1 -rho 0.8
element truss 2 2 3 0.001 1 -rho 0.8 -doRayleigh 1
element truss 3 3 4 0.001 2 -rho 1.5
element truss 4 2 4 0.001 2 -rho 1.5 -doRayleigh 1
rayleigh 0.7 0.0 0.0 0.001
timeSeries Path 2 -dt 0.01 -values [synthetic_record 0.01 600 4.0]
pattern UniformExcitation 2 1 -accel 2
recorder Node -file $out/truss_disp.out -time -precision 16 -node 3 4 -dof 1 2 disp
recorder Node -file $out/truss_reaction.out -time -precision 16 -node 1 2 -dof 1 2 reaction
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-11 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
puts "truss mass: status [analyze 600 0.01] roof [nodeDisp 4 1]"
