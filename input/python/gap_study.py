#!/usr/bin/env python3
"""Gap study with poundfe's Python module: the default example (two RC
frames, 3 and 2 storeys, under a Kanai-Tajimi motion) run for a list of
separations; the peak drift ratio and floor acceleration of each building
and the peak contact force against the gap, plotted to a PNG and tabulated
to a CSV file.

    python3 input/python/gap_study.py                 # from the repository's root
    python3 input/python/gap_study.py --gaps 0.005 0.01 0.02 --output results/gaps

Needs the module built (scripts/setup.sh); it is found in build/python
without PYTHONPATH.
"""

import argparse
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
try:
    import poundfe
except ImportError:
    sys.path.insert(0, os.path.join(ROOT, "build", "python"))
    import poundfe

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt
import numpy as np


def study(input_file, gaps):
    """Peaks per gap: {building: (drift ratio, floor acceleration)}, contact force, impacts."""
    rows = []
    for gap in gaps:
        results = poundfe.run(poundfe.read(input_file, overrides={"Model/Separations": gap}))
        peaks = {name: (p["drift_ratio"].max(), p["floor_acceleration"].max())
                 for name, p in results.peaks.items()}
        force = max([g["peak_force_N"] for g in results.gaps.values()], default=0.0)
        impacts = 0 if results.impacts is None else len(results.impacts)
        rows.append((gap, peaks, force, impacts))
        print(f"gap {gap * 1000:6.1f} mm: " +
              ", ".join(f"{n} drift {d:.5f} acc {a:.3f} m/s^2" for n, (d, a) in peaks.items()) +
              f", contact force {force / 1000:.1f} kN, {impacts} impacts", flush=True)
    return rows


def plot(rows, title, path):
    gaps_mm = np.array([r[0] for r in rows]) * 1000
    buildings = list(rows[0][1])
    figure, axes = plt.subplots(1, 3, figsize=(13, 4), constrained_layout=True)
    for name in buildings:
        axes[0].plot(gaps_mm, [100 * r[1][name][0] for r in rows], "o-", label=name)
        axes[1].plot(gaps_mm, [r[1][name][1] for r in rows], "o-", label=name)
    axes[2].plot(gaps_mm, [r[2] / 1000 for r in rows], "o-", color="black")
    for gap, row in zip(gaps_mm, rows):
        axes[2].annotate(str(row[3]), (gap, row[2] / 1000), textcoords="offset points",
                         xytext=(4, 4), fontsize=8)
    labels = ("peak inter-storey drift ratio (%)", "peak absolute floor acceleration (m/s$^2$)",
              "peak contact force (kN), number of impacts")
    for axis, label in zip(axes, labels):
        axis.set_xlabel("separation (mm)")
        axis.set_ylabel(label)
        axis.grid(True, alpha=0.3)
    axes[0].legend()
    axes[1].legend()
    figure.suptitle(title)
    figure.savefig(path, dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--input", default=os.path.join(ROOT, "input", "two-buildings.prm"))
    parser.add_argument("--gaps", type=float, nargs="+",
                        default=[0.001, 0.0025, 0.005, 0.0075, 0.01, 0.0125, 0.015, 0.02, 0.03],
                        help="separations, m")
    parser.add_argument("--output", default=os.path.join("results", "gap-study"),
                        help="directory for gap_study.png and gap_study.csv")
    args = parser.parse_args()
    rows = study(args.input, args.gaps)
    os.makedirs(args.output, exist_ok=True)
    with open(os.path.join(args.output, "gap_study.csv"), "w") as f:
        names = list(rows[0][1])
        f.write("gap_m," + ",".join(f"{n}_peak_drift_ratio,{n}_peak_floor_acc_m_s2" for n in names)
                + ",peak_contact_force_N,impacts\n")
        for gap, peaks, force, impacts in rows:
            f.write(",".join(repr(v) for v in [gap, *np.ravel([peaks[n] for n in names]).tolist(),
                                               force]) + f",{impacts}\n")
    png = os.path.join(args.output, "gap_study.png")
    plot(rows, f"gap study: {os.path.basename(args.input)}", png)
    print(f"written {png} and gap_study.csv")


if __name__ == "__main__":
    main()
