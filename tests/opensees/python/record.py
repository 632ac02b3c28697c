"""The synthetic ground acceleration of record.tcl, evaluated as Tcl's expr
evaluates it (the C library's sin and exp, the same order of operations),
so that a Path series made from it holds the Tcl script's doubles."""
import math

PI = 3.14159265358979


def synthetic_record(dt, n, scale=1.0):
    return [scale * (3.0 * math.sin(2 * PI * 1.3 * (i * dt)) * math.exp(-0.3 * (i * dt))
                     + 1.5 * math.sin(2 * PI * 4.1 * (i * dt)) * math.exp(-0.5 * (i * dt)))
            for i in range(n + 1)]
