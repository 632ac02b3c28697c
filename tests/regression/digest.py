#!/usr/bin/env python3
"""Numbers of a poundfe results directory, one per line, for regression.

  digest.py DIR            print the digest of DIR
  digest.py --compare A B  compare two digests; exit 1 on a difference

A digest line is `key value`. Keys name the file and the place of the
number: `summary:buildings.0.storeys.1.peak_drift_ratio`,
`impacts.csv:3:peak_force`, `drift.csv@t=2.5:A3_storey1_drift_ratio`.
Taken: every number of summary.json except those of the clock; every row
of impacts.csv and realizations.csv; of each time series (every CSV whose
first column is `time`) the rows at 41 evenly spaced row indices and the
last row; the small per-storey CSVs (profiles) whole.

Comparison (tolerance 1e-12 relative): two values agree when
|a - b| <= 1e-12 * scale, where scale is the largest |value| of the same
column (time series, tables) or the value itself (summary). A time series
that starts at exactly zero would otherwise be compared to round-off on
its first rows. Keys renamed on purpose are listed in RENAMED below, old
name first, so a rename never hides a changed number.
"""
import csv
import json
import math
import os
import re
import sys

TOLERANCE = 1e-12
# Quantities of the clock or of the machine, not of the analysis.
SKIPPED = re.compile(r"(wall_time|steps_per_second|realizations_per_second|set_up_time|"
                     r"\.input$|\.ranks$|realizations_run_now)")
SAMPLES = 41

# old key pattern -> new key (re.sub), applied to the reference before
# comparing. Each rename of an output column or summary field goes here.
RENAMED = [
]


def flatten(prefix, node, out):
    if isinstance(node, dict):
        for k, v in node.items():
            flatten(f"{prefix}.{k}" if prefix else k, v, out)
    elif isinstance(node, list):
        for i, v in enumerate(node):
            flatten(f"{prefix}.{i}", v, out)
    elif isinstance(node, bool):
        out.append((prefix, float(node)))
    elif isinstance(node, (int, float)):
        out.append((prefix, float(node)))


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def table(path, name, out, sample):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        return
    header, body = rows[0], rows[1:]
    if sample and len(body) > SAMPLES:
        step = (len(body) - 1) / (SAMPLES - 1)
        picked = sorted({round(i * step) for i in range(SAMPLES)} | {len(body) - 1})
    else:
        picked = range(len(body))
    time_keyed = header and header[0] == "time"
    for i in picked:
        row = body[i]
        where = f"@t={row[0]}" if time_keyed else f":{i}"
        for column, text in zip(header, row):
            value = number(text)
            if value is not None and not (time_keyed and column == "time"):
                out.append((f"{name}{where}:{column}", value))


def digest(directory):
    out = []
    for name in sorted(os.listdir(directory)):
        path = os.path.join(directory, name)
        if name == "summary.json":
            items = []
            with open(path) as f:
                flatten("", json.load(f), items)
            out += [("summary:" + k, v) for k, v in items if not SKIPPED.search(k)]
        elif name.endswith(".csv"):
            with open(path) as f:
                first = f.readline()
            table(path, name, out, sample=first.startswith("time,"))
    return out


def read(path):
    values = {}
    with open(path) as f:
        for line in f:
            key, _, text = line.rstrip("\n").rpartition(" ")
            values[key] = float(text)
    return values


def column_of(key):
    """The column a key belongs to: the key without its row."""
    return re.sub(r"(@t=[^:]*|:\d+):", ":", key, count=1)


def compare(reference_path, actual_path):
    reference = read(reference_path)
    for old, new in RENAMED:
        reference = {re.sub(old, new, k): v for k, v in reference.items()}
    actual = read(actual_path)
    scale = {}
    for key, value in reference.items():
        if not key.startswith("summary:"):
            c = column_of(key)
            scale[c] = max(scale.get(c, 0.0), abs(value))
    problems = []
    for key, expected in reference.items():
        if key not in actual:
            problems.append(f"missing {key}")
            continue
        got = actual[key]
        s = abs(expected) if key.startswith("summary:") else scale[column_of(key)]
        if got == expected or (math.isnan(expected) and math.isnan(got)):
            continue
        if not abs(got - expected) <= TOLERANCE * max(s, abs(expected)):
            problems.append(f"{key}: {got!r} instead of {expected!r} "
                            f"(difference {abs(got - expected) / max(s, 1e-300):.3g} relative)")
    for message in problems[:20]:
        print("  " + message)
    if len(problems) > 20:
        print(f"  ... and {len(problems) - 20} more")
    return not problems, len(reference)


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "--compare":
        ok, n = compare(sys.argv[2], sys.argv[3])
        print(f"{'ok  ' if ok else 'FAIL'} {os.path.basename(sys.argv[2])}: {n} numbers")
        sys.exit(0 if ok else 1)
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    for key, value in digest(sys.argv[1]):
        print(f"{key} {value!r}")
