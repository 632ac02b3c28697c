#!/usr/bin/env bash
# P(pounding) in `separation` with random parameters (issue 24): the two
# linear SDOFs of separation-sdof-pair.prm (4 s, 300 realizations) with a
# random storey stiffness of S2 (it enters the free responses) and a random
# separation (sampled per realization: pounding when the largest approach
# a_r exceeds s_r, as D_r > g of the curve):
#  - the summary's P(pounding at the random separation) equals the count of
#    a_r > s_r in realizations.csv (exact);
#  - a second estimator of the same probability, E[F_S(a)] = mean of the
#    lognormal CDF at each a_r (the separation drawn independently of the
#    response), agrees within 4 standard errors of their difference;
#  - the sampled separations have the lognormal's mean (4 standard errors);
#  - the random stiffness changes the approaches (against the nominal run);
#  - correlated random separations (below).
set -eu
poundfe=$1 input=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/helpers.sh"

sed -e 's/set Duration        = 15/set Duration        = 4/' \
    -e 's/set Realizations = 1/set Realizations = 300/' "$input" > "$work/nominal.prm"
cat "$work/nominal.prm" - > "$work/random.prm" << 'PRM'
subsection Random parameters
  set Variables = k2: Building 2/Storey stiffnesses ~ lognormal mean 61685.02750680849 cov 0.2; \
                  s: Model/Separations[1] ~ lognormal mean 0.06 cov 0.3
end
PRM
"$poundfe" separation "$work/nominal.prm" --output "$work/nominal" > /dev/null
"$poundfe" separation "$work/random.prm" --output "$work/random" > "$work/random.log"
grep -q "P(pounding at the random separation)" "$work/random.log" || fail "no P(pounding) line"
result=$(python3 - "$work" << 'PY'
import csv, json, math, sys
d = sys.argv[1]
rows = list(csv.DictReader(open(d + "/random/realizations.csv")))
nominal = list(csv.DictReader(open(d + "/nominal/realizations.csv")))
approach = [c for c in rows[0] if c.endswith("max_approach_m")][0]
separation = [c for c in rows[0] if c.endswith("_random_separation_m")][0]
a = [float(r[approach]) for r in rows]
s = [float(r[separation]) for r in rows]
n = len(rows)
summary = json.load(open(d + "/random/summary.json"))
p = [x for x in summary["pairs"] if "pounding_at_random_separation" in x][0]["pounding_at_random_separation"]
count = sum(ai > si for ai, si in zip(a, s))
assert p["pounding_realizations"] == count and p["realizations"] == n, (p, count, n)
# lognormal of mean 0.06, cov 0.3
zeta = math.sqrt(math.log(1 + 0.3 ** 2)); lam = math.log(0.06) - zeta ** 2 / 2
F = [0.5 * math.erfc(-(math.log(ai) - lam) / (zeta * math.sqrt(2))) if ai > 0 else 0 for ai in a]
second = sum(F) / n
sd = math.sqrt(sum(f * (1 - f) for f in F)) / n
assert abs(p["probability"] - second) <= 4 * sd, (p["probability"], second, sd)
mean = sum(s) / n
assert abs(mean / 0.06 - 1) < 4 * 0.3 / math.sqrt(n), mean
changed = sum(abs(float(r[approach]) - float(q[approach])) > 1e-9 for r, q in zip(rows, nominal))
assert changed > n / 2, changed
print("P(pounding) %.4f (%d of %d), E[F_S(a)] %.4f +- %.4f; mean separation %.4f m"
      % (p["probability"], count, n, second, sd, mean))
PY
) || fail "separation with random parameters"
echo "ok   separation: P(pounding at a random separation) with a random stiffness: $result"

# Correlated random separations (Nataf): a row of three SDOFs (S1, S2 and a
# copy of S1), lognormal separations s1 (mean 0.06, cov 0.3) and s2 (0.04,
# 0.5) with rho = 0.7, and a storey stiffness of S2 listed between them
# (correlated 0.3 with s1: the structure's variables come first in the
# joint transformation). ln s1 and ln s2 are jointly normal with the
# correlation rho0 = ln(1 + rho d1 d2)/(zeta1 zeta2) (Liu & Der Kiureghian
# 1986, eq. 19): the sample correlation of the logs against rho0 within 4
# standard errors (1 - rho0^2)/sqrt(n), and their means.
python3 - "$input" "$work/row.prm" << 'PY'
import sys
s = open(sys.argv[1]).read()
one = s[s.index("subsection Building 1"):s.index("subsection Building 2")]
s = s.replace("set Number of buildings = 2", "set Number of buildings = 3")
s = s.replace("set Separations         = 0.02", "set Separations         = 0.02, 0.02")
s = s.replace("set Duration        = 15", "set Duration        = 0.2")
s = s.replace("set Realizations = 1", "set Realizations = 2000")
s = s.replace("subsection Ground motion", one.replace("Building 1", "Building 3").replace("S1", "S3") + "subsection Ground motion")
s += """subsection Random parameters
  set Variables = s1: Model/Separations[1] ~ lognormal mean 0.06 cov 0.3; \\
                  k2: Building 2/Storey stiffnesses ~ lognormal mean 61685.02750680849 cov 0.2; \\
                  s2: Model/Separations[2] ~ lognormal mean 0.04 cov 0.5
  set Correlation = 1 0.3 0.7; 0.3 1 0; 0.7 0 1
end
"""
open(sys.argv[2], "w").write(s)
PY
"$poundfe" separation "$work/row.prm" --output "$work/row" > /dev/null || fail "correlated separations"
result=$(python3 - "$work/row/realizations.csv" << 'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
columns = [c for c in rows[0] if c.endswith("_random_separation_m")]
assert len(columns) == 2, columns
x = [[math.log(float(r[c])) for r in rows] for c in columns]
n = len(rows)
def zeta(d): return math.sqrt(math.log(1 + d * d))
rho0 = math.log(1 + 0.7 * 0.3 * 0.5) / (zeta(0.3) * zeta(0.5))
m = [sum(v) / n for v in x]
cov = sum((a - m[0]) * (b - m[1]) for a, b in zip(*x)) / n
r = cov / math.sqrt(sum((a - m[0]) ** 2 for a in x[0]) / n * sum((b - m[1]) ** 2 for b in x[1]) / n)
assert abs(r - rho0) < 4 * (1 - rho0 ** 2) / math.sqrt(n), (r, rho0)
for mean, cv, mi in ((0.06, 0.3, m[0]), (0.04, 0.5, m[1])):
    lam = math.log(mean) - zeta(cv) ** 2 / 2
    assert abs(mi - lam) < 4 * zeta(cv) / math.sqrt(n), (mi, lam)
print("sample correlation of ln s1, ln s2 %.4f against rho0 %.4f (n = %d)" % (r, rho0, n))
PY
) || fail "correlated separations"
echo "ok   correlated random separations: $result"
