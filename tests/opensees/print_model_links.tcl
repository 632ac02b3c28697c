# printModel -JSON of Hysteretic materials (three-point and two-point
# envelopes), section Fiber (patch rect, quad and circ, layer straight,
# fiber; the fibres in OpenSees's order and the sectionRepr), section
# Aggregator and twoNodeLinks (2D: along the nodes, -shearDist, -pDelta, -doRayleigh,
# -mass, -orient; 3D: -orient x and yp), against OpenSees 3.8's files
# (print_model_opensees/model_links_2d.json, model_links_3d.json).
#   argv: the output directory.
set out [lindex $argv 0]
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0
node 2 0.0 3.0
node 3 0.0 3.0
node 4 1.0 3.5
fix 1 1 1 1
uniaxialMaterial Hysteretic 1 100.0 0.001 150.0 0.01 160.0 0.05 \
    -80.0 -0.001 -120.0 -0.01 -128.0 -0.05 0.8 0.2 0.01 0.02 0.3
uniaxialMaterial Hysteretic 2 100.0 0.001 150.0 0.01 -80.0 -0.002 -120.0 -0.03 0.9 0.1 0.0 0.0
uniaxialMaterial Elastic 3 2.0e8
uniaxialMaterial Steel01 4 400.0 2.0e8 0.01
section Elastic 1 2.0e8 0.12 1.6e-3
section Aggregator 2 4 Mz 3 P
section Fiber 5 {
    layer straight 4 3 5.0e-4 -0.17 -0.12 -0.17 0.12
    patch rect 3 4 2 -0.2 -0.15 0.2 0.15
    fiber 0.1 0.05 1.0e-4 4
    patch quad 3 2 2 -0.25 -0.15 -0.2 -0.15 -0.2 0.15 -0.25 0.15
}
element twoNodeLink 2 2 4 -mat 1 3 -dir 1 2
element twoNodeLink 3 3 4 -mat 2 3 -dir 2 3 -shearDist 0.4 -pDelta 0.3 0.7 -doRayleigh \
    -mass 2.0 -orient 0.0 1.0 0.0
element zeroLengthSection 4 2 3 2
printModel -JSON -file [file join $out model_links_2d.json]

wipe
model basic -ndm 3 -ndf 6
node 1 0.0 0.0 0.0
node 2 1.0 2.0 3.0
fix 1 1 1 1 1 1 1
uniaxialMaterial Hysteretic 1 100.0 0.001 150.0 0.01 -80.0 -0.002 -120.0 -0.03 0.9 0.1 0.0 0.0 0.2
uniaxialMaterial Elastic 2 5.0e4
section Fiber 3 -GJ 1.0e4 {
    patch circ 2 8 2 0.1 -0.05 0.1 0.3 0.0 360.0
    layer straight 1 2 3.0e-4 -0.2 0.1 0.2 0.1
    fiber -0.1 0.2 2.0e-4 1
}
element twoNodeLink 1 1 2 -mat 1 2 2 -dir 1 4 6 -pDelta 0.1 0.2 0.3 0.1 -shearDist 0.3 0.6 \
    -orient 0.6 0.8 0.0 -0.8 0.6 0.0
printModel -JSON -file [file join $out model_links_3d.json]
