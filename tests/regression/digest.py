#!/usr/bin/env python3
"""Numbers of a poundfe results directory, one per line, for regression.

  digest.py DIR            print the digest of DIR
  digest.py --compare A B  compare two digests; exit 1 on a difference

A digest line is `key value`. Keys name the file and the place of the
number: `summary:buildings.0.storeys.1.peak_drift_ratio`,
`impacts.csv:3:peak_force`, `drift.csv@t=2.5:A3_storey1_drift_ratio`. The reference digests in
reference/ were taken before the engine was reshaped (issue 10); RENAMED
maps their keys to today's names.
Taken: every number of summary.json except those of the clock; every row
of impacts.csv and realizations.csv; of each time series (every CSV whose
first column is `time`) the rows at 41 evenly spaced row indices and the
last row; the small per-storey CSVs (profiles) whole.

Comparison (tolerance 1e-8 relative): two values agree when
|a - b| <= 1e-8 * scale, where scale is the largest |value| of the same
column (time series, tables), of the same list (summary.json: e.g. the
participating mass ratios of every mode) or the value itself (the other
summary numbers). A time series that starts at exactly zero, or a mode's
mass ratio of 1e-31 (zero), would otherwise be compared to round-off.
The energy balance error, itself a round-off figure relative to the
energy, is compared absolutely (|a - b| <= 1e-8).
Why 1e-8 and not round-off: the digests must hold on every machine that
runs CI. The CPU decides which libm and BLAS kernels run (FMA, AVX-512),
which changes last bits, and impacts amplify them: the digests taken on
one VM differed on another (an AMD EPYC with AVX-512) by up to 2.2e-9 of
a column's peak (3d-torsional-pair, contact energy), everywhere else by
less than 1e-12. A change of the engine's behaviour moves numbers by far
more. Keys renamed on purpose are listed in RENAMED below, old name
first, so a rename never hides a changed number.
"""
import csv
import json
import math
import os
import re
import sys

TOLERANCE = 1e-8
# figures that are themselves round-off: compared absolutely
ABSOLUTE = re.compile(r"balance_error$")
# Quantities of the clock or of the machine, not of the analysis.
SKIPPED = re.compile(r"(wall_time|steps_per_second|realizations_per_second|set_up_time|"
                     r"\.input$|\.ranks$|realizations_run_now)")
SAMPLES = 41

# (digest file pattern, old key pattern, new key or None to drop), applied
# with re.sub to the reference before comparing. Each rename of an output
# column or summary field goes here.
HINGE_FILES = r"^(?!bouc-wen-sdof|subset-drift)"  # examples whose hysteretic elements are hinges
STOREY_FILES = r"^(bouc-wen-sdof|subset-drift)"   # ... Bouc-Wen storeys
RENAMED = [
    # issue 10: every CSV column carries its unit, profiles name the building
    ("", r"^(drift\.csv@[^:]*:.*_storey\d+)$", r"\1_drift_ratio"),
    ("", r"^(floor_acceleration\.csv@[^:]*:.*_floor\d+)$", r"\1_acc_m_s2"),
    ("", r"^(floor_displacement\.csv@[^:]*:.*_floor\d+)$", r"\1_disp_m"),
    ("", r"^(ground_motion\.csv@[^:]*:ground_acceleration)$", r"\1_m_s2"),
    ("", r"^(energy\.csv@[^:]*:(input|kinetic|damping|strain|hysteretic|contact))$", r"\1_J"),
    ("", r"^(hinges\.csv@[^:]*:.*_S\d+)_force$", r"\1_force_N"),
    ("", r"^(hinges\.csv@[^:]*:.*_S\d+)_deformation$", r"\1_drift_m"),
    ("", r"^(hinges\.csv@[^:]*:.*)_force$", r"\1_moment_N_m"),
    ("", r"^(hinges\.csv@[^:]*:.*)_deformation$", r"\1_rotation_rad"),
    ("", r"^(contact_force\.csv@[^:]*:.*)_force$", r"\1_force_N"),
    ("", r"^(contact_force\.csv@[^:]*:.*)_penetration$", r"\1_penetration_m"),
    ("", r"^(drift_profile|acceleration_profile)\.csv:\d+:building$", None),
    ("", r"^(drift_profile\.csv:\d+:time_of_peak)$", r"\1_s"),
    ("", r"^(acceleration_profile\.csv:\d+:)peak_absolute_acceleration$", r"\1peak_absolute_acc_m_s2"),
    ("", r"^(acceleration_profile\.csv:\d+:)peak_displacement$", r"\1peak_floor_disp_m"),
    ("", r"^(impacts\.csv:\d+:level)$", r"\1_m"),
    ("", r"^(impacts\.csv:\d+:(start|max_penetration|end)_time)$", r"\1_s"),
    ("", r"^(impacts\.csv:\d+:(approach|separation)_velocity)$", r"\1_m_s"),
    ("", r"^(impacts\.csv:\d+:max_penetration)$", r"\1_m"),
    ("", r"^(impacts\.csv:\d+:peak_force)$", r"\1_N"),
    ("", r"^(impacts\.csv:\d+:impulse)$", r"\1_N_s"),
    ("", r"^(realizations\.csv:\d+:)peak_drift_ratio_(.+)_S(\d+)$", r"\1\2_storey\3_peak_drift_ratio"),
    ("", r"^(realizations\.csv:\d+:)peak_floor_acceleration_(.+)_F(\d+)$", r"\1\2_floor\3_peak_acc_m_s2"),
    ("", r"^(summary:statistics\.)peak_drift_ratio_(.+)_S(\d+)\.", r"\1\2_storey\3_peak_drift_ratio."),
    ("", r"^(summary:statistics\.)peak_floor_acceleration_(.+)_F(\d+)\.", r"\1\2_floor\3_peak_acc_m_s2."),
    # a hinge's force is a moment, its deformation a rotation
    (HINGE_FILES, r"^(summary:hinges\.\d+\.)yield_deformation$", r"\1yield_rotation_rad"),
    (HINGE_FILES, r"^(summary:hinges\.\d+\.)peak_deformation$", r"\1peak_rotation_rad"),
    (HINGE_FILES, r"^(summary:hinges\.\d+\.)peak_plastic_deformation$", r"\1peak_plastic_rotation_rad"),
    (HINGE_FILES, r"^(summary:hinges\.\d+\.)peak_force$", r"\1peak_moment_N_m"),
    (STOREY_FILES, r"^(summary:hinges\.\d+\.)yield_deformation$", r"\1yield_drift_m"),
    (STOREY_FILES, r"^(summary:hinges\.\d+\.)peak_deformation$", r"\1peak_drift_m"),
    (STOREY_FILES, r"^(summary:hinges\.\d+\.)peak_plastic_deformation$", r"\1peak_plastic_drift_m"),
    (STOREY_FILES, r"^(summary:hinges\.\d+\.)peak_force$", r"\1peak_force_N"),
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
    time_keyed = header and header[0] in ("time", "time_s")
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
            table(path, name, out, sample=first.startswith(("time,", "time_s,")))
    return out


def read(path):
    values = {}
    with open(path) as f:
        for line in f:
            key, _, text = line.rstrip("\n").rpartition(" ")
            values[key] = float(text)
    return values


def column_of(key):
    """The column a key belongs to: the key without its row; for a number
    of summary.json in a list, the list."""
    if key.startswith("summary:"):
        return re.sub(r"\.\d+$", "", key)
    return re.sub(r"(@t=[^:]*|:\d+):", ":", key, count=1)


def in_list(key):
    return key.startswith("summary:") and re.search(r"\.\d+$", key) is not None


def compare(reference_path, actual_path):
    reference = read(reference_path)
    name = os.path.basename(reference_path)
    for files, old, new in RENAMED:
        if not re.search(files, name):
            continue
        if new is None:
            reference = {k: v for k, v in reference.items() if not re.search(old, k)}
        else:
            reference = {re.sub(old, new, k): v for k, v in reference.items()}
    actual = read(actual_path)
    scale = {}
    for key, value in reference.items():
        if not key.startswith("summary:") or in_list(key):
            c = column_of(key)
            scale[c] = max(scale.get(c, 0.0), abs(value))
    problems = []
    for key, expected in reference.items():
        if key not in actual:
            problems.append(f"missing {key}")
            continue
        got = actual[key]
        if key.startswith("summary:") and not in_list(key):
            s = abs(expected)
        else:
            s = scale[column_of(key)]
        if ABSOLUTE.search(key):
            s, expected_scale = 1.0, 0.0
        else:
            expected_scale = abs(expected)
        if got == expected or (math.isnan(expected) and math.isnan(got)):
            continue
        if not abs(got - expected) <= TOLERANCE * max(s, expected_scale):
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
