# poundfe::energy and poundfe::impacts across analyze calls (two sticks
# pounding through an ElasticPPGap, Rayleigh damping). argv: the case,
# reset (a `reset` starts both again: the same 1000 steps after it, taken
# one `analyze 1 dt` at a time, give the balance and the episodes of the
# first 1000, taken by one analyze) or rayleigh (new Rayleigh factors
# between two analyze calls: the balance's damping vectors are built anew,
# and it still closes within 1e-8 of its largest term, the equilibrium
# Newton's 1e-12 m test leaves).
set case [lindex $argv 0]
source [file join [file dirname [info script]] record.tcl]
wipe
model basic -ndm 1 -ndf 1
set pi 3.14159265358979
set m 1.0e5
node 1 0.0; node 2 0.0 -mass $m; node 3 0.0; node 4 0.0 -mass $m
fix 1 1; fix 3 1
uniaxialMaterial Elastic 1 [expr {$m * pow(2 * $pi / 0.5, 2)}]
uniaxialMaterial Elastic 2 [expr {$m * pow(2 * $pi / 1.0, 2)}]
uniaxialMaterial ElasticPPGap 3 2.0e9 -4.0e6 -0.01 0.1 damage
element zeroLength 1 1 2 -mat 1 -dir 1 -doRayleigh 1
element zeroLength 2 3 4 -mat 2 -dir 1 -doRayleigh 1
element zeroLength 3 2 4 -mat 3 -dir 1
set dt 0.002
timeSeries Path 1 -dt $dt -values [synthetic_record $dt 2000 0.6]
pattern UniformExcitation 1 1 -accel 1
rayleigh 0.3 1.0e-3 0.0 0.0
constraints Plain
numberer Plain
system BandGeneral
test NormDispIncr 1.0e-12 50
algorithm Newton
integrator Newmark 0.5 0.25
analysis Transient
poundfe::energy on
poundfe::impacts on
proc run_steps {n one_at_a_time} {
    if {!$one_at_a_time} {
        if {[analyze $n $::dt] != 0} { error "analyze failed" }
        return
    }
    for {set i 0} {$i < $n} {incr i} {
        if {[analyze 1 $::dt] != 0} { error "step $i failed" }
    }
}
switch -- $case {
    reset {
        run_steps 1000 0
        set first [poundfe::energy]
        set n_first [llength [poundfe::impacts]]
        reset
        run_steps 1000 1
        set second [poundfe::energy]
        set n_second [llength [poundfe::impacts]]
        puts "energy_restart reset: $n_first then $n_second impacts; $first; $second"
        if {$n_first == 0 || $n_second != $n_first} {
            error "impacts: $n_first before the reset, $n_second after it"
        }
        # the same steps from the same start: the same sums to round-off
        foreach term {input kinetic elements damping contact} {
            set a [dict get $first $term]
            set b [dict get $second $term]
            if {abs($a - $b) > 1.0e-9 * max(abs($a), 1.0e-30)} {
                error "$term: $a before the reset, $b after it"
            }
        }
    }
    rayleigh {
        run_steps 1000 1
        rayleigh 0.6 2.0e-3 0.0 0.0
        run_steps 1000 1
        set energy [poundfe::energy]
        puts "energy_restart rayleigh: $energy"
        if {[dict get $energy relative_residual] > 1.0e-8} {
            error "the residual [dict get $energy relative_residual] of the largest term exceeds 1e-8"
        }
    }
    default { error "energy_restart.tcl: no case '$case'" }
}
