# poundfe::locateEvents on a 2D pounding pair: two elastic cantilevers
# (elasticBeamColumn, the masses at their tops) that pound through a
# zeroLength gap between their tops under a ground motion.
# argv: the output directory, the law (linear: ElasticPPGap with an
# unreachable Fy; Jankowski: a soft JankowskiImpact; Hertzdamp: a stiff
# one, whose impact steps Newton fails at dt = 0.01), the mode (off: OpenSees's steps; on:
# poundfe::locateEvents on R; fine: off at dt/2^R), the step, R, and the
# model (tuned: the pair the tolerances were set on; other: other masses,
# periods, gap and ground motion); optionally the gap element (zeroLength,
# the default; twoNodeLink: the same gap as a twoNodeLink along global X;
# Series: the zeroLength's material in series with a stiff Elastic spring).
# Writes LAW_MODEL_MODE.out (the tops' displacements), LAW_MODEL_MODE.csv
# (poundfe::impacts), both with _ELEMENT before the suffix for another
# element than zeroLength, and prints the energy balance's relative residual.
lassign $argv out law mode dt levels model link
if {$link eq ""} { set link zeroLength }
set name ${law}_${model}_$mode[expr {$link eq "zeroLength" ? "" : "_$link"}]
source [file join [file dirname [info script]] record.tcl]
set pi 3.14159265358979
if {$model eq "tuned"} {
    set m1 1.0e5; set t1 0.5; set m2 1.0e5; set t2 1.0; set gap 0.01
    set record_dt 0.002; set n 2000
    set record [synthetic_record $record_dt $n 0.6]
} else {
    set m1 2.5e5; set t1 0.7; set m2 8.0e4; set t2 0.35; set gap 0.006
    set record_dt 0.005; set n 800
    # a chirp from 0.5 to 3 Hz under a rising and falling envelope
    set record {}
    for {set i 0} {$i <= $n} {incr i} {
        set t [expr {$i * $record_dt}]
        lappend record [expr {4.0 * sin(2 * $pi * (0.5 + 0.3125 * $t) * $t) * sin($pi * $t / 4.0)}]
    }
}
wipe
model basic -ndm 2 -ndf 3
set h 3.0
node 1 0.0 0.0; node 2 0.0 $h -mass $m1 $m1 0.0
node 3 0.0 0.0; node 4 0.0 $h -mass $m2 $m2 0.0
fix 1 1 1 1; fix 3 1 1 1
geomTransf Linear 1
# tip stiffness 3 EI / h^3 = m (2 pi / T)^2
set e 3.0e10; set area 1.0
foreach {tag i j m t} [list 1 1 2 $m1 $t1 2 3 4 $m2 $t2] {
    set inertia [expr {$m * pow(2 * $pi / $t, 2) * pow($h, 3) / (3 * $e)}]
    element elasticBeamColumn $tag $i $j $area $e $inertia 1
}
switch -- $law {
    linear { uniaxialMaterial ElasticPPGap 3 2.0e9 -1.0e12 [expr {-$gap}] }
    Jankowski {
        # a soft Hertz law, so that Newton converges at dt = 0.01 without it
        set m_eff [expr {$m1 * $m2 / ($m1 + $m2)}]
        uniaxialMaterial JankowskiImpact 3 5.0e8 0.35 $m_eff [expr {-$gap}]
    }
    Hertzdamp { uniaxialMaterial Hertzdamp 3 5.0e10 0.48 [expr {-$gap}] }
    default { error "locate_events.tcl: no law '$law'" }
}
switch -- $link {
    zeroLength { element zeroLength 3 2 4 -mat 3 -dir 1 }
    twoNodeLink { element twoNodeLink 3 2 4 -mat 3 -dir 1 -orient 1 0 0 0 1 0 }
    Series {
        uniaxialMaterial Elastic 5 1.0e12
        uniaxialMaterial Series 6 3 5
        element zeroLength 3 2 4 -mat 6 -dir 1
    }
    default { error "locate_events.tcl: no gap element '$link'" }
}
timeSeries Path 1 -dt $record_dt -values $record
pattern UniformExcitation 1 1 -accel 1
rayleigh 0.4 0.0 0.0 0.0
recorder Node -file $out/$name.out -time -precision 16 -node 2 4 -dof 1 disp
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-12 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
poundfe::energy on
poundfe::impacts on
switch -- $mode {
    on { poundfe::locateEvents on $levels }
    fine { set dt [expr {$dt / pow(2, $levels)}] }
    off {}
    default { error "locate_events.tcl: no mode '$mode'" }
}
set status [analyze [expr {int(round($n * $record_dt / $dt))}] $dt]
poundfe::impacts -file $out/$name.csv
set energy [poundfe::energy]
puts "locate_events $law $model $mode $link: status $status time [getTime] locate\
      [poundfe::locateEvents query] relative_residual [dict get $energy relative_residual]"
