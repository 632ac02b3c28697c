# Closed-form checks of the sections, beam integrations, beam-columns,
# DisplacementControl, element responses and the truss of `poundfe
# opensees`: each case (but the last, a two-bar truss) builds a cantilever of length L (node 1 fixed, node 2 free, 2D),
# loads it, and compares with the exact answer written here. One line per
# check: "ok NAME relative-difference" or "FAIL NAME got expected".
# Elastic members under end loads: the force-based element integrates the
# flexibility exactly (Lobatto >= 3 points, HingeRadau), the displacement-
# based one solves the Hermite cubics exactly: round-off (1e-10).
set L 3.0; set E 3.0e7; set b 0.3; set h 0.5
set A [expr {$b*$h}]; set I [expr {$b*$h*$h*$h/12.0}]
set H 40.0; set P -500.0; set M 25.0
set failures 0

proc check {name got expected tolerance} {
    global failures
    set scale [expr {abs($expected) > 0 ? abs($expected) : 1.0}]
    set d [expr {abs($got - $expected)/$scale}]
    if {$d <= $tolerance} {
        puts [format "ok %s %.3e" $name $d]
    } else {
        puts "FAIL $name got $got expected $expected"
        incr failures
    }
}

# A cantilever: `element` is the element command after its tag and nodes.
proc cantilever {define element} {
    global L
    wipe
    model basic -ndm 2 -ndf 3
    node 1 0.0 0.0
    node 2 0.0 $L
    fix 1 1 1 1
    uplevel #0 $define
    eval element $element
}

proc static_tip_loads {fx fy mz {steps 1}} {
    timeSeries Linear 1
    pattern Plain 1 1 "load 2 $fx $fy $mz"
    system UmfPack
    test NormDispIncr 1.0e-12 20
    algorithm Newton
    integrator LoadControl [expr {1.0/$steps}]
    analysis Static
    analyze $steps
}

# the exact tip of the elastic cantilever (along y) under H (along x), P
# (along y) and M (counter-clockwise) at its tip
set ux [expr {$H*$L*$L*$L/(3*$E*$I) - $M*$L*$L/(2*$E*$I)}]
set uy [expr {$P*$L/($E*$A)}]
set rz [expr {-$H*$L*$L/(2*$E*$I) + $M*$L/($E*$I)}]

foreach {name define element} {
    elasticBeamColumn {geomTransf Linear 1} {elasticBeamColumn 1 1 2 $A $E $I 1}
    forceBeamColumn_Lobatto5 {geomTransf Linear 1; section Elastic 1 $E $A $I; beamIntegration Lobatto 1 1 5}
        {forceBeamColumn 1 1 2 1 1}
    forceBeamColumn_old_syntax {geomTransf Linear 1; section Elastic 1 $E $A $I} {forceBeamColumn 1 1 2 3 1 1}
    nonlinearBeamColumn {geomTransf Linear 1; section Elastic 1 $E $A $I} {nonlinearBeamColumn 1 1 2 4 1 1}
    forceBeamColumn_iter {geomTransf Linear 1; section Elastic 1 $E $A $I; beamIntegration Lobatto 1 1 3}
        {forceBeamColumn 1 1 2 1 1 -iter 20 1.0e-14 -mass 0.5}
    dispBeamColumn_Legendre2 {geomTransf Linear 1; section Elastic 1 $E $A $I; beamIntegration Legendre 1 1 2}
        {dispBeamColumn 1 1 2 1 1}
    forceBeamColumn_HingeRadau {geomTransf Linear 1; section Elastic 1 $E $A $I; section Elastic 2 $E $A $I;
        beamIntegration HingeRadau 1 1 0.25 2 0.3 1} {forceBeamColumn 1 1 2 1 1}
    Aggregator_Mz {geomTransf Linear 1; uniaxialMaterial Elastic 6 [expr {$E*$A}];
        uniaxialMaterial Elastic 5 [expr {$E*$I}]; section Aggregator 2 5 Mz 6 P}
        {forceBeamColumn 1 1 2 3 2 1}
} {
    cantilever [subst $define] [subst $element]
    static_tip_loads $H $P $M
    check "$name ux" [nodeDisp 2 1] $ux 1e-10
    check "$name uy" [nodeDisp 2 2] $uy 1e-10
    check "$name rz" [nodeDisp 2 3] $rz 1e-10
}

# HingeRadau (Scott & Fenves 2006; OpenSees's sections: end I's at xi = 0
# only, the interior's at 8 lp/3): a base section of half the rigidity adds
# exactly lp (1/EI_h - 1/EI) M to the base rotation, so the tip moves
# H L^3/3EI + H L^2 lp/EI for EI_h = EI/2
set lp 0.25
cantilever "geomTransf Linear 1; section Elastic 1 $E $A [expr {$I/2}]; section Elastic 2 $E $A $I
    beamIntegration HingeRadau 1 1 $lp 2 $lp 2" {forceBeamColumn 1 1 2 1 1}
static_tip_loads $H 0.0 0.0
check "HingeRadau hinge ux" [nodeDisp 2 1] \
    [expr {$H*$L*$L*$L/(3*$E*$I) + $H*$L*$L*$lp/($E*$I)}] 1e-10

# A fibre section of nY layers of an elastic material over the depth h:
# I_n = b h^3/12 (1 - 1/nY^2) (the layers' own inertia is lost), A = b h.
set nY 8
set In [expr {$b*$h*$h*$h/12.0*(1.0 - 1.0/($nY*$nY))}]
cantilever "geomTransf Linear 1; uniaxialMaterial Elastic 1 $E
    section Fiber 1 { patch rect 1 $nY 2 [expr {-$h/2}] [expr {-$b/2}] [expr {$h/2}] [expr {$b/2}] }
    beamIntegration Lobatto 1 1 4" {forceBeamColumn 1 1 2 1 1}
static_tip_loads $H $P 0.0
check "fibre rect ux" [nodeDisp 2 1] [expr {$H*$L*$L*$L/(3*$E*$In)}] 1e-10
check "fibre rect uy" [nodeDisp 2 2] [expr {$P*$L/($E*$A)}] 1e-10
# the responses: the base section's resultants (N, M) in OpenSees's signs,
# basic forces (N, MI, MJ), local forces and the global force = -reaction
check "section 1 force N" [lindex [eleResponse 1 section 1 force] 0] $P 1e-10
check "section 1 force M" [lindex [eleResponse 1 section 1 force] 1] [expr {-$H*$L}] 1e-10
check "section 4 force M" [lindex [eleResponse 1 section 4 force] 1] 0.0 1e-10
check "basicForce MI" [lindex [eleResponse 1 basicForce] 1] [expr {$H*$L}] 1e-10
check "localForce V" [lindex [eleResponse 1 localForce] 1] $H 1e-10
check "eleForce Fx at I" [eleForce 1 1] [expr {-$H}] 1e-10
check "eleForce My at I" [eleForce 1 3] [expr {$H*$L}] 1e-10
check "section 1 deformation kappa" [lindex [eleResponse 1 section 1 deformation] 1] \
    [expr {-$H*$L/($E*$In)}] 1e-10

# DisplacementControl: the tip reaches n dU exactly; the load factor of a
# unit reference load is then k u with k = 3 E I_n / L^3 (elastic fibres)
cantilever "geomTransf Linear 1; uniaxialMaterial Elastic 1 $E
    section Fiber 1 { patch rect 1 $nY 2 [expr {-$h/2}] [expr {-$b/2}] [expr {$h/2}] [expr {$b/2}] }
    beamIntegration Lobatto 1 1 4" {forceBeamColumn 1 1 2 1 1}
timeSeries Linear 1
pattern Plain 1 1 { load 2 1.0 0.0 0.0 }
system UmfPack
test NormDispIncr 1.0e-12 20
algorithm Newton
integrator DisplacementControl 2 1 0.001
analysis Static
analyze 7
check "DisplacementControl u" [nodeDisp 2 1] 0.007 1e-12
check "DisplacementControl lambda" [getTime %.17g] [expr {3*$E*$In/($L*$L*$L)*0.007}] 1e-10
# back, with a new integrator: exactly to -0.002
integrator DisplacementControl 2 1 -0.0015
analyze 6
check "DisplacementControl back" [nodeDisp 2 1] -0.002 1e-12

# Elastic-perfectly-plastic Steel01 fibres under DisplacementControl: the
# displacement is still exact, and once every layer of the base section has
# yielded its moment is the plastic moment fy sum |y_i| A_i = fy b h^2/4
# (layers at the cells' centroids, nY even)
cantilever "geomTransf Linear 1; uniaxialMaterial Steel01 1 60.0e3 $E 0.0
    section Fiber 1 { patch rect 1 $nY 1 [expr {-$h/2}] [expr {-$b/2}] [expr {$h/2}] [expr {$b/2}] }
    beamIntegration Lobatto 1 1 5" {forceBeamColumn 1 1 2 1 1}
timeSeries Linear 1
pattern Plain 1 1 { load 2 1.0 0.0 0.0 }
system UmfPack
test NormDispIncr 1.0e-12 30
algorithm Newton
integrator DisplacementControl 2 1 0.008
analysis Static
analyze 25
check "DisplacementControl Steel01 u" [nodeDisp 2 1] 0.2 1e-11
check "plastic moment" [expr {-[lindex [eleResponse 1 section 1 force] 1]}] \
    [expr {60.0e3*$b*$h*$h/4.0}] 1e-9

# Corotational: an elastic cantilever bent by a tip moment into a quarter
# circle, M = (pi/2) EI/L: the tip at (R sin(L/R), R (1 - cos(L/R))),
# R = EI/M; 16 elements (chord error (L/16/R)^2/24 ~ 4e-4)
set n 16
set Mq [expr {acos(-1.0)/2.0*$E*$I/$L}]
set R [expr {$E*$I/$Mq}]
foreach {name kind} {elasticBeamColumn elastic forceBeamColumn force} {
    wipe
    model basic -ndm 2 -ndf 3
    for {set i 0} {$i <= $n} {incr i} { node [expr {$i + 1}] [expr {$L*$i/$n}] 0.0 }
    fix 1 1 1 1
    geomTransf Corotational 1
    section Elastic 1 $E $A $I
    beamIntegration Lobatto 1 1 3
    for {set i 1} {$i <= $n} {incr i} {
        if {$kind eq "elastic"} {
            element elasticBeamColumn $i $i [expr {$i + 1}] $A $E $I 1
        } else {
            element forceBeamColumn $i $i [expr {$i + 1}] 1 1
        }
    }
    timeSeries Linear 1
    pattern Plain 1 1 "load [expr {$n + 1}] 0.0 0.0 $Mq"
    system UmfPack
    test NormDispIncr 1.0e-12 30
    algorithm Newton
    integrator LoadControl 0.1
    analysis Static
    analyze 10
    set x [expr {$L + [nodeDisp [expr {$n + 1}] 1]}]
    set y [nodeDisp [expr {$n + 1}] 2]
    check "Corotational $name x" $x [expr {$R*sin($L/$R)}] 1e-3
    check "Corotational $name y" $y [expr {$R*(1 - cos($L/$R))}] 1e-3
    check "Corotational $name rotation" [nodeDisp [expr {$n + 1}] 3] [expr {$L/$R}] 1e-10
}
# truss: the symmetric two-bar truss (bars of length 5 at sin = 0.8) under a
# vertical load P at the apex: N = -P/(2 sin), the apex sinks P L/(2 EA sin^2)
wipe
model basic -ndm 2 -ndf 2
node 1 0.0 0.0
node 2 6.0 0.0
node 3 3.0 4.0
fix 1 1 1
fix 2 1 1
uniaxialMaterial Elastic 1 $E
element truss 1 1 3 $A 1
element truss 2 2 3 $A 1 -rho 0.0 -doRayleigh 0
timeSeries Linear 1
pattern Plain 1 1 { load 3 0.0 -1000.0 }
system UmfPack
test NormDispIncr 1.0e-14 10
algorithm Newton
integrator LoadControl 1.0
analysis Static
analyze 1
check "truss apex" [nodeDisp 3 2] [expr {-1000.0*5.0/(2*$E*$A*0.64)}] 1e-10
check "truss ux" [expr {[nodeDisp 3 1] + 1.0}] 1.0 1e-14
check "truss axialForce" [eleResponse 1 axialForce] [expr {-1000.0/1.6}] 1e-10
# rigidLink bar: two cantilevers (EI and 3 EI, the second 2 m away) whose
# tips move together in x and y (OpenSees's RigidBar: the translations
# equal); H on the first tip: both sway H L^3 / (3 (EI + 3 EI)), each keeps
# its own rotation (the stiffer turns less, by its share)
wipe
model basic -ndm 2 -ndf 3
node 1 0.0 0.0
node 2 0.0 $L
node 3 2.0 0.0
node 4 2.0 $L
fix 1 1 1 1
fix 3 1 1 1
geomTransf Linear 1
element elasticBeamColumn 1 1 2 $A $E $I 1
element elasticBeamColumn 2 3 4 $A $E [expr {3*$I}] 1
rigidLink bar 2 4
timeSeries Linear 1
pattern Plain 1 1 "load 2 $H 0.0 0.0"
test NormDispIncr 1.0e-12 20
algorithm Newton
integrator LoadControl 1.0
analysis Static
analyze 1
set sway [expr {$H*$L*$L*$L/(3*4*$E*$I)}]
check "rigidLink bar sway" [nodeDisp 2 1] $sway 1e-10
check "rigidLink bar sway of the other" [nodeDisp 4 1] $sway 1e-10
check "rigidLink bar rotation" [nodeDisp 2 3] [expr {-1.5*$sway/$L}] 1e-10
puts "failures $failures"
