# printModel and print: a 2D and a 3D model of every kind whose fields
# poundfe writes in OpenSees's JSON layout (the beam-columns with each
# integration), each written with
# `printModel -JSON -file`, and the text of nodes not on a zeroLength
# (`print -file f -node`, appended) before any analysis.
# argv: the output directory.
set out [lindex $argv 0]
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0
node 2 0.0 3.5 -mass 12.5 12.5 0.0
node 3 4.25 3.5
mass 3 7.5 7.5 0.25
node 4 4.25 0.0
node 5 8.0 0.0
node 6 8.0 0.0
fix 1 1 1 1
fix 4 1 1 1
fix 5 1 1 1
geomTransf Linear 1
geomTransf PDelta 2
geomTransf Corotational 3
uniaxialMaterial Elastic 1 2.5e5
uniaxialMaterial Elastic 2 2.5e5 12.5 1.25e5
uniaxialMaterial ElasticPP 3 2.0e5 0.002
uniaxialMaterial ElasticPP 4 2.0e5 0.002 -0.001 0.0005
uniaxialMaterial ElasticPPGap 5 1.0e6 250.0 0.01 0.125 damage
uniaxialMaterial Steel01 6 355.0 2.1e5 0.02
uniaxialMaterial Steel01 7 355.0 2.1e5 0.02 0.01 2.0 0.03 4.0
uniaxialMaterial Steel02 8 355.0 2.1e5 0.02
uniaxialMaterial Steel02 9 355.0 2.1e5 0.02 18.5 0.9 0.125
uniaxialMaterial MinMax 10 1 -min -0.05 -max 0.0625
uniaxialMaterial Series 11 1 2
section Elastic 1 2.1e11 0.0125 2.5e-4
element elasticBeamColumn 1 1 2 0.0125 2.1e11 2.5e-4 1
element elasticBeamColumn 2 2 3 0.0125 2.1e11 2.5e-4 2 -mass 12.5
element elasticBeamColumn 3 4 3 0.0125 2.1e11 2.5e-4 3
element truss 4 1 3 0.005 6
element truss 5 2 4 0.005 7 -rho 2.5
element zeroLength 6 5 6 -mat 1 3 9 -dir 1 2 3
element zeroLength 7 5 6 -mat 10 -dir 1 -orient 0 1 0 -1 0 0
node 7 12.0 0.0
node 8 12.0 3.5
node 9 12.0 3.5
fix 7 1 1 1
section Elastic 2 2.0e11 0.015 3.5e-4
beamIntegration Lobatto 1 1 5
beamIntegration HingeRadau 2 1 0.25 2 0.375 1
element forceBeamColumn 8 7 8 1 1 -mass 2.5
element dispBeamColumn 9 7 8 4 2 2
element forceBeamColumn 10 7 8 2 2
element corotTruss 11 7 8 0.005 8 -rho 1.5
element zeroLengthSection 12 8 9 2 -orient 0 1 0 -1 0 0
printModel -JSON -file [file join $out model_2d.json]
print -file [file join $out nodes.txt] -node 1 2 3
print -file [file join $out nodes.txt] -node 4

wipe
model basic -ndm 3 -ndf 6
node 1 0.0 0.0 0.0
node 2 0.0 0.0 3.5 -mass 12.5 12.5 0.0 0.0 0.0 0.5
node 3 4.0 0.0 3.5
node 4 4.0 0.0 3.5
fix 1 1 1 1 1 1 1
geomTransf Linear 1 1.0 0.0 0.0
geomTransf PDelta 2 0.0 2.0 2.0
geomTransf Corotational 3 0.0 1.0 0.0
uniaxialMaterial Elastic 1 2.5e5
section Elastic 1 2.1e11 0.0125 2.5e-4 1.25e-4 8.0e10 3.75e-4
element elasticBeamColumn 1 1 2 0.0125 2.1e11 8.0e10 3.75e-4 1.25e-4 2.5e-4 1
element elasticBeamColumn 2 2 3 0.0125 2.1e11 8.0e10 3.75e-4 1.25e-4 2.5e-4 3
element zeroLength 3 3 4 -mat 1 1 1 -dir 1 3 5 -orient 0 1 0 -1 0 0
beamIntegration Legendre 1 1 3
element forceBeamColumn 4 1 3 2 1 -mass 0.75
printModel -JSON -file [file join $out model_3d.json]
print -file [file join $out nodes.txt] -node 2
