"""same_columns.py A.csv B.csv SIGN TOLERANCE: every number of B is SIGN times
the number of A in the same row and column (the first column, time, as is),
to TOLERANCE relative to the column's largest finite magnitude; exit 1
otherwise. A NaN in either file fails (it compares as nothing: a column of
NaN would otherwise pass), an infinity must be the same in both."""
import csv
import math
import sys


def rows(path):
    with open(path) as f:
        return [r for r in csv.reader(f)]


a, b = rows(sys.argv[1]), rows(sys.argv[2])
sign, tolerance = float(sys.argv[3]), float(sys.argv[4])
if a[0] != b[0] or len(a) != len(b):
    sys.exit("different columns or lengths: %s %s" % (sys.argv[1], sys.argv[2]))
worst = 0.0
for j in range(1, len(a[0])):
    column_a = [float(r[j]) for r in a[1:]]
    column_b = [float(r[j]) for r in b[1:]]
    if any(math.isnan(v) for v in column_a + column_b):
        sys.exit("column %s: NaN" % a[0][j])
    if any((math.isinf(x) or math.isinf(y)) and y != sign * x for x, y in zip(column_a, column_b)):
        sys.exit("column %s: an infinity differs" % a[0][j])
    scale = max([abs(x) for x in column_a if math.isfinite(x)] + [0.0]) or 1.0
    worst = max([worst] + [abs(y - sign * x) / scale
                           for x, y in zip(column_a, column_b) if math.isfinite(x)])
print("largest relative difference %.3g" % worst)
sys.exit(0 if worst <= tolerance else 1)
