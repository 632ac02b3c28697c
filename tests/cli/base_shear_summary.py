#!/usr/bin/env python3
"""summary.json gives every building's peak base shear and largest residual
drift ratio whatever the recorders (issue 27 item 5).

  base_shear_summary.py POUNDFE INPUT_DIR

Reference: the base_shear.csv recorder (its storey shears are checked against
horizontal equilibrium in unit/output) written at every step of the same run,
and residual_drift.csv. The summary's peak is taken at every step and sub-step
of a contact, the recorder at the steps, so: equal to round-off (1e-12) when
the run has no sub-steps (an elastic frame without contact, a shear building
with Bouc-Wen storeys), and never below the recorder's (1e-12) with them (the
default example). The residual drift: the largest |residual_drift_ratio| of the
building's rows, exactly. A run without any recorder gives the same summary
values (the summary does not depend on what is recorded).
"""
import csv
import json
import os
import subprocess
import sys
import tempfile

poundfe, inputs = sys.argv[1], sys.argv[2]
failures = 0


def with_output(text, lines):
    """`text` with its Output section's own entries and Recorders replaced by
    `lines` (a parameter may be set only once)."""
    out, depth, in_output, skip = [], 0, False, 0
    for line in text.splitlines():
        word = line.split()
        if word[:2] == ["subsection", "Output"] and depth == 0:
            in_output = True
            out.append(line)
            out.extend("  " + l for l in lines)
            depth += 1
            continue
        if word[:1] == ["subsection"]:
            depth += 1
            if in_output and word[1:] == ["Recorders"]:
                skip = depth
            if skip:
                continue
        elif word[:1] == ["end"]:
            depth -= 1
            if skip:
                if depth < skip:
                    skip = 0
                continue
            if depth == 0:
                in_output = False
        elif skip or (in_output and depth == 1 and word[:1] == ["set"] and
                      any(line.split("=")[0].split(None, 1)[1].strip() == key
                          for key in ("Output interval", "VTU interval", "Plots"))):
            continue
        out.append(line)
    if not any(l.split()[:2] == ["subsection", "Output"] for l in text.splitlines()):
        out += ["subsection Output"] + ["  " + l for l in lines] + ["end"]
    return "\n".join(out) + "\n"


def run(prm, directory, lines):
    text = with_output(open(os.path.join(inputs, prm)).read(), lines)
    path = os.path.join(directory, "input.prm")
    with open(path, "w") as f:
        f.write(text)
    out = os.path.join(directory, "out")
    subprocess.run([poundfe, "run", path, "--output", out], check=True,
                   stdout=subprocess.DEVNULL, cwd=inputs)
    return out


def fail(message):
    global failures
    failures += 1
    print("FAIL", message)


for prm, step, substeps in [("three-storey-frame.prm", None, False),
                            ("bouc-wen-sdof.prm", None, False),
                            ("two-buildings.prm", None, True)]:
    with tempfile.TemporaryDirectory() as work:
        recorded = os.path.join(work, "recorded")
        plain = os.path.join(work, "plain")
        os.makedirs(recorded)
        os.makedirs(plain)
        quiet = ["set VTU interval = 0", "set Plots = false"]
        a = run(prm, recorded, quiet + ["set Output interval = 0", "subsection Recorders",
                                        "  set Record = base shear; residual drift", "end"])
        b = run(prm, plain, quiet)
        sa = json.load(open(os.path.join(a, "summary.json")))
        sb = json.load(open(os.path.join(b, "summary.json")))
        rows = list(csv.DictReader(open(os.path.join(a, "base_shear.csv"))))
        residual = list(csv.DictReader(open(os.path.join(a, "residual_drift.csv"))))
        for i, building in enumerate(sa["buildings"]):
            name = building["name"]
            peak = building["peak_base_shear_N"]
            column = max(abs(float(r[name + "_base_shear_N"])) for r in rows)
            if substeps:
                ok = peak >= column * (1 - 1e-12)
            else:
                ok = abs(peak - column) <= 1e-12 * column
            if not ok:
                fail(f"{prm} {name}: summary peak base shear {peak!r}, base_shear.csv {column!r}")
            largest = max(abs(float(r["residual_drift_ratio"])) for r in residual
                          if r["building"] == name)
            if building["max_residual_drift_ratio"] != largest:
                fail(f"{prm} {name}: max residual drift {building['max_residual_drift_ratio']!r}, "
                     f"residual_drift.csv {largest!r}")
            for key in ("peak_base_shear_N", "time_of_peak_base_shear_s", "max_residual_drift_ratio"):
                if sb["buildings"][i][key] != building[key]:
                    fail(f"{prm} {name}: {key} depends on the recorders")
            print(f"{prm} {name}: peak base shear {peak:.6g} N (recorder {column:.6g} N), "
                  f"residual drift ratio {largest:.3g}")
print("ok" if not failures else f"{failures} failures")
sys.exit(1 if failures else 0)
