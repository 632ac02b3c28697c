#!/usr/bin/env python3
"""Whether two runs' CSV time series are the same trajectory to a tolerance
(tests/cli/distributed.sh): same header, same rows, the same text in every
non-numeric field, and in every numeric column
    max |a - b| <= tolerance * max |a|
over the column (the column's own scale: a value that passes through zero
is compared at the size of the response, not at its rounding noise).
The energy balance error column is rounding noise itself and is skipped.
With --common-scale every column is compared at the largest value of the
whole file (energy.csv: the terms of one balance, where a term that is
round-off of the others, the dissipation of an elastic gap, has no scale
of its own).

  same_trajectory.py [--common-scale] TOLERANCE REFERENCE.csv CANDIDATE.csv
Exit status 0 when they agree, 1 (with the worst column) when not.
"""
import csv
import sys

SKIPPED = {"balance_error"}


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def main():
    arguments = sys.argv[1:]
    common = arguments[0] == "--common-scale"
    if common:
        arguments = arguments[1:]
    tolerance, reference, candidate = float(arguments[0]), arguments[1], arguments[2]
    with open(reference) as f:
        a = list(csv.reader(f))
    with open(candidate) as f:
        b = list(csv.reader(f))
    if not a or a[0] != b[0]:
        sys.exit("%s: the header differs" % candidate)
    if len(a) != len(b):
        sys.exit("%s: %d rows instead of %d" % (candidate, len(b) - 1, len(a) - 1))
    header = a[0]
    scale = [0.0] * len(header)
    error = [0.0] * len(header)
    for row, (x, y) in enumerate(zip(a[1:], b[1:]), start=2):
        if len(x) != len(y):
            sys.exit("%s line %d: %d fields instead of %d" % (candidate, row, len(y), len(x)))
        for c, (p, q) in enumerate(zip(x, y)):
            u, v = number(p), number(q)
            if u is None or v is None:
                if p != q:
                    sys.exit("%s line %d, %s: '%s' instead of '%s'" % (candidate, row, header[c], q, p))
                continue
            scale[c] = max(scale[c], abs(u))
            error[c] = max(error[c], abs(u - v))
    if common:
        scale = [max(scale)] * len(header)
    worst, name = 0.0, ""
    for c, column in enumerate(header):
        if column in SKIPPED or scale[c] == 0:
            if scale[c] == 0 and error[c] > 0:
                sys.exit("%s, %s: %g where the reference is 0" % (candidate, column, error[c]))
            continue
        if error[c] / scale[c] > worst:
            worst, name = error[c] / scale[c], column
    if worst > tolerance:
        sys.exit("%s, %s: differs by %.3g of its largest value (tolerance %g)"
                 % (candidate, name, worst, tolerance))
    print("%s: largest difference %.3g of a column's largest value (%s)" % (candidate, worst, name or "-"))


if __name__ == "__main__":
    main()
