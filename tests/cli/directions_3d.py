"""The directions of a 3D run (tests/cli/directions_3d.sh; doc/verification.md,
"Every direction of a 3D run"). A symmetric, linear 3D building shaken along x
(X_DIR), along y (Y_DIR: the same motion turned by 90 degrees) and at 45
degrees (D45_DIR):
  * every column of floor_displacement.csv, floor_acceleration.csv, drift.csv
    (mass centres and slab corners), ground_motion.csv, base_shear.csv and
    storey_shear.csv of Y_DIR along y is X_DIR's along x, column for column,
    and along x X_DIR's along y (none); so are the peaks and residuals of
    drift_profile.csv, acceleration_profile.csv and residual_drift.csv, row
    for row (the time of a peak along the axis shaken);
  * base_shear.csv is storey_shear.csv's first storey (x, y and torque), and
    its largest |V_x|, |V_y|, |T| are the summary's plan peaks;
  * at 45 degrees the columns along x and along y are both X_DIR's along x
    over sqrt(2), and so are the summary's PGA of each axis and the storeys'
    peaks along x and y;
  * the torsional irregularity ratios along the axis without drift are null.
  directions_3d.py X_DIR Y_DIR D45_DIR TOLERANCE"""
import csv
import json
import math
import os
import re
import sys

x_dir, y_dir, d45_dir, tolerance = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
failures = []


def table(directory, name):
    with open(os.path.join(directory, name)) as f:
        rows = list(csv.reader(f))
    return {c: [float(r[j]) for r in rows[1:]] for j, c in enumerate(rows[0])}


def summary(directory):
    with open(os.path.join(directory, "summary.json")) as f:
        return json.load(f)


def swapped(name):
    """The column of the other horizontal axis (x <-> y)."""
    return re.sub(r"_([xy])(_|$)", lambda m: "_" + "yx"["xy".index(m.group(1))] + m.group(2), name)


def along_x(name):
    return re.search(r"_x(_|$)", name) is not None


def agree(what, got, want, scale):
    error = max(abs(g - w) for g, w in zip(got, want)) / scale
    if not error <= tolerance:
        failures.append(f"{what}: relative difference {error:.3g}")
    return error


worst = 0.0
for name in ("floor_displacement.csv", "floor_acceleration.csv", "drift.csv", "ground_motion.csv",
             "base_shear.csv", "storey_shear.csv"):
    x, y, d = table(x_dir, name), table(y_dir, name), table(d45_dir, name)
    columns = [c for c in x if c != "time_s"]
    if not any(along_x(c) for c in columns) or not all(swapped(c) in x for c in columns):
        failures.append(f"{name}: no columns along x and y ({', '.join(columns[:4])}, ...)")
        continue
    largest = max(max(abs(v) for v in x[c]) for c in columns)
    for c in columns:
        scale = max(abs(v) for v in x[c])
        if scale < 1e-6 * largest:  # a column without motion (round-off): against the file's
            scale = largest
        worst = max(worst, agree(f"{name} {swapped(c)} shaken along y against {c} along x",
                                 y[swapped(c)], x[c], scale))
        if along_x(c):
            for other in (c, swapped(c)):
                worst = max(worst, agree(f"{name} {other} at 45 degrees against {c} / sqrt(2)",
                                         d[other], [v / math.sqrt(2) for v in x[c]], scale))



def rows_of(directory, name):
    """A table of one row per storey or floor: its numeric columns."""
    with open(os.path.join(directory, name)) as f:
        rows = list(csv.DictReader(f))
    return {c: [float(r[c]) for r in rows] for c in rows[0] if c not in ("building", "storey", "floor")}


# per storey / floor: the peaks and residuals along the axis shaken, and the
# time of the peak along it; about z (twist, rotation) round-off in both runs
for name in ("drift_profile.csv", "acceleration_profile.csv", "residual_drift.csv"):
    x, y = rows_of(x_dir, name), rows_of(y_dir, name)
    columns = [c for c in x if along_x(c)]
    if not columns or not all(swapped(c) in x for c in columns):
        failures.append(f"{name}: no columns along x and y ({', '.join(list(x)[:4])}, ...)")
        continue
    for c in columns:
        scale = max(max(abs(v) for v in x[c]), 1e-300)
        worst = max(worst, agree(f"{name} {swapped(c)} shaken along y against {c} along x",
                                 y[swapped(c)], x[c], scale))
    if "peak_resultant_disp_m" in x:
        worst = max(worst, agree(f"{name} peak_resultant_disp_m shaken along y and along x",
                                 y["peak_resultant_disp_m"], x["peak_resultant_disp_m"],
                                 max(x["peak_resultant_disp_m"])))

sx, sy, sd = summary(x_dir), summary(y_dir), summary(d45_dir)
# the base shears are the first storey's, and their peaks the summary's
for directory, run in ((x_dir, sx), (y_dir, sy)):
    base, storeys = table(directory, "base_shear.csv"), table(directory, "storey_shear.csv")
    for building in run["buildings"]:
        n = building["name"]
        for base_column, storey_column, key in (("base_shear_x_N", "storey1_shear_x_N", "peak_base_shear_x_N"),
                                                ("base_shear_y_N", "storey1_shear_y_N", "peak_base_shear_y_N"),
                                                ("base_torque_N_m", "storey1_torque_N_m", "peak_base_torque_N_m")):
            if base[f"{n}_{base_column}"] != storeys[f"{n}_{storey_column}"]:
                failures.append(f"{directory}: {n}_{base_column} is not {n}_{storey_column}")
            peak = max(abs(v) for v in base[f"{n}_{base_column}"])
            if peak != building["plan"][key]:
                failures.append(f"{directory}: largest |{n}_{base_column}| {peak!r}, summary {key} "
                                f"{building['plan'][key]!r}")
# the summary's peak base shears of a 3D building: along x, along y and the
# resultant, each named by its direction (no direction-free peak_base_shear_N),
# the largest |V_x|, |V_y| and sqrt(V_x^2 + V_y^2) of base_shear.csv's rows
for directory, run in ((x_dir, sx), (y_dir, sy), (d45_dir, sd)):
    if not os.path.exists(os.path.join(directory, "base_shear.csv")):
        continue
    base = table(directory, "base_shear.csv")
    for building in run["buildings"]:
        n = building["name"]
        if "peak_base_shear_N" in building:
            failures.append(f"{directory}: {n} has peak_base_shear_N, a direction-free name in 3D")
        vx, vy = base[f"{n}_base_shear_x_N"], base[f"{n}_base_shear_y_N"]
        resultant = [math.hypot(a, b) for a, b in zip(vx, vy)]
        for key, values in (("x", [abs(v) for v in vx]), ("y", [abs(v) for v in vy]),
                            ("resultant", resultant)):
            got = building.get(f"peak_base_shear_{key}_N")
            if got is None or f"time_of_peak_base_shear_{key}_s" not in building:
                failures.append(f"{directory}: {n} lacks peak_base_shear_{key}_N or its time")
                continue
            worst = max(worst, agree(f"{directory}: {n} summary peak_base_shear_{key}_N",
                                     [got], [max(values)], max(max(resultant), 1e-300)))
pga = sx["ground_motion"]["pga_m_s2"]
for key, want in (("pga_x_m_s2", pga / math.sqrt(2)), ("pga_y_m_s2", pga / math.sqrt(2))):
    worst = max(worst, agree(f"summary {key} at 45 degrees", [sd["ground_motion"][key]], [want], pga))
worst = max(worst, agree("summary pga_x_m_s2 along x", [sx["ground_motion"]["pga_x_m_s2"]], [pga], pga))
for b, building in enumerate(sx["buildings"]):
    for i, storey in enumerate(building["storeys"]):
        peak = storey["peak_drift_ratio"]
        worst = max(worst, agree(f"storey {i + 1}: peak_drift_ratio_y shaken along y",
                                 [sy["buildings"][b]["storeys"][i]["peak_drift_ratio_y"]], [peak], peak))
        for key in ("peak_drift_ratio", "peak_drift_ratio_y"):
            worst = max(worst, agree(f"storey {i + 1}: {key} at 45 degrees",
                                     [sd["buildings"][b]["storeys"][i][key]],
                                     [peak / math.sqrt(2)], peak))
    for run, still, moving in ((sx, "y", "x"), (sy, "x", "y")):
        plan = run["buildings"][b]["plan"]
        for key in ("torsional_irregularity_", "torsional_irregularity_at_peak_"):
            if any(r is not None for r in plan[key + still]):
                failures.append(f"{key}{still} without drift along {still}: {plan[key + still]}")
            if any(r is None for r in plan[key + moving]):
                failures.append(f"{key}{moving} is null along the axis shaken")
print(f"largest relative difference {worst:.3g}")
for f in failures[:10]:
    print("FAIL " + f)
sys.exit(1 if failures else 0)
