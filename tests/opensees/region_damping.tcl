# Damping by region, and masses on elements: two planar frames 0.02 m apart
# (units kN, m, t). Frame A: a one-bay two-storey elastic frame (nodes 1-6,
# a twoNodeLink with -mass along the roof beam); frame B: a two-storey stick
# of elastic columns (nodes 7-9) standing on a twoNodeLink bearing (Steel01
# in shear, -doRayleigh, -mass); an ElasticPPGap twoNodeLink with -mass
# between the roofs. A `rayleigh` for the whole domain, then
#   region 1 -ele (frame A's members: their nodes too) -rayleigh aM, bKc,
#   region 2 -node (frame B's nodes: the columns whose nodes all are in it)
#     -rayleigh aM, bK0,
#   region 3 -eleOnly (the bearing: its mass, not its nodes) -rayleigh bK;
# the gap's mass and the roof link's take no alpha_M (no -doRayleigh), the
# bearing's takes region 3's (0). argv: the output directory, then
# "uniform" for one `rayleigh` after the regions (which clears them:
# OpenSees sets every element's and node's factors), or "ranges" for
# region 2 given by -eleRange and -nodeOnlyRange.
set out [lindex $argv 0]
set variant [expr {$argc > 1 ? [lindex $argv 1] : "regions"}]
source [file join [file dirname [info script]] record.tcl]
wipe
model basic -ndm 2 -ndf 3
# frame A (its roof beam's mass on a twoNodeLink along it)
node 1 0.0 0.0
node 2 6.0 0.0
node 3 0.0 3.0 -mass 20.0 20.0 0.0
node 4 6.0 3.0 -mass 20.0 20.0 0.0
node 5 0.0 6.0 -mass 15.0 15.0 0.0
node 6 6.0 6.0 -mass 15.0 15.0 0.0
fix 1 1 1 1
fix 2 1 1 1
geomTransf Linear 1
foreach {tag i j} {1 1 3  2 2 4  3 3 5  4 4 6} {
    element elasticBeamColumn $tag $i $j 0.16 3.0e7 2.13e-3 1
}
element elasticBeamColumn 5 3 4 0.15 3.0e7 3.13e-3 1
element elasticBeamColumn 6 5 6 0.15 3.0e7 3.13e-3 1
uniaxialMaterial Elastic 13 1.0e5
element twoNodeLink 12 5 6 -mat 13 -dir 1 -mass 6.0
# frame B on its bearing (node 10 fixed, 7 its top)
node 10 6.02 0.0
node 7 6.02 0.2
node 8 6.02 3.2 -mass 30.0 30.0 0.0
node 9 6.02 6.2 -mass 25.0 25.0 0.0
fix 10 1 1 1
element elasticBeamColumn 7 7 8 0.2 3.0e7 1.5e-3 1
element elasticBeamColumn 8 8 9 0.2 3.0e7 1.2e-3 1
uniaxialMaterial Elastic 10 5.0e7
uniaxialMaterial Steel01 11 150.0 6.0e4 0.05
uniaxialMaterial Elastic 12 1.0e6
element twoNodeLink 10 10 7 -mat 10 11 12 -dir 1 2 3 -doRayleigh -mass 4.0
# the gap between the roofs, with a mass of its own
uniaxialMaterial ElasticPPGap 20 2.0e6 -3.0e3 -0.02 0.1 damage
element twoNodeLink 11 6 9 -mat 20 -dir 1 -mass 0.6
rayleigh 0.1 0.0 0.0 0.001
region 1 -ele 1 2 3 4 5 6 12 -rayleigh 0.5 0.0 0.0 0.002
region 2 -node 7 8 9 -rayleigh 0.3 0.0 0.004 0.0
region 3 -eleOnly 10 -rayleigh 0.0 0.001 0.0 0.0
if {$variant eq "uniform"} {
    rayleigh 0.1 0.0 0.0 0.001
}
set dt 0.005
set steps 1200
timeSeries Path 1 -dt $dt -values [synthetic_record $dt $steps 2.0]
pattern UniformExcitation 1 1 -accel 1
recorder Node -file $out/region_disp.out -time -precision 16 -node 5 6 8 9 7 -dof 1 disp
recorder Element -file $out/region_gap.out -time -precision 16 -ele 11 10 basicForce
recorder Node -file $out/region_base.out -time -precision 16 -node 1 2 10 -dof 1 reaction
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-10 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
set status [analyze $steps $dt]
puts "region damping: status $status roof A [nodeDisp 5 1] roof B [nodeDisp 9 1]"
