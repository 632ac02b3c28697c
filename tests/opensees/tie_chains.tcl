# Chains of constraints through rigid ties: an equalDOF whose retained node
# is a rigid tie's constrained node, a rigidLink beam whose retained node is
# such an equalDOF's constrained node, and a rigidLink beam whose retained
# node is another link's constrained node. Each constrained DOF follows the
# first retained node through the chain (u_c = C_cr u_r composed along it),
# as OpenSees's Lagrange handler meets the constraints. 2d: rigidLink beam
# 2 5, equalDOF 5 6 1 2, rigidLink beam 6 8, rigidLink beam 4 9 and 9 10;
# 3d: rigidDiaphragm 3 2 5 12, equalDOF 5 7 1 2, rigidLink beam 4 9 and
# 9 10, equalDOF 10 11 1 2 3. Elastic columns and beams hold the free DOFs;
# the masses are at the first retained nodes. Gravity, a lateral load, a
# moment and loads on constrained nodes by LoadControl, then the synthetic
# record with Rayleigh damping. argv: the output directory, 2d|3d, the
# handler's words (Transformation, Lagrange or Penalty alphaSP alphaMP).
set out [lindex $argv 0]
set dim [lindex $argv 1]
set handler [expr {[llength $argv] > 2 ? [lrange $argv 2 end] : "Transformation"}]
source [file join [file dirname [info script]] record.tcl]
source [file join [file dirname [info script]] tie_analysis.tcl]
wipe
set h 3.0
set m 8.0e3
set E 3.0e10
if {$dim eq "2d"} {
    model basic -ndm 2 -ndf 3
    node 1 0.0 0.0
    node 2 0.0 $h -mass $m $m [expr {$m * 0.5}]
    node 3 5.0 0.0
    node 4 5.0 $h -mass $m $m [expr {$m * 0.5}]
    node 5 0.35 [expr {$h + 0.25}]
    node 6 4.6 [expr {$h + 0.3}]
    node 7 4.4 0.0
    node 8 1.0 [expr {$h + 0.8}]
    node 9 5.5 [expr {$h - 0.2}]
    node 10 6.2 [expr {$h + 0.4}]
    node 11 6.2 0.0
    foreach n {1 3 7 11} { fix $n 1 1 1 }
    geomTransf Linear 1
    element elasticBeamColumn 1 1 2 0.16 $E 2.13e-3 1
    element elasticBeamColumn 2 3 4 0.16 $E 2.13e-3 1
    element elasticBeamColumn 3 5 6 0.12 $E 1.6e-3 1
    element elasticBeamColumn 4 7 6 0.09 $E 6.75e-4 1
    element elasticBeamColumn 5 8 10 0.12 $E 1.6e-3 1
    element elasticBeamColumn 6 11 10 0.09 $E 6.75e-4 1
    rigidLink beam 2 5
    equalDOF 5 6 1 2
    rigidLink beam 6 8
    rigidLink beam 4 9
    rigidLink beam 9 10
    set loads {2 {0.0 -7.8e4 0.0} 4 {0.0 -7.8e4 2.0e4} 2 {4.0e4 0.0 0.0}
               6 {0.0 -5.0e3 2.0e3} 10 {3.0e3 0.0 0.0}}
    set dofs {1 2 3}
    set disp_nodes {2 4 5 6 8 9 10}
    set force_elements {3 5}
    set excitations {1 1.5}
} else {
    model basic -ndm 3 -ndf 6
    set mr [expr {$m * 0.5}]
    node 1 0.0 0.0 0.0
    node 2 0.0 0.0 $h -mass $m $m $m $mr $mr $mr
    node 3 5.0 1.0 0.0
    node 4 5.0 1.0 $h -mass $m $m $m $mr $mr $mr
    node 5 0.4 0.5 $h
    node 12 0.3 2.5 $h
    node 7 3.0 0.5 $h
    node 9 5.4 1.3 [expr {$h + 0.3}]
    node 10 6.0 0.7 [expr {$h + 0.1}]
    node 11 6.5 2.0 [expr {$h + 0.2}]
    node 13 0.4 0.5 0.0
    node 14 0.3 2.5 0.0
    node 15 3.0 0.5 0.0
    node 16 6.5 2.0 0.0
    foreach n {1 3 13 14 15 16} { fix $n 1 1 1 1 1 1 }
    geomTransf Linear 1 1.0 0.0 0.0
    geomTransf Linear 2 0.0 0.0 1.0
    set G 1.25e10
    element elasticBeamColumn 1 1 2 0.16 $E $G 3.6e-3 2.13e-3 2.6e-3 1
    element elasticBeamColumn 2 3 4 0.16 $E $G 3.6e-3 2.13e-3 2.6e-3 1
    element elasticBeamColumn 3 13 5 0.09 $E $G 1.1e-3 6.75e-4 6.75e-4 1
    element elasticBeamColumn 4 14 12 0.09 $E $G 1.1e-3 6.75e-4 6.75e-4 1
    element elasticBeamColumn 5 15 7 0.09 $E $G 1.1e-3 6.75e-4 6.75e-4 1
    element elasticBeamColumn 6 16 11 0.09 $E $G 1.1e-3 6.75e-4 6.75e-4 1
    element elasticBeamColumn 7 7 10 0.12 $E $G 2.5e-3 1.6e-3 1.1e-3 2
    rigidDiaphragm 3 2 5 12
    equalDOF 5 7 1 2
    rigidLink beam 4 9
    rigidLink beam 9 10
    equalDOF 10 11 1 2 3
    set loads {2 {0.0 0.0 -7.8e4 0.0 0.0 0.0} 4 {0.0 0.0 -7.8e4 0.0 0.0 0.0}
               2 {4.0e4 1.6e4 0.0 0.0 0.0 0.0} 4 {0.0 0.0 0.0 6.0e3 -4.0e3 2.0e4}
               7 {2.0e3 -3.0e3 -5.0e3 0.0 0.0 1.0e3} 10 {3.0e3 1.0e3 0.0 0.0 0.0 0.0}}
    set dofs {1 2 3 4 5 6}
    set disp_nodes {2 4 5 7 9 10 11 12}
    set force_elements {3 5 7}
    set excitations {1 1.5 2 0.9}
}
pattern Plain 1 Linear {
    foreach {n load} $loads { eval load $n $load }
}
eval recorder Node -file $out/tie_chains_disp.out -time -precision 16 -node $disp_nodes \
    -dof $dofs disp
eval recorder Element -file $out/tie_chains_force.out -time -precision 16 -ele $force_elements localForce
tie_static $handler
set dt 0.005
set steps 400
tie_transient $handler $excitations $dt $steps
set status [analyze $steps $dt]
puts "tie_chains $dim $handler: status $status time [getTime] end [nodeDisp 10 1]"
