# The analyses shared by the rigid-tie scripts (rigid_beam.tcl,
# tie_chains.tcl), sourced by them: their handler's words, algorithm Newton
# (Linear under Lagrange: OpenSees 3.8's NormDispIncr counts the
# multipliers, which stall above 1e-10), BandGeneral, NormDispIncr 1e-10.
proc tie_algorithm {handler} {
    return [expr {[lindex $handler 0] eq "Lagrange" ? "Linear" : "Newton"}]
}
proc tie_solution {handler} {
    constraints {*}$handler
    numberer Plain
    system BandGeneral
    test NormDispIncr 1.0e-10 20
    algorithm [tie_algorithm $handler]
}
# The loads of pattern 1 in four LoadControl steps, then held.
proc tie_static {handler} {
    tie_solution $handler
    integrator LoadControl 0.25
    analysis Static
    analyze 4
    loadConst -time 0.0
    wipeAnalysis
}
# Rayleigh damping (mass and committed stiffness) and the synthetic record
# (record.tcl) of $steps steps of $dt along each {direction scale} pair,
# ready for analyze under Newmark.
proc tie_transient {handler excitations dt steps} {
    rayleigh 0.25 0.0 0.0 0.002
    set tag 2
    foreach {direction scale} $excitations {
        timeSeries Path $tag -dt $dt -values [synthetic_record $dt $steps $scale]
        pattern UniformExcitation $tag $direction -accel $tag
        incr tag
    }
    tie_solution $handler
    integrator Newmark 0.5 0.25
    analysis Transient
}
