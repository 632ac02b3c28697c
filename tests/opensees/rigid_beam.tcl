# rigidLink beam (OpenSees's RigidBeam: u_c = u_r + theta_r x d,
# theta_c = theta_r) and `remove mp`: two elastic columns whose tops carry
# the masses and, by rigid offsets (d with every component nonzero), the
# ends of an elastic beam between them. Gravity, a lateral load and a moment
# by LoadControl, then the synthetic record (2d: along X; 3d: along X and
# 0.6 of it along Y) with Rayleigh damping; halfway through it `remove mp 6`
# frees the beam's second end (it then hangs from the first), and a third
# column's top, tied to the first column's by equalDOF, is released by
# `remove mp 8`. argv: the output directory, 2d|3d, the handler's words
# (Transformation, Lagrange or Penalty alphaSP alphaMP).
set out [lindex $argv 0]
set dim [lindex $argv 1]
set handler [expr {[llength $argv] > 2 ? [lrange $argv 2 end] : "Transformation"}]
source [file join [file dirname [info script]] record.tcl]
source [file join [file dirname [info script]] tie_analysis.tcl]
wipe
set h 3.0
set m 8.0e3
set E 3.0e10
set g 9.81
if {$dim eq "2d"} {
    model basic -ndm 2 -ndf 3
    node 1 0.0 0.0
    node 2 0.0 $h -mass $m $m [expr {$m * 0.5}]
    node 3 5.0 0.0
    node 4 5.0 $h -mass $m $m [expr {$m * 0.5}]
    node 5 0.35 [expr {$h + 0.25}]
    node 6 4.6 [expr {$h + 0.3}]
    node 7 7.0 0.0
    node 8 7.0 $h -mass $m $m 0.0
    fix 1 1 1 1
    fix 3 1 1 1
    fix 7 1 1 1
    geomTransf Linear 1
    element elasticBeamColumn 1 1 2 0.16 $E 2.13e-3 1
    element elasticBeamColumn 2 3 4 0.16 $E 2.13e-3 1
    element elasticBeamColumn 3 5 6 0.12 $E 1.6e-3 1
    element elasticBeamColumn 4 7 8 0.09 $E 6.75e-4 1
    set gravity {0.0 -1 0.0}
    set lateral {1.0 0.0 0.0}
    set moment {0.0 0.0 1.0}
    set dofs {1 2 3}
    set excitations {1 1.5}
} else {
    model basic -ndm 3 -ndf 6
    set mr [expr {$m * 0.5}]
    node 1 0.0 0.0 0.0
    node 2 0.0 0.0 $h -mass $m $m $m $mr $mr $mr
    node 3 5.0 1.0 0.0
    node 4 5.0 1.0 $h -mass $m $m $m $mr $mr $mr
    node 5 0.35 0.2 [expr {$h + 0.25}]
    node 6 4.6 0.75 [expr {$h + 0.3}]
    node 7 7.0 1.0 0.0
    node 8 7.0 1.0 $h -mass $m $m $m 0.0 0.0 0.0
    foreach n {1 3 7} { fix $n 1 1 1 1 1 1 }
    geomTransf Linear 1 1.0 0.0 0.0
    geomTransf Linear 2 0.0 0.0 1.0
    set G 1.25e10
    element elasticBeamColumn 1 1 2 0.16 $E $G 3.6e-3 2.13e-3 2.6e-3 1
    element elasticBeamColumn 2 3 4 0.16 $E $G 3.6e-3 2.13e-3 2.6e-3 1
    element elasticBeamColumn 3 5 6 0.12 $E $G 2.5e-3 1.6e-3 1.1e-3 2
    element elasticBeamColumn 4 7 8 0.09 $E $G 1.1e-3 6.75e-4 6.75e-4 1
    set gravity {0.0 0.0 -1 0.0 0.0 0.0}
    set lateral {1.0 0.4 0.0 0.0 0.0 0.0}
    set moment {0.0 0.0 0.0 0.3 -0.2 1.0}
    set dofs {1 2 3 4 5 6}
    set excitations {1 1.5 2 0.9}
}
rigidLink beam 2 5
rigidLink beam 4 6
equalDOF 4 8 1
proc scaled {vector factor} {
    set result {}
    foreach v $vector { lappend result [expr {$v * $factor}] }
    return $result
}
pattern Plain 1 Linear {
    foreach n {2 4 8} { eval load $n [scaled $gravity [expr {$m * $g}]] }
    eval load 2 [scaled $lateral 4.0e4]
    eval load 4 [scaled $moment 2.0e4]
}
eval recorder Node -file $out/rigid_beam_disp.out -time -precision 16 -node 2 4 5 6 8 \
    -dof $dofs disp
eval recorder Node -file $out/rigid_beam_base.out -time -precision 16 -node 1 3 7 \
    -dof $dofs reaction
recorder Element -file $out/rigid_beam_force.out -time -precision 16 -ele 3 4 localForce
tie_static $handler
set dt 0.005
set steps 600
tie_transient $handler $excitations $dt $steps
set status [analyze [expr {$steps / 2}] $dt]
remove mp 6
remove mp 8
set status [expr {$status + [analyze [expr {$steps / 2}] $dt]}]
puts "rigid_beam $dim $handler: status $status time [getTime] end [nodeDisp 6 1]"
