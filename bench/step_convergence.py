#!/usr/bin/env python3
"""Step-convergence study of pounding (doc/verification.md, "Contact resolved
in time"): each case at dt = 1e-2 ... 2e-4 s with Contact/Steps per contact
N = 0 and 20, against the same run at dt = 1e-4 s. Prints a Markdown table
per case: the worst relative difference over every peak (drift ratio and
absolute acceleration of every floor, peak force and impulse of every gap),
the steps taken, step cuts and the most Newton iterations in a step.
Usage (from the repository root, after building): bench/step_convergence.py
"""
import json, os, re, subprocess, sys, tempfile

POUNDFE = os.path.abspath("build/poundfe")
CASES = [
    ("shear pair, linear gaps", "input/shear-pair-pounding.prm", {}),
    ("shear pair, Jankowski gaps", "input/shear-pair-pounding.prm",
     {"Law": "jankowski", "Stiffness": "2.75e9"}),
    # the default pair under a motion that is the same at every step, 4 mm apart so it pounds
    ("default example (two-buildings.prm, Hertz-damp)", "input/two-buildings.prm",
     {"Method": "spectral-representation", "Cutoff frequency": "100", "Separations": "0.004"}),
]


def run(work, source, dt, n, changes):
    text = open(source).read()
    text = re.sub(r"set Time step\s*=.*", f"set Time step = {dt}", text)
    if re.search(r"set Steps per contact\s*=", text):
        text = re.sub(r"set Steps per contact\s*=.*", f"set Steps per contact = {n}", text)
    else:
        text = text.replace("subsection Contact\n", f"subsection Contact\n  set Steps per contact = {n}\n", 1)
    for key, value in changes.items():
        if re.search(rf"set {key}\s*=", text):
            text = re.sub(rf"set {key}\s*=.*", f"set {key} = {value}", text)
        else:
            text = text.replace("subsection Stochastic\n", f"subsection Stochastic\n    set {key} = {value}\n", 1)
    name = os.path.join(work, f"run-{dt}-{n}")
    open(name + ".prm", "w").write(text)
    subprocess.run([POUNDFE, "run", name + ".prm", "--output", name], check=True, capture_output=True)
    summary = json.load(open(name + "/summary.json"))
    peaks, impacts = {}, 0
    for b in summary["buildings"]:
        for s in b["storeys"]:
            peaks[f"{b['name']} drift {s['storey']}"] = s["peak_drift_ratio"]
            peaks[f"{b['name']} acceleration {s['storey']}"] = s["peak_absolute_floor_acceleration_m_s2"]
    for g in summary["gaps"]:
        impacts += g["impacts"]
        if g["impacts"]:
            peaks[g["label"] + " force"] = g["peak_force_N"]
            peaks[g["label"] + " impulse"] = g["total_impulse_N_s"]
    return peaks, impacts, summary["newton"]


def main():
    for title, source, changes in CASES:
        with tempfile.TemporaryDirectory() as work:
            reference, n_reference, newton = run(work, source, 1e-4, 20, changes)
            print(f"\n{title}: reference dt = 1e-4 s, {n_reference} impacts, "
                  f"max {newton['max_iterations_per_step']} iterations, {newton['step_cuts']} cuts")
            print("| Δt (s) | worst peak, N = 0 | worst peak, N = 20 | steps incl. sub-steps (N = 20) "
                  "| step cuts | max Newton iterations |")
            print("|---|---|---|---|---|---|")
            for dt in (1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4):
                cells, stats = [], []
                for n in (0, 20):
                    peaks, impacts, newton = run(work, source, dt, n, changes)
                    errors = {k: (peaks.get(k, 0) - v) / v for k, v in reference.items() if v}
                    worst = max(errors, key=lambda k: abs(errors[k]))
                    cells.append(f"{100 * errors[worst]:+.2f} % ({worst}; {impacts} impacts)")
                    stats.append(newton)
                print(f"| {dt:g} | {cells[0]} | {cells[1]} | {stats[1]['steps_including_substeps']} "
                      f"| {stats[0]['step_cuts']} → {stats[1]['step_cuts']} "
                      f"| {stats[0]['max_iterations_per_step']} → {stats[1]['max_iterations_per_step']} |")
            sys.stdout.flush()


if __name__ == "__main__":
    main()
