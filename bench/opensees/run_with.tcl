# Runs a corpus script for bench/opensees/speed.py, in poundfe or OpenSees.
# argv: the output directory, the number of transient steps (0: the
# script's own; the script reads ::bench_steps), "full" or "setup" (every
# analyze with a time step, the transient one, skipped: the model, the
# record and the static steps alone), the script and its own words.
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
source $script
