#!/usr/bin/env python3
"""The fibre pair (bench/fibre-pair.prm, pair.tcl) in poundfe and OpenSees 3.8.

    compare_pair.py scripts OPENSEES_DIR POUNDFE_OPENSEES_DIR
    compare_pair.py run POUNDFE_RUN_DIR OPENSEES_DIR

scripts: the recorder files of pair.tcl from OpenSees and from `poundfe
opensees` (the same script), every column of every file: the largest
difference over the history relative to the peak of its column, file by
file; exit 1 when one exceeds 1e-6.

run: `poundfe run bench/fibre-pair.prm` against pair.tcl in OpenSees: per
storey the peak drift ratio, per floor the peak absolute acceleration, per
gap the peak force, and their largest differences relative to the largest
peak of their kind (the programs then differ by the contact law's
stepping and the element tolerances, not by the model)."""
import csv
import os
import sys

import numpy as np

FILES = ["floor_disp.out", "floor_accel.out", "gap_force.out", "gap_strain.out",
         "member_force.out", "member_deformation.out"]
N_STOREYS, N_JOINTS, H = 10, 4, 3.2
BUILDINGS = ["A", "B"]


def load(path):
    return np.loadtxt(path, ndmin=2)


def compare_scripts(opensees, poundfe):
    worst = 0.0
    for name in FILES:
        a, b = load(os.path.join(opensees, name)), load(os.path.join(poundfe, name))
        if a.shape != b.shape:
            print(f"{name}: {a.shape} rows x columns in OpenSees, {b.shape} in poundfe")
            return 1
        peak = np.maximum(np.abs(a).max(axis=0), 1e-300)
        relative = (np.abs(a - b).max(axis=0) / peak)[1:]
        column = int(np.argmax(relative))
        print(f"{name:24s} {a.shape[0]:5d} rows {a.shape[1]:4d} columns: largest difference "
              f"{relative[column]:.2e} of its column's peak (column {column + 2})")
        worst = max(worst, relative[column])
    print(f"largest: {worst:.2e} (limit 1e-6)")
    return 0 if worst <= 1e-6 else 1


def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], np.array(rows[1:], dtype=float)


def opensees_floors(opensees):
    """Mean ux of each floor's joints, A then B, floors bottom up, and the
    floors' relative accelerations the same way."""
    shape = (-1, len(BUILDINGS) * N_STOREYS, N_JOINTS)
    disp = load(os.path.join(opensees, "floor_disp.out"))
    accel = load(os.path.join(opensees, "floor_accel.out"))
    return (disp[:, 0], disp[:, 1:].reshape(shape).mean(axis=2),
            accel[:, 1:].reshape(shape).mean(axis=2))


def drifts(floors):
    ratios = []
    for b in range(len(BUILDINGS)):
        x = np.hstack([np.zeros((floors.shape[0], 1)),
                       floors[:, b * N_STOREYS:(b + 1) * N_STOREYS]])
        ratios.append(np.diff(x, axis=1) / H)
    return np.hstack(ratios)


def report(kind, labels, ours, theirs):
    reference = max(np.abs(theirs).max(), 1e-300)
    difference = np.abs(ours - theirs)
    for label, p, o in zip(labels, ours, theirs):
        print(f"  {label:10s} poundfe {p:12.5e}  OpenSees {o:12.5e}")
    worst = int(np.argmax(difference))
    print(f"{kind}: largest difference {difference[worst] / reference:.2e} of the largest peak "
          f"({labels[worst]})")


def compare_run(run, opensees):
    time, floors, relative_accel = opensees_floors(opensees)
    _, drift = read_csv(os.path.join(run, "drift.csv"))
    _, acceleration = read_csv(os.path.join(run, "floor_acceleration.csv"))
    _, ground = read_csv(os.path.join(run, "ground_motion.csv"))
    header, contact = read_csv(os.path.join(run, "contact_force.csv"))
    if drift.shape[0] != time.size + 1:
        print(f"poundfe has {drift.shape[0]} rows, OpenSees {time.size} steps: "
              "run with Output interval = the time step")
        return 1
    labels = [f"{b}{s + 1}" for b in BUILDINGS for s in range(N_STOREYS)]
    report("peak drift ratio", labels, np.abs(drift[1:, 1:]).max(axis=0),
           np.abs(drifts(floors)).max(axis=0))
    absolute = relative_accel + ground[1:, 1:2]
    report("peak floor acceleration", labels, np.abs(acceleration[1:, 1:]).max(axis=0),
           np.abs(absolute).max(axis=0))
    forces = contact[1:, [i for i, h in enumerate(header) if h.endswith("_force_N")]]
    gap_force = load(os.path.join(opensees, "gap_force.out"))[:, 1:]
    gaps = [f"gap {k + 1}" for k in range(N_STOREYS)]
    # a zeroLength's force in the plane: (Fx, Fy, M) on each node; Fx on A's
    # joint is the contact force
    report("peak gap force", gaps, np.abs(forces).max(axis=0),
           np.abs(gap_force[:, 0::6]).max(axis=0))
    return 0


def main(argv):
    if len(argv) != 4 or argv[1] not in ("scripts", "run"):
        print(__doc__)
        return 1
    if argv[1] == "scripts":
        return compare_scripts(argv[2], argv[3])
    return compare_run(argv[2], argv[3])


if __name__ == "__main__":
    sys.exit(main(sys.argv))
