#!/usr/bin/env bash
# `poundfe site-hazard` on input/site-hazard.prm (issue 13 item 2) and the
# drift limits of `poundfe run` on the same file (item 4):
#   - hazard.csv: the thesis's three events at 79.4, 119.3 and 280 km (placed
#     by the destination-point formula, coordinates rounded to 1e-4 degree:
#     0.05 km), every row's distance against a haversine written here (1e-9
#     km), I and A_h against the formulas (1e-12);
#   - the Gumbel fit is a maximum of the censored likelihood: its gradient,
#     by central differences here, vanishes (1e-6 of the scale of terms);
#   - return periods: F(x_T) = 1 - 1/T, PGA = 10^(0.014 + 0.3 x)/100/g (1e-12);
#   - fragility x hazard against a second method: the direct sum of
#     P(F | a) |d lambda| over a fine grid in intensity (midpoint rule,
#     1e-6 relative: the midpoint rule on 200 000 cells, measured 2.4e-10);
#   - the fragility read from a summary.json that `poundfe fragility` wrote
#     gives the same probability as its theta and beta typed in;
#   - bad catalogue rows and parameters: exit 1, one message naming the file
#     and line, no output directory;
#   - run: each building's pass/fail per limit equals (every storey's peak
#     drift ratio <= the limit) of the same summary.json;
#   - montecarlo: the section's limits are added to the exceedance
#     probabilities, each the fraction of realizations above it.
set -eu
poundfe=$1 file=$2 small=$3
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$here/helpers.sh"

"$poundfe" site-hazard "$file" --output "$work/hazard" > "$work/hazard.log"
for f in hazard.csv hazard_curve.csv return_periods.csv summary.json hazard.png; do
  [ -s "$work/hazard/$f" ] || fail "no $f"
done
if ls -a "$work/hazard" | grep -q '\.tmp$'; then fail "temporary files left"; fi
python3 - "$work/hazard" "$file" <<'PY' || exit 1
import csv, json, math, sys
out, prm = sys.argv[1], sys.argv[2]
summary = json.load(open(f"{out}/summary.json"))
rows = list(csv.DictReader(open(f"{out}/hazard.csv")))
failures = []
def check(name, got, want, tolerance):
    if not abs(got - want) <= tolerance:
        failures.append(f"{name}: {got!r} instead of {want!r} (tolerance {tolerance})")
site = (summary["site"]["latitude_deg"], summary["site"]["longitude_deg"])
def haversine(a, b):
    p1, l1, p2, l2 = map(math.radians, (*a, *b))
    h = math.sin((p2 - p1) / 2)**2 + math.cos(p1) * math.cos(p2) * math.sin((l2 - l1) / 2)**2
    return 2 * 6371.0 * math.asin(math.sqrt(h))
for r in rows:
    d = haversine(site, (float(r["latitude_deg"]), float(r["longitude_deg"])))
    check(f"distance {r['date']}", float(r["distance_km"]), d, 1e-9)
    I = 8.0 + 1.5 * float(r["magnitude"]) - 2.5 * math.log(d)
    check(f"intensity {r['date']}", float(r["intensity"]), I, 1e-12)
    check(f"A_h {r['date']}", float(r["pga_cm_s2"]), 10**(0.014 + 0.3 * I), 1e-12 * 10**(0.3 * I))
thesis = {(4.4, 79.4), (5.7, 119.3), (5.1, 280.0)}
for M, r in thesis:
    near = [x for x in rows if float(x["magnitude"]) == M and abs(float(x["distance_km"]) - r) <= 0.05]
    if len(near) != 1:
        failures.append(f"the thesis event M {M} at {r} km is not in hazard.csv")
# the Gumbel fit maximises the likelihood with censored years
fit = summary["fit"]
assert fit["model"] == "gumbel"
minimum = summary["attenuation"]["minimum_intensity"]
maxima = {}
for r in rows:
    I = float(r["intensity"])
    if I >= minimum:
        maxima[r["year"]] = max(maxima.get(r["year"], -1e300), I)
years = summary["catalogue"]["years"]
n_censored = years - len(maxima)
check("censored years", fit["censored_years"], n_censored, 0)
def loglik(u, s):
    l = sum(-math.log(s) - (x - u) / s - math.exp(-(x - u) / s) for x in maxima.values())
    return l - n_censored * math.exp(-(minimum - u) / s)
u, s, h = fit["location"], fit["scale"], 1e-5
check("dl/du", (loglik(u + h, s) - loglik(u - h, s)) / (2 * h), 0, 1e-6 * len(maxima) / s)
check("dl/ds", (loglik(u, s + h) - loglik(u, s - h)) / (2 * h), 0, 1e-6 * len(maxima) / s)
F = lambda x: math.exp(-math.exp(-(x - u) / s))
for t in summary["return_periods"]:
    T, x = t["return_period_years"], t["intensity"]
    check(f"F(x_{T})", F(x), 1 - 1 / T, 1e-12)
    check(f"pga_g {T}", t["pga_g"], 10**(0.014 + 0.3 * x) / 100 / 9.80665, 1e-12 * t["pga_g"])
# fragility x hazard: sum of P(F | a(I)) |d lambda| over a fine grid in I
frag = summary["fragility"]
theta, beta = frag["theta_g"], frag["beta"]
rate = lambda x: math.exp(-(x - u) / s)
pga = lambda x: 10**(0.014 + 0.3 * x) / 100 / 9.80665
P = lambda x: 0.5 * math.erfc(-math.log(pga(x) / theta) / beta / math.sqrt(2))
top = (math.log10(theta * math.exp(10 * beta) * 980.665) - 0.014) / 0.3
n = 200000
dx = (top - minimum) / n
total = sum(P(minimum + (i + 0.5) * dx) * (rate(minimum + i * dx) - rate(minimum + (i + 1) * dx))
            for i in range(n)) + rate(top)
check("annual failure rate", frag["annual_failure_rate"], total, 1e-6 * total)
check("probability over exposure", frag["probability_over_exposure"],
      1 - math.exp(-frag["exposure_years"] * frag["annual_failure_rate"]), 1e-14)
for f in failures:
    print("FAIL", f)
print(f"site-hazard: {len(rows)} events, u = {u:.4g}, s = {s:.4g}, "
      f"475-year PGA {summary['return_periods'][-1]['pga_g']:.4g} g, "
      f"annual failure rate {frag['annual_failure_rate']:.4g} (second method {total:.4g})")
sys.exit(1 if failures else 0)
PY

# The fragility of a summary.json written by `poundfe fragility` (the small
# input of the probabilistic tests), then typed in: the same probability.
"$poundfe" fragility "$small" --output "$work/fragility" > /dev/null
read -r theta beta < <(python3 -c "
import json, sys
c = [c for c in json.load(open('$work/fragility/summary.json'))['curves'] if c['name'] == 'pounding'][0]
print(repr(c['theta_g']), repr(c['beta']))")
prm_dir=$(dirname "$file")
sed -e "s|^\( *set Catalogue file *=\).*|\1 $prm_dir/memvele-catalogue-illustrative.csv|" \
    -e "/set Median PGA/d" -e "/set Beta/d" \
    -e "s|^\( *subsection Fragility\)|\1\n    set File = $work/fragility/summary.json\n    set Curve = pounding|" \
    "$file" > "$work/from-file.prm"
"$poundfe" site-hazard "$work/from-file.prm" --output "$work/from-file" > /dev/null
sed -e "s|^\( *set Catalogue file *=\).*|\1 $prm_dir/memvele-catalogue-illustrative.csv|" \
    -e "s|^\( *set Median PGA *=\).*|\1 $theta|" -e "s|^\( *set Beta *=\).*|\1 $beta|" \
    "$file" > "$work/typed.prm"
"$poundfe" site-hazard "$work/typed.prm" --output "$work/typed" > /dev/null
python3 - "$work" <<'PY' || exit 1
import json, sys
a = json.load(open(f"{sys.argv[1]}/from-file/summary.json"))["fragility"]
b = json.load(open(f"{sys.argv[1]}/typed/summary.json"))["fragility"]
if a["theta_g"] != b["theta_g"] or a["annual_failure_rate"] != b["annual_failure_rate"]:
    print("FAIL the fragility from the file differs from it typed in:", a, b); sys.exit(1)
PY

# Bad input: exit 1, one message with the file and line, nothing written.
bad() { # name, catalogue contents, expected text of the message
  printf '%s' "$2" > "$work/$1.csv"
  sed -e "s|^\( *set Catalogue file *=\).*|\1 $1.csv|" "$file" > "$work/$1.prm"
  if "$poundfe" site-hazard "$work/$1.prm" --output "$work/out-$1" > /dev/null 2> "$work/err"; then
    fail "$1: accepted"
  fi
  [ "$(wc -l < "$work/err")" -eq 1 ] || { cat "$work/err"; fail "$1: not one line"; }
  grep -q -- "$3" "$work/err" || { cat "$work/err"; fail "$1: message"; }
  [ ! -e "$work/out-$1" ] || fail "$1: output written"
}
header='date,latitude,longitude,magnitude'
bad bad-date "$header
1960-02-30x,3,10,4
" "bad-date.csv:2"
bad bad-latitude "$header
1960,3,10,4
1961,-91,10,4
" "bad-latitude.csv:3"
bad negative-magnitude "$header
1960,3,10,4
1961,3,10.2,-1.5
" "negative-magnitude.csv:3"
bad no-magnitude "date,latitude,longitude
1960,3,10
" "no-magnitude.csv:1"
bad at-the-site "$header
1960,2.4,10.4,4
1961,3,10,4
" "at-the-site.csv:2"
bad outside-period "$header
1940,3,10,4
" "outside-period.csv:2"
bad one-year "$header
1960,3,10,4
1960,3.1,10,4.2
" "Site hazard/Fit"
sed -e "s|^\( *set Return periods *=\).*|\1 100, 1|" "$file" > "$work/period.prm"
if "$poundfe" site-hazard "$work/period.prm" --output "$work/out-period" 2> "$work/err" > /dev/null; then
  fail "return period 1: accepted"
fi
grep -q "Return periods" "$work/err" || { cat "$work/err"; fail "return period: message"; }

# run: the drift limits' pass/fail against the peaks of the same summary
# (the example's limits and a code's)
sed -e "s|^\( *set Limits *=.*\)|\1\n  set Code = asce-7\n  set Risk category = IV|" "$file" > "$work/run.prm"
"$poundfe" run "$work/run.prm" --output "$work/run" > /dev/null
[ -s "$work/run/drift_profile.png" ] || fail "no drift_profile.png"
python3 - "$work/run/summary.json" <<'PY' || exit 1
import json, sys
summary = json.load(open(sys.argv[1]))
n = 0
for b in summary["buildings"]:
    peaks = [s["peak_drift_ratio"] for s in b["storeys"]]
    names = [c["name"] for c in b["drift_limits"]]
    assert names == ["limit 0.02 %", "limit 0.05 %", "ASCE 7 Table 12.12-1, risk category IV"], names
    assert b["drift_limits"][2]["drift_ratio_limit"] == 0.010
    for c in b["drift_limits"]:
        limit = c["drift_ratio_limit"]
        exceeding = [i + 1 for i, p in enumerate(peaks) if not p <= limit]
        ok = (c["passes"] == (not exceeding) and c["storeys_exceeding"] == exceeding
              and c["peak_drift_ratio"] == max(peaks) and peaks[c["storey_of_peak"] - 1] == max(peaks))
        if not ok:
            print("FAIL", b["name"], c, peaks); sys.exit(1)
        n += 1
        print(f"  {b['name']}: peak {max(peaks):.4g} against {c['name']} ({limit:g}):",
              "passes" if c["passes"] else f"fails at storeys {exceeding}")
print(f"drift limits: {n} checks agree with the peaks")
assert any(not c["passes"] for b in summary["buildings"] for c in b["drift_limits"]), "no check fails"
assert any(c["passes"] for b in summary["buildings"] for c in b["drift_limits"]), "no check passes"
PY
# montecarlo: the Drift limits section's limits join the Monte Carlo
# section's; each probability = the fraction of realizations.csv's
# max_drift_ratio above the limit (exact)
{ cat "$small"; printf 'subsection Drift limits\n  set Limits = 0.3 %%\n  set Code = eurocode-8\nend\n'; } > "$work/mc.prm"
"$poundfe" montecarlo "$work/mc.prm" --output "$work/mc" > /dev/null
python3 - "$work/mc" <<'PY' || exit 1
import csv, json, sys
summary = json.load(open(f"{sys.argv[1]}/summary.json"))
rows = [r for r in csv.DictReader(open(f"{sys.argv[1]}/realizations.csv")) if r["completed"] == "1"]
drifts = [float(r["max_drift_ratio"]) for r in rows]
entries = summary["probabilities"]["drift_limit_exceedance"]
assert [e["drift_ratio_limit"] for e in entries] == [0.005, 0.01, 0.02, 0.003, 0.01], entries
assert [e.get("name") for e in entries][3:] == ["limit 0.3 %", "Eurocode 8 4.4.3.2, brittle non-structural elements, nu = 0.5"], entries
for e in entries:
    fraction = sum(d > e["drift_ratio_limit"] for d in drifts) / len(drifts)
    if e["probability"] != fraction:
        print("FAIL montecarlo", e, fraction); sys.exit(1)
print(f"montecarlo: {len(entries)} drift limits, P = {[e['probability'] for e in entries]}")
PY
echo "ok site-hazard"
