# A force-based RC cantilever reversed by a few DBL_EPSILON at its post-yield
# peaks. OpenSees 3.8's ForceBeamColumn2d::update takes the increment dv
# since the element's last update (getBasicIncrDeltaDisp) and, when
# |dv| <= DBL_EPSILON, keeps its state; the next update starts from
# vin = v - dv, so a skipped increment is not carried into the next one's
# band test. Each reversal is two DisplacementControl steps of r (each
# below the band at the element, together above it), then one Linear
# LoadControl step of lateral load that moves the tip by the tangent the
# reversal left: the loading branch's when the element skipped both steps,
# the unloading one's otherwise. Two forceBeamColumns of 5 Lobatto points
# on a 0.5 x 0.6 m RC rectangle (Concrete01 cover, Concrete02 core, Steel02
# bars), PDelta, 2000 kN axial load, cycles to 1 and 3 cm of tip drift
# (kN, m).
#   argv: the output directory, the reversal r (default 4e-16).
set out [lindex $argv 0]
set r [expr {[llength $argv] > 1 ? [lindex $argv 1] : 4.0e-16}]
wipe
model basic -ndm 2 -ndf 3
uniaxialMaterial Concrete01 1 -35.0e3 -0.002 -7.0e3 -0.0045
uniaxialMaterial Concrete02 2 -45.0e3 -0.003 -36.0e3 -0.025 0.15 3.5e3 2.0e6
uniaxialMaterial Steel02 3 520.0e3 2.05e8 0.008 20.0 0.925 0.15
section Fiber 1 {
    patch rect 2 10 1 -0.25 -0.2 0.25 0.2
    patch rect 1 2 1 -0.3 -0.25 0.3 -0.2
    patch rect 1 2 1 -0.3 0.2 0.3 0.25
    patch rect 1 10 1 -0.3 -0.2 -0.25 0.2
    patch rect 1 10 1 0.25 -0.2 0.3 0.2
    layer straight 3 4 4.9e-4 -0.24 -0.19 -0.24 0.19
    layer straight 3 4 4.9e-4 0.24 -0.19 0.24 0.19
}
node 1 0.0 0.0
node 2 0.0 1.5
node 3 0.0 3.0
fix 1 1 1 1
geomTransf PDelta 1
element forceBeamColumn 1 1 2 5 1 1
element forceBeamColumn 2 2 3 5 1 1
recorder Node -file $out/top.out -time -precision 16 -node 3 -dof 1 2 3 disp
recorder Node -file $out/base.out -time -precision 16 -node 1 -dof 1 2 3 reaction
recorder Element -file $out/section.out -time -precision 16 -ele 1 section 1 force
constraints Plain
numberer RCM
system BandGeneral
test NormDispIncr 1.0e-10 60
algorithm Newton
analysis Static
timeSeries Linear 1
pattern Plain 1 1 { load 3 0.0 -2000.0 0.0 }
integrator LoadControl 0.1
analyze 10
loadConst -time 0.0
timeSeries Linear 2
pattern Plain 2 2 { load 3 1.0 0.0 0.0 }

proc reverse_then_load {step} {
    integrator DisplacementControl 3 1 $step
    analyze 2
    algorithm Linear
    integrator LoadControl 0.5
    analyze 1
    algorithm Newton
}
set u [nodeDisp 3 1]
foreach amplitude {0.01 0.03} {
    foreach target [list $amplitude [expr {-$amplitude}] 0.0] {
        set n [expr {int(round(abs($target - $u) / 0.002))}]
        if {$n == 0} { continue }
        set step [expr {($target - $u) / $n}]
        integrator DisplacementControl 3 1 $step
        if {[analyze $n] != 0} { puts "failed at u $u"; exit 2 }
        reverse_then_load [expr {$step > 0 ? -$r : $r}]
        set u [nodeDisp 3 1]
    }
}
puts "force reversals: u [nodeDisp 3 1]"
