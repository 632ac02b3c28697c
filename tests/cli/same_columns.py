"""same_columns.py A.csv B.csv SIGN TOLERANCE [PATTERN REPLACEMENT]: every
number of B is SIGN times the number of A in the same row and column (the
first column, time, as is), to TOLERANCE relative to the column's largest
finite magnitude (a column whose largest is below 1e-9 of the file's: the
file's); exit 1 otherwise. A NaN in either file fails (it compares
as nothing: a column of NaN would otherwise pass), an infinity must be the
same in both. With PATTERN and REPLACEMENT, each column of A is compared
with B's column named re.sub(PATTERN, REPLACEMENT, its name) (e.g. a 3D
run's columns along x with another's along y), which B must have."""
import csv
import math
import re
import sys


def rows(path):
    with open(path) as f:
        return [r for r in csv.reader(f)]


a, b = rows(sys.argv[1]), rows(sys.argv[2])
sign, tolerance = float(sys.argv[3]), float(sys.argv[4])
if len(sys.argv) > 6:
    renamed = [re.sub(sys.argv[5], sys.argv[6], name) for name in a[0]]
    missing = [name for name in renamed[1:] if name not in b[0]]
    if missing or len(a) != len(b):
        sys.exit("%s lacks %s (or has other rows)" % (sys.argv[2], ", ".join(missing[:5])))
    column_of = [b[0].index(name) if name in b[0] else 0 for name in renamed]
elif a[0] != b[0] or len(a) != len(b):
    sys.exit("different columns or lengths: %s %s" % (sys.argv[1], sys.argv[2]))
else:
    column_of = list(range(len(a[0])))
# a column without motion of its own (a 3D run's y or θz shaken along x:
# round-off) is measured against the file's largest magnitude
largest = max([abs(float(r[j])) for r in a[1:] for j in range(1, len(a[0]))
               if math.isfinite(float(r[j]))] + [0.0])
worst = 0.0
for j in range(1, len(a[0])):
    column_a = [float(r[j]) for r in a[1:]]
    column_b = [float(r[column_of[j]]) for r in b[1:]]
    if any(math.isnan(v) for v in column_a + column_b):
        sys.exit("column %s: NaN" % a[0][j])
    if any((math.isinf(x) or math.isinf(y)) and y != sign * x for x, y in zip(column_a, column_b)):
        sys.exit("column %s: an infinity differs" % a[0][j])
    scale = max([abs(x) for x in column_a if math.isfinite(x)] + [0.0])
    if scale < 1e-9 * largest:
        scale = largest
    scale = scale or 1.0
    worst = max([worst] + [abs(y - sign * x) / scale
                           for x, y in zip(column_a, column_b) if math.isfinite(x)])
print("largest relative difference %.3g" % worst)
sys.exit(0 if worst <= tolerance else 1)
