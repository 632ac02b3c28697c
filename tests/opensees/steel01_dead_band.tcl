# Steel01's dead band: a strain change of at most DBL_EPSILON from the
# committed strain keeps the committed state, tangent included (OpenSees 3.8,
# Steel01::setTrialStrain). A Steel01 twoNodeLink (fy 100, E0 1e5, b 0.02)
# is pushed onto its hardening branch (u = 0.003) by DisplacementControl,
# then takes a step of -1e-17, inside the band, then one Linear LoadControl
# step of +10 kN, which moves the link by 10 / tangent: 10 / (b E0) = 5e-3 if
# the hardening tangent is kept, 10 / E0 = 1e-4 if the tiny step is taken as
# an unloading. Then a cycle back through yield checks that the state after
# the band is the committed one.   argv: the output directory.
set out [lindex $argv 0]
wipe
model basic -ndm 2 -ndf 2
node 1 0.0 0.0
node 2 1.0 0.0
fix 1 1 1
fix 2 0 1
uniaxialMaterial Steel01 1 100.0 1.0e5 0.02
element twoNodeLink 1 1 2 -mat 1 -dir 1
timeSeries Linear 1
pattern Plain 1 1 { load 2 1.0 0.0 }
recorder Node -file $out/band_disp.out -time -precision 16 -node 2 -dof 1 disp
recorder Node -file $out/band_reaction.out -time -precision 16 -node 1 -dof 1 reaction
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-14 20
algorithm Newton
integrator DisplacementControl 2 1 0.0005
analysis Static
analyze 6
integrator DisplacementControl 2 1 -1.0e-17
analyze 1
algorithm Linear
integrator LoadControl 10.0
analyze 1
algorithm Newton
integrator DisplacementControl 2 1 -0.001
analyze 12
puts "steel01 dead band: u [nodeDisp 2 1]"
