# An RC cantilever column (0.4 m x 0.4 m, 3 m, 8 bars of 20 mm; P-Delta)
# under an axial load of 10 % of f'c Ag by LoadControl in 10 steps, held
# (loadConst -time 0), then pushed cyclically at its top by
# DisplacementControl: 0.5 %, 1 % and 2 % drift, one cycle each, 1.5 mm a
# step, Newton with NormDispIncr.
#   argv: OUTPUT_DIR force|disp
#   force: one forceBeamColumn, Lobatto 5 points;
#   disp:  three dispBeamColumns, Legendre 3 points each.
set out [lindex $argv 0]
set kind [lindex $argv 1]
source [file join [file dirname [info script]] rc_section.tcl]
wipe
model basic -ndm 2 -ndf 3
set H 3.0
set n [expr {$kind eq "force" ? 1 : 3}]
for {set i 0} {$i <= $n} {incr i} { node [expr {$i + 1}] 0.0 [expr {$H*$i/$n}] }
set top [expr {$n + 1}]
fix 1 1 1 1
rc_materials
rc_section 1 0.4 0.4 0.04 3 3.14e-4
geomTransf PDelta 1
if {$kind eq "force"} {
    beamIntegration Lobatto 1 1 5
    element forceBeamColumn 1 1 2 1 1
} else {
    for {set i 1} {$i <= $n} {incr i} {
        element dispBeamColumn $i $i [expr {$i + 1}] 3 1 1
    }
}
recorder Node -file $out/column_${kind}_top.out -time -precision 12 -node $top -dof 1 2 3 disp
recorder Node -file $out/column_${kind}_base.out -time -precision 12 -node 1 -dof 1 2 3 reaction
recorder Element -file $out/column_${kind}_section.out -time -precision 12 -ele 1 section 1 force
recorder Element -file $out/column_${kind}_deformation.out -time -precision 12 -ele 1 section 1 deformation
timeSeries Linear 1
pattern Plain 1 1 { load $top 0.0 -480.0 0.0 }
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-12 50
algorithm Newton
integrator LoadControl 0.1
analysis Static
analyze 10
loadConst -time 0.0
pattern Plain 2 1 { load $top 1.0 0.0 0.0 }
set du 0.0015
set status 0
foreach drift {0.005 0.01 0.02} {
    set amplitude [expr {$drift*$H}]
    foreach {target sign} [list $amplitude 1 [expr {-$amplitude}] -1 0.0 1] {
        set steps [expr {round(abs($target - [nodeDisp $top 1])/$du)}]
        integrator DisplacementControl $top 1 [expr {$sign*$du}]
        set status [expr {$status + [analyze $steps]}]
    }
}
puts "column $kind: status $status top [nodeDisp $top 1] [expr {[namespace exists ::poundfe] ? [poundfe::report] : ""}]"
