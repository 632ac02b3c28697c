#!/usr/bin/env python3
"""Whether two VTU frames hold the same field: the same points, cells and
field data, and every point and cell array within TOLERANCE of that array's
largest magnitude (as same_trajectory.py compares a CSV column to its peak).
What a frame of a run over ranks is compared with: the one-process frame.

  usage: same_vtu.py TOLERANCE REFERENCE.vtu OTHER.vtu

Exit 0 when they agree, else 1 with the first difference on stdout.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vtu  # noqa: E402  (read_vtu: Python's XML parser, base64 and zlib)


def main():
    tolerance, reference, other = float(sys.argv[1]), sys.argv[2], sys.argv[3]
    a, b = vtu.read_vtu(reference), vtu.read_vtu(other)
    # a 3D model's contact points stand where its gaps' ends do: coincident points are its own
    unreadable = [f for f in vtu.failures if "duplicated points" not in f]
    if unreadable:
        print("unreadable: " + "; ".join(unreadable))
        return 1
    for key in ("fields", "xyz", "cells"):
        if a[key] != b[key]:
            print(f"{other}: other {key} than {reference}")
            return 1
    for where in ("point", "cell"):
        if a[where].keys() != b[where].keys():
            print(f"{other}: other {where} arrays than {reference}")
            return 1
        for name, values in a[where].items():
            theirs = b[where][name]
            if len(values) != len(theirs):
                print(f"{other}: {where} array {name}: {len(theirs)} values, not {len(values)}")
                return 1
            scale = max([abs(x) for x in values] + [1e-300])
            for i, (x, y) in enumerate(zip(values, theirs)):
                if not abs(x - y) <= tolerance * scale:
                    print(f"{other}: {where} array {name}[{i}]: {y!r} against {x!r} "
                          f"(largest {scale:g})")
                    return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
