# poundfe::energy and poundfe::impacts against a second computation written
# here: the script steps one `analyze 1 dt` at a time and sums, from
# nodeDisp, nodeVel and eleResponse, the trapezoidal input work of the
# ground motion and the loads, 1/2 v^T M v, 1/2 u^T K u of the elastic
# springs (their work), the Rayleigh damping's work and each contact
# episode of the gap's force history (count, peak force, impulse). argv: the
# case, sdof (a linear SDOF, 5 % Rayleigh, algorithm Linear), mdof (a
# two-storey linear stick with a nodal load, Rayleigh on the initial
# stiffness, Newton), modal (the same with modalDamping), steel01 (the
# same stick yielding, Steel01 springs, Rayleigh on the committed
# stiffness: its elements' work the trapezoidal sum of eleResponse's force,
# its damping what closes the balance) or one of pounding_sticks.tcl's gap
# laws (two sticks pounding, Newton), TwoNodeLink (its ElasticPPGap as a
# twoNodeLink) or Series (its ElasticPPGap in series with an Elastic
# spring: in contact while the gap's force is not zero, which the script
# reads as the element's force above 1e-6 N, a Series's out of contact
# being its iteration's residue, ~1e-22 N); optionally a directory for
# impacts.csv. Runs where poundfe runs it (poundfe:: exists).
set case [lindex $argv 0]
source [file join [file dirname [info script]] record.tcl]
proc check {what got want tolerance} {
    set scale [expr {max(abs($want), 1.0e-30)}]
    if {abs($got - $want) > $tolerance * $scale} {
        error "$what: poundfe $got, the script's own sum $want (tolerance $tolerance)"
    }
}
wipe
model basic -ndm 1 -ndf 1
set pi 3.14159265358979
set dt 0.01
set n 1000
set scale 1.0
set beta_kc 0.0
# node masses, spring stiffnesses by element (nodes i j), gap element
switch -- $case {
    sdof {
        node 1 0.0; node 2 0.0 -mass 2.0; fix 1 1
        set masses {2 2.0}
        uniaxialMaterial Elastic 1 800.0
        element zeroLength 1 1 2 -mat 1 -dir 1 -doRayleigh 1
        set springs {1 {1 2 800.0}}
        set alpha_m 1.0; set beta_k 2.5e-3; set beta_k0 0.0
    }
    mdof - modal {
        node 1 0.0; node 2 0.0 -mass 1.0e5; node 3 0.0 -mass 8.0e4; fix 1 1
        set masses {2 1.0e5 3 8.0e4}
        uniaxialMaterial Elastic 1 4.0e7
        uniaxialMaterial Elastic 2 3.0e7
        element zeroLength 1 1 2 -mat 1 -dir 1 -doRayleigh 1
        element zeroLength 2 2 3 -mat 2 -dir 1 -doRayleigh 1
        set springs {1 {1 2 4.0e7} 2 {2 3 3.0e7}}
        set alpha_m 0.4; set beta_k 0.0; set beta_k0 2.0e-3
        timeSeries Linear 2
        pattern Plain 2 2 { load 3 5.0e4 }
    }
    steel01 {
        node 1 0.0; node 2 0.0 -mass 1.0e5; node 3 0.0 -mass 8.0e4; fix 1 1
        set masses {2 1.0e5 3 8.0e4}
        uniaxialMaterial Steel01 1 2.0e5 4.0e7 0.02
        uniaxialMaterial Steel01 2 1.5e5 3.0e7 0.05
        element zeroLength 1 1 2 -mat 1 -dir 1 -doRayleigh 1
        element zeroLength 2 2 3 -mat 2 -dir 1 -doRayleigh 1
        set springs {1 {1 2 0.0} 2 {2 3 0.0}}
        set alpha_m 0.0; set beta_k 0.0; set beta_k0 0.0; set beta_kc 2.0e-3
        set scale 3.0
    }
    default {
        # pounding_sticks.tcl's two sticks and gap
        set m 1.0e5
        node 1 0.0; node 2 0.0 -mass $m; node 3 0.0; node 4 0.0 -mass $m
        fix 1 1; fix 3 1
        set masses [list 2 $m 4 $m]
        set k2 [expr {$m * pow(2 * $pi / 0.5, 2)}]
        set k4 [expr {$m * pow(2 * $pi / 1.0, 2)}]
        uniaxialMaterial Elastic 1 $k2
        uniaxialMaterial Elastic 2 $k4
        element zeroLength 1 1 2 -mat 1 -dir 1 -doRayleigh 1
        element zeroLength 2 3 4 -mat 2 -dir 1 -doRayleigh 1
        set springs [list 1 [list 1 2 $k2] 2 [list 3 4 $k4]]
        switch -- $case {
            ElasticPPGap - TwoNodeLink {
                uniaxialMaterial ElasticPPGap 3 2.0e9 -4.0e6 -0.01 0.1 damage
            }
            Series {
                uniaxialMaterial ElasticPPGap 4 2.0e9 -4.0e6 -0.01 0.1 damage
                uniaxialMaterial Elastic 5 2.0e10
                uniaxialMaterial Series 3 4 5
            }
            ImpactMaterial { uniaxialMaterial ImpactMaterial 3 2.0e9 6.0e8 -0.002 -0.01 }
            ViscoelasticGap { uniaxialMaterial ViscoelasticGap 3 2.0e9 4.0e6 -0.01 }
            Hertzdamp { uniaxialMaterial Hertzdamp 3 5.0e10 0.48 -0.01 }
            MinMax {
                uniaxialMaterial ImpactMaterial 4 2.0e9 6.0e8 -0.002 -0.01
                uniaxialMaterial MinMax 3 4 -min -0.014
            }
            default { error "energy_balance.tcl: no case '$case'" }
        }
        if {$case eq "TwoNodeLink"} {
            element twoNodeLink 3 2 4 -mat 3 -dir 1 -orient 1 0 0
        } else {
            element zeroLength 3 2 4 -mat 3 -dir 1
        }
        set gap 3
        set dt 0.002
        set n 4000
        set scale 0.6
        set alpha_m 0.3; set beta_k 1.0e-3; set beta_k0 0.0
    }
}
set record [synthetic_record $dt $n $scale]
timeSeries Path 1 -dt $dt -values $record
pattern UniformExcitation 1 1 -accel 1
if {$case eq "modal"} {
    # 5 % in both modes: the damping term is what closes the balance (the
    # other terms are checked against the script's sums)
    eigen 2
    modalDamping 0.05
    set alpha_m 0.0; set beta_k 0.0; set beta_k0 0.0
} else {
    rayleigh $alpha_m $beta_k $beta_k0 $beta_kc
}
constraints Plain
numberer Plain
system BandGeneral
# the residual of a nonlinear model is the equilibrium Newton leaves: with
# the test at 1e-12 m (K_gap 1e-12 m ~ 2e-3 N a step) within 1e-8 of the
# largest term; a linear model's is round-off
test NormDispIncr 1.0e-12 50
algorithm [expr {$case eq "sdof" ? "Linear" : "Newton"}]
integrator Newmark 0.5 0.25
analysis Transient
poundfe::energy on
poundfe::impacts on

# the script's own sums: the forces at each end of a step
proc state {} {
    global masses springs record dt alpha_m beta_k beta_k0
    set t [getTime]
    set i [expr {int(round($t / $dt))}]
    set a_g [lindex $record $i]
    set s [dict create]
    foreach {node m} $masses {
        dict set s u$node [nodeDisp $node 1]
        dict set s v$node [nodeVel $node 1]
        # -m a_g + the nodal load (mdof: 5e4 N times t on node 3)
        set p [expr {-$m * $a_g}]
        if {[info exists ::case] && $::case in {mdof modal} && $node == 3} {
            set p [expr {$p + 5.0e4 * $t}]
        }
        dict set s p$node $p
        dict set s c$node [expr {$alpha_m * $m * [nodeVel $node 1]}]
    }
    foreach {e spring} $springs {
        lassign $spring i j k
        set du [expr {[nodeDisp $j 1] - ($i == 1 || $i == 3 ? 0.0 : [nodeDisp $i 1])}]
        set dv [expr {[nodeVel $j 1] - ($i == 1 || $i == 3 ? 0.0 : [nodeVel $i 1])}]
        dict set s f$e [lindex [eleResponse $e force] 1]
        dict set s d$e $du
        dict set s fd$e [expr {($beta_k + $beta_k0) * $k * $dv}]
    }
    return $s
}
set input 0.0; set strain 0.0; set work 0.0; set damping 0.0; set yielded 0
set episodes 0; set peak 0.0; set impulse 0.0; set in_contact 0; set force_last 0.0
set last [state]
for {set step 0} {$step < $n} {incr step} {
    if {[analyze 1 $dt] != 0} { error "step $step failed" }
    set now [state]
    foreach {node m} $masses {
        set du [expr {[dict get $now u$node] - [dict get $last u$node]}]
        set input [expr {$input + 0.5 * ([dict get $now p$node] + [dict get $last p$node]) * $du}]
        set damping [expr {$damping + 0.5 * ([dict get $now c$node] + [dict get $last c$node]) * $du}]
    }
    foreach {e spring} $springs {
        set dd [expr {[dict get $now d$e] - [dict get $last d$e]}]
        set work [expr {$work + 0.5 * ([dict get $now f$e] + [dict get $last f$e]) * $dd}]
        set f_max($e) [expr {max([info exists f_max($e)] ? $f_max($e) : 0.0, abs([dict get $now f$e]))}]
        set damping [expr {$damping + 0.5 * ([dict get $now fd$e] + [dict get $last fd$e]) * $dd}]
    }
    if {[info exists gap]} {
        set force [expr {abs([lindex [eleResponse $gap force] 1])}]
        if {$case eq "Series" && $force <= 1.0e-6} { set force 0.0 }
        if {$force > 0 && !$in_contact} { incr episodes }
        set in_contact [expr {$force > 0}]
        set peak [expr {max($peak, $force)}]
        set impulse [expr {$impulse + 0.5 * ($force + $force_last) * $dt}]
        set force_last $force
    }
    set last $now
}
set kinetic 0.0
foreach {node m} $masses {
    set kinetic [expr {$kinetic + 0.5 * $m * pow([nodeVel $node 1], 2)}]
}
foreach {e spring} $springs {
    set k [lindex $spring 2]
    set strain [expr {$strain + 0.5 * $k * pow([dict get $last d$e], 2)}]
}
set energy [poundfe::energy]
puts "energy_balance $case: $energy"
set largest 0.0
foreach term {input kinetic elements damping contact} {
    set largest [expr {max($largest, abs([dict get $energy $term]))}]
}
# the terms against the script's sums: the same trapezoidal sums of the
# same committed states, so to round-off (1e-9 of the largest term)
check "input" [dict get $energy input] $input 1.0e-9
check "kinetic" [dict get $energy kinetic] $kinetic 1.0e-9
if {$case eq "steel01"} {
    # both springs yield (Fy 2e5 and 1.5e5 N): the committed tangent moves
    if {$f_max(1) < 2.0e5 || $f_max(2) < 1.5e5} {
        error "steel01: the springs do not yield (peak forces $f_max(1), $f_max(2))"
    }
    check "elements" [dict get $energy elements] $work 1.0e-9
} else {
    check "elements" [dict get $energy elements] $strain 1.0e-9
}
if {$case ni {modal steel01}} {
    check "damping" [dict get $energy damping] $damping 1.0e-9
}
if {[dict get $energy relative_residual] > 1.0e-8} {
    error "the balance's residual [dict get $energy relative_residual] of the largest term exceeds 1e-8"
}
if {[info exists gap]} {
    set impacts [expr {$argc > 1 ? [poundfe::impacts -file [lindex $argv 1]/impacts.csv] :
                                   [poundfe::impacts]}]
    puts "energy_balance $case: [llength $impacts] impacts"
    if {[llength $impacts] != $episodes || $episodes == 0} {
        error "impacts: poundfe [llength $impacts], the force history $episodes"
    }
    set peak_log 0.0; set impulse_log 0.0
    foreach i $impacts {
        set peak_log [expr {max($peak_log, [dict get $i peak_force])}]
        set impulse_log [expr {$impulse_log + [dict get $i impulse]}]
    }
    check "peak contact force" $peak_log $peak 1.0e-12
    check "impulse" $impulse_log $impulse 1.0e-9
}
