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
#  - a random separation correlated with another variable: exit 1.
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

# a random separation correlated with another variable: exit 1, one message
sed 's/^end$/end/' "$work/random.prm" | awk '{ print } /s: Model\/Separations\[1\]/ { print "  set Correlation = 1 0.5; 0.5 1" }' > "$work/correlated.prm"
set +e
"$poundfe" separation "$work/correlated.prm" --output "$work/correlated" > /dev/null 2> "$work/correlated.err"
status=$?
set -e
[ $status -eq 1 ] && [ "$(wc -l < "$work/correlated.err")" -eq 1 ] &&
  grep -q "Random parameters/Correlation" "$work/correlated.err" && [ ! -e "$work/correlated" ] ||
  fail "correlated random separation: exit $status, $(cat "$work/correlated.err")"
echo "ok   bad input: $(cat "$work/correlated.err")"
