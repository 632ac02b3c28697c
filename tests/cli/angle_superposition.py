"""The peaks of a linear 3D model against the incidence angle, by superposition
(doc/verification.md, "Critical incidence angle"): the load is linear in
(a_x, a_y) = R(a) (g_1, g_2) = cos a (g_1, g_2) + sin a R(90 deg) (g_1, g_2), so
any response is u(t; a) = cos a u(t; 0) + sin a u(t; 90 deg), and its peak is
max_t |cos a u(t; 0) + sin a u(t; 90)| from the two time histories alone.
  angle_superposition.py SWEEP_DIR RUN0_CSV RUN90_CSV RUN_COLUMN SWEEP_COLUMN TOL
Compares every row of SWEEP_DIR/sweep.csv, and the critical angle (the
largest peak) of the superposition with that of SWEEP_DIR/summary.json."""
import csv
import json
import math
import sys


def column(path, name):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return [float(r[name]) for r in rows], rows


sweep_dir, run0, run90, run_column, sweep_column, tol = sys.argv[1:7]
sweep_csv = sweep_dir + "/sweep.csv"
u0, _ = column(run0, run_column)
u90, _ = column(run90, run_column)
assert len(u0) == len(u90) and len(u0) > 10
with open(sweep_csv) as f:
    rows = list(csv.DictReader(f))
angle_name = list(rows[0].keys())[0]
worst, reference, swept = 0.0, [], []
for r in rows:
    a = math.radians(float(r[angle_name]))
    peak = max(abs(math.cos(a) * x + math.sin(a) * y) for x, y in zip(u0, u90))
    reference.append((peak, float(r[angle_name])))
    swept.append((float(r[sweep_column]), float(r[angle_name])))
    worst = max(worst, abs(float(r[sweep_column]) - peak) / peak)
critical_reference = max(reference)[1]
with open(sweep_dir + "/summary.json") as f:
    critical_swept = json.load(f)["critical"][sweep_column]["value"]
print(f"largest relative difference {worst:.3g} over {len(rows)} angles; critical angle "
      f"{critical_swept} (superposition {critical_reference})")
if worst > float(tol) or critical_reference != critical_swept:
    sys.exit(1)
