# OpenSees 3.8's dead bands of Concrete01, Concrete02 and Steel02 in an RC
# fibre section (rc_section.tcl's rectangle 0.4 x 0.4 m: Concrete01 cover,
# Concrete02 core, Steel02 bars; kN, m) on a zeroLengthSection whose
# rotation is the curvature. Each law skips a strain change below
# DBL_EPSILON from its committed strain (Steel02: 10 DBL_EPSILON, from a
# virgin state only): Concrete01 keeps its committed state, Concrete02 its
# committed history with its last trial's stress and tangent, Steel02 stays
# virgin. A curvature step of 5e-16 (fibre strains up to 1e-16) from the
# virgin section, then one Linear LoadControl step of 1 kNm, which moves
# the section by the tangent the bands left (a cover fibre given a tiny
# tension keeps Ec0 in the band, 0 outside it); that moment held, the axial
# load of 800 kN, held; curvature cycles of 0.005, 0.015 and 0.03 by
# DisplacementControl (Newton), a reverse step of 5e-16 at every peak.
#   argv: the output directory.
set out [lindex $argv 0]
source [file join [file dirname [info script]] rc_section.tcl]
wipe
model basic -ndm 2 -ndf 3
uniaxialMaterial Concrete01 1 -30.0e3 -0.002 -6.0e3 -0.005
uniaxialMaterial Concrete02 2 -39.0e3 -0.0026 -32.0e3 -0.02 0.1 3.0e3 1.5e6
uniaxialMaterial Steel02 3 450.0e3 2.0e8 0.01 18.0 0.925 0.15
rc_section 1 0.4 0.4 0.04 3 3.14e-4
node 1 0.0 0.0
node 2 0.0 0.0
fix 1 1 1 1
fix 2 0 1 0
element zeroLengthSection 1 1 2 1
recorder Node -file $out/band_disp.out -time -precision 16 -node 2 -dof 1 3 disp
recorder Node -file $out/band_reaction.out -time -precision 16 -node 1 -dof 1 3 reaction
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-10 50
analysis Static

proc tiny_then_linear {step moment} {
    algorithm Newton
    integrator DisplacementControl 2 3 $step
    analyze 1
    algorithm Linear
    integrator LoadControl $moment
    analyze 1
    algorithm Newton
}
timeSeries Linear 1
pattern Plain 1 1 { load 2 0.0 0.0 1.0 }
tiny_then_linear 5.0e-16 1.0
loadConst -time 0.0
# the axial load, then held
timeSeries Linear 2
pattern Plain 2 2 { load 2 -800.0 0.0 0.0 }
integrator LoadControl 0.1
analyze 10
loadConst -time 0.0
timeSeries Linear 3
pattern Plain 3 3 { load 2 0.0 0.0 1.0 }
set kappa [nodeDisp 2 3]
foreach amplitude {0.005 0.015 0.03} {
    foreach target [list $amplitude [expr {-$amplitude}] 0.0] {
        set n [expr {int(round(abs($target - $kappa) / 0.0005))}]
        if {$n == 0} { continue }
        set step [expr {($target - $kappa) / $n}]
        integrator DisplacementControl 2 3 $step
        if {[analyze $n] != 0} { puts "failed at kappa $kappa"; exit 2 }
        set kappa [nodeDisp 2 3]
        integrator DisplacementControl 2 3 [expr {$step > 0 ? -5.0e-16 : 5.0e-16}]
        analyze 1
        set kappa [nodeDisp 2 3]
    }
}
puts "dead bands: kappa [nodeDisp 2 3]"
