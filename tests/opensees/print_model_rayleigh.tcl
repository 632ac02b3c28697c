# Node text after a transient analysis with Rayleigh damping (print -node
# after 25 Newmark steps of a portal frame under a ground acceleration), and
# which vectors a node shows before it. OpenSees 3.8's own file of this
# script is print_model_opensees/nodes_rayleigh.txt.
set out [lindex $argv 0]
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0
node 2 0.0 3.2 -mass 4.0 4.0 0.0
node 3 6.0 3.2 -mass 4.0 4.0 0.0
node 4 6.0 0.0
fix 1 1 1 1
fix 4 1 1 1
geomTransf PDelta 1
uniaxialMaterial Steel01 1 350.0 2.0e5 0.02
section Fiber 2 { patch rect 1 6 1 -0.15 -0.1 0.15 0.1 }
beamIntegration Lobatto 1 2 4
element forceBeamColumn 1 1 2 1 1
element dispBeamColumn 2 4 3 1 1
element elasticBeamColumn 3 2 3 0.02 2.0e5 1.0e-4 1
element truss 4 1 3 0.001 1
# before any analysis: node 5, which nothing holds yet, has no Disps; nodes 6
# and 7 keep the Velocities their truss gave them after it is removed
node 5 9.0 0.0
node 6 9.0 3.0
node 7 12.0 3.0
element truss 6 6 7 0.001 1
remove element 6
print -file [file join $out nodes_rayleigh.txt] -node 5 6
fix 5 1 1 1
fix 6 1 1 1
fix 7 1 1 1
rayleigh 0.1 0.0 0.002 0.0
timeSeries Path 1 -dt 0.02 -values {0.0 0.3 0.8 0.2 -0.5 -0.9 -0.1 0.6 0.4 0.0 -0.2 0.1 0.0} -factor 9.81
pattern UniformExcitation 1 1 -accel 1
constraints Plain
numberer Plain
system UmfPack
test NormDispIncr 1e-10 30
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
analyze 25 0.01
print -file [file join $out nodes_rayleigh.txt] -node 1 2 3 4 5
