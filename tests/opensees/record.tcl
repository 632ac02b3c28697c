# A synthetic ground acceleration (m/s^2) shared by the corpus scripts: two
# decaying sines, sampled every $dt s for $n steps. Sourced by the scripts;
# tests/opensees/reference.py evaluates the same formula.
proc synthetic_record {dt n {scale 1.0}} {
    set pi 3.14159265358979
    set values {}
    for {set i 0} {$i <= $n} {incr i} {
        set t [expr {$i * $dt}]
        lappend values [expr {$scale * (3.0 * sin(2 * $pi * 1.3 * $t) * exp(-0.3 * $t)
                                        + 1.5 * sin(2 * $pi * 4.1 * $t) * exp(-0.5 * $t))}]
    }
    return $values
}
