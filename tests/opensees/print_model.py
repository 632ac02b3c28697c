#!/usr/bin/env python3
"""printModel -JSON and print -node of tests/opensees/print_model.tcl
against OpenSees 3.8's own files of the same script (print_model_opensees/).

    print_model.py OUTPUT_DIR REFERENCE_DIR

Each JSON file is read with Python's json: the same keys, lists of the same
length, the same strings, and numbers equal to 1e-12 of their magnitude
(OpenSees writes 6 significant digits; the script's values have fewer, so
both files hold the same decimals, and 1e-12 leaves room for ElasticPP's
eps_y, which OpenSees writes as (E eps_y)/E), or, for the numbers OpenSees
computes (Hysteretic's slopes, a twoNodeLink's direction cosines), ours
rounded to its 6 digits equal to 1e-12; inside a fibre section, also any
two numbers within 1e-12 of the section's size (its largest fibre
coordinate), so that coordinates zero to round-off compare equal. print_model_links.tcl gives
model_links_2d.json and model_links_3d.json. The node text must be the
same bytes; after the transient analysis of print_model_rayleigh.tcl
(nodes_rayleigh.txt: velocities, accelerations and Rayleigh forces, which
OpenSees writes to 6 digits) too, once OpenSees's `unbalanced Load` and
`ID` lines, which poundfe does not write, are dropped. Exit 1 naming the
first difference."""
import json
import os
import sys


def section_size(section):
    """The largest |coordinate| of a fibre section's fibres (0 for others)."""
    fibres = section.get("fibers", []) if isinstance(section, dict) else []
    return max((abs(c) for f in fibres for c in f.get("coord", [])), default=0.0)


def differences(a, b, where, floor=0.0):
    """floor: the absolute difference taken as equal, 1e-12 of the size of
    the fibre section the numbers are in (a fibre's coordinate that is zero
    to round-off is computed as 1e-17 by one program, 1e-19 by the other)."""
    if isinstance(a, dict) and isinstance(b, dict):
        if list(a) != list(b):
            return [f"{where}: keys {list(a)} != {list(b)}"]
        floor = max(floor, 1e-12 * section_size(b))
        return [d for k in a for d in differences(a[k], b[k], f"{where}.{k}", floor)]
    if isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            return [f"{where}: {len(a)} items != {len(b)}"]
        return [d for i, (x, y) in enumerate(zip(a, b))
                for d in differences(x, y, f"{where}[{i}]", floor)]
    numbers = (int, float)
    if isinstance(a, numbers) and isinstance(b, numbers) and not isinstance(a, bool):
        close = lambda x: abs(x - b) <= max(1e-12 * max(abs(x), abs(b)), floor)
        # a number OpenSees computes (a slope, a direction cosine) it
        # writes to 6 significant digits: ours rounded to them
        return [] if close(a) or close(float(f"{a:.6g}")) else [f"{where}: {a} != {b}"]
    return [] if a == b else [f"{where}: {a!r} != {b!r}"]


def main(output, reference):
    for name in ("model_2d.json", "model_3d.json", "model_links_2d.json", "model_links_3d.json"):
        with open(os.path.join(output, name)) as f, open(os.path.join(reference, name)) as g:
            found = differences(json.load(f), json.load(g), name)
        if found:
            sys.exit("\n".join(found[:5]))
    with open(os.path.join(output, "nodes.txt")) as f, open(os.path.join(reference, "nodes.txt")) as g:
        if f.read() != g.read():
            sys.exit("nodes.txt differs from OpenSees's")
    with open(os.path.join(output, "nodes_rayleigh.txt")) as f, \
            open(os.path.join(reference, "nodes_rayleigh.txt")) as g:
        theirs = [line for line in g.read().splitlines(True)
                  if not line.startswith(("\t unbalanced Load:", "\tID :"))]
        if f.read() != "".join(theirs):
            sys.exit("nodes_rayleigh.txt differs from OpenSees's")


if __name__ == "__main__":
    main(*sys.argv[1:3])
