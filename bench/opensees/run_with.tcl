# Runs a corpus script for bench/opensees/speed.py, in poundfe or OpenSees.
# argv: the output directory, the number of transient steps (0: the
# script's own; the script reads ::bench_steps), "full", "setup" (every
# analyze with a time step, the transient one, skipped: the model, the
# record and the static steps alone) or "loop" (each `analyze n dt` run as
# n calls of `analyze 1 dt` in a Tcl loop, as scripts often step), the
# script and its own words.
lassign $argv out steps mode script
set argv [list $out {*}[lrange $argv 4 end]]
set argc [llength $argv]
if {$steps > 0} {
    set ::bench_steps $steps
}
if {$mode eq "setup"} {
    rename analyze bench_analyze
    proc analyze {n args} {
        if {[llength $args] > 0} {
            return 0
        }
        return [bench_analyze $n]
    }
}
if {$mode eq "loop"} {
    rename analyze bench_analyze
    proc analyze {n args} {
        if {[llength $args] == 0} {
            return [bench_analyze $n]
        }
        for {set i 0} {$i < $n} {incr i} {
            set status [bench_analyze 1 {*}$args]
            if {$status != 0} {
                return $status
            }
        }
        return 0
    }
}
source $script
