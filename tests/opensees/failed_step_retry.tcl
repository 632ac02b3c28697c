# A force-based cantilever on section Aggregator (a two-point Hysteretic in
# Mz, Elastic P) cycled by DisplacementControl, retrying each failed step as
# four quarter steps. Its Newton iteration stalls near the envelope's corner
# (4e-9 for 40 iterations), so steps fail and are reverted. OpenSees 3.8's
# Domain::revertToLastCommit ends with an update of every element at the
# committed displacements, and HystereticMaterial::revertToLastCommit leaves
# its tangent (Ttangent) as the failed trial made it: the next step's first
# tangent is that one, so a step may fail where the committed tangent would
# converge (here two steps fail, and their retries too: 44 rows; with the
# committed tangent none fails: 54 rows). (kN, m)
#   argv: the output directory, the list of targets of the top's drift
#   (default {0.02 -0.025 0.0}).
set out [lindex $argv 0]
set targets [expr {[llength $argv] > 1 ? [lindex $argv 1] : {0.02 -0.025 0.0}}]
wipe
model basic -ndm 2 -ndf 3
uniaxialMaterial Hysteretic 2 180.0 0.004 240.0 0.03 -180.0 -0.004 -240.0 -0.03 1.0 1.0 0.0 0.0 0.0
uniaxialMaterial Elastic 3 1.0e7
section Aggregator 1 2 Mz 3 P
node 1 0.0 0.0
node 2 0.0 3.5
fix 1 1 1 1
geomTransf Linear 1
element forceBeamColumn 1 1 2 5 1 1
recorder Node -file $out/top.out -time -precision 16 -node 2 -dof 1 2 3 disp
recorder Node -file $out/base.out -time -precision 16 -node 1 -dof 1 2 3 reaction
recorder Element -file $out/section.out -time -precision 16 -ele 1 section 1 deformation
timeSeries Linear 1
pattern Plain 1 1 { load 2 1.0 -100.0 0.0 }
constraints Plain
numberer Plain
system FullGeneral
test NormDispIncr 1e-12 40
algorithm Newton
integrator LoadControl 0.0
analysis Static
set u 0.0
set failures 0
foreach target $targets {
    set n [expr {int(ceil(abs($target - $u) / 0.0017))}]
    set step [expr {($target - $u) / $n}]
    for {set k 0} {$k < $n} {incr k} {
        integrator DisplacementControl 2 1 $step
        if {[analyze 1] != 0} {
            incr failures
            integrator DisplacementControl 2 1 [expr {$step / 4.0}]
            if {[analyze 4] != 0} { break }
        }
    }
    set u [nodeDisp 2 1]
}
puts "failures $failures"
