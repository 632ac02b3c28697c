#!/usr/bin/env bash
# What a loss model and a FEMA P-695 evaluation read (output/demand_table.h,
# assessment/collapse_margin.h), through the binary:
#  - ida with IDA/Demand intensities writes demands_<building>_im<k>.csv in
#    pelicun 3's DEMAND sample schema (below); each record's PID there equals
#    its IDA curve (ida.csv) interpolated linearly at the intensity, computed
#    here again (1e-12 relative: the same few operations), and its SA_<T>
#    column (Sa at the IDA's period, pelicun's name) is the intensity;
#  - ida with IDA/Collapse margin: summary.json's S_CT is the median of the
#    records' collapse intensities (those that did not collapse counted
#    above), CMR = S_CT / S_MT and ACMR = SSF CMR to round-off; SSF within
#    0.005 of FEMA P-695's closed form at the period (the tables' rounding);
#    beta_TOT 0.525 and the acceptable ACMRs 1.96 / 1.56 of Tables 7-2, 7-3
#    for mu_T = 4 and good ratings (0.005: the tables' two decimals);
#  - run with Output/Demand tables = true: demands_<building>.csv with PID,
#    PFA, PFD equal to drift_profile.csv and acceleration_profile.csv (PFA
#    in g: 1e-15 relative); no table without it;
#  - montecarlo with Output/Demand tables = true: demands_<building>.csv
#    with a row per completed realization, its values those of
#    realizations.csv (PFA in g: 1e-15 relative), the per-gap impacts and
#    peak forces consistent with the totals (n_impacts, peak_contact_force);
#    no table and no extra column without it;
#  - bad input: demand intensities above the upper one, a margin on PGA:
#    exit 1, one line naming the entry, nothing written.
poundfe=$(realpath "$1") example=$(realpath "$2")
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
# shellcheck source=/dev/null
. "$here/expect.sh"
die() { echo "FAIL $*"; exit 1; }

short=(--set "Ground motion/Stochastic/Duration=4" --set "IDA/Runs per record=6"
       --set "IDA/Tolerance=0.2" --set "Output/Plots=false")
"$poundfe" ground-motion "$example" --realizations 3 --write-at2 --output gen "${short[@]}" > /dev/null ||
  die "ground-motion --write-at2"
cp "$example" ida.prm
loss=(--set "IDA/Suite=$work/gen/records/suite.csv" --set "IDA/Demand intensities=0.1, 0.3"
      --set "IDA/Collapse margin/MCE spectral acceleration=0.5"
      --set "IDA/Collapse margin/Period-based ductility=4")
"$poundfe" ida ida.prm --output ida "${short[@]}" "${loss[@]}" > ida.log || die "ida: $(cat ida.log)"
grep -q "FEMA P-695: S_CT" ida.log || die "no collapse margin in the report: $(cat ida.log)"
HERE=$here python3 - ida <<'PY' || die "ida's demand tables or collapse margin"
import csv, json, math, os, re, sys
d = sys.argv[1]
summary = json.load(open(os.path.join(d, "summary.json")))

sys.path.insert(0, os.environ["HERE"])
from pelicun_schema import check_schema  # pelicun 3's DEMAND sample

runs = list(csv.DictReader(open(os.path.join(d, "ida.csv"))))
for k, table in enumerate(summary["demand_tables"], 1):
    x = table["intensity"]
    assert table["files"] == [f"demands_shear3_im{k}.csv", f"demands_shear2_im{k}.csv"], table
    head, data = check_schema(os.path.join(d, table["files"][0]))
    sa = "1-SA_%.2f-0-1" % summary["periods_s"][0]  # pelicun's name of Sa(T)
    assert head[:6] == ["1-PFA-0-1", sa, "1-PFA-1-1", "1-PFA-2-1", "1-PFA-3-1", "1-PID-1-1"], head
    assert all(float(row[2]) == x for row in data), "SA column"
    assert len(data) == len(table["records"]) == 3 - table["collapsed"] - table["not_reached"]
    for row, name in zip(data, table["records"]):
        # along the record's curve: (0, 0) and its runs that did not collapse
        curve = [(0.0, 0.0)] + sorted((float(r["intensity"]), float(r["shear3_storey1_peak_drift_ratio"]))
                                      for r in runs if r["name"] == name and r["collapsed"] == "0")
        (x0, d0), (x1, d1) = next((a, b) for a, b in zip(curve, curve[1:]) if b[0] >= x)
        expected = d0 + (x - x0) / (x1 - x0) * (d1 - d0)
        got = float(row[head.index("1-PID-1-1") + 1])
        assert abs(got - expected) <= 1e-12 * abs(expected), (name, got, expected)
    print(f"demands at {x}: {len(data)} records, PID-1-1 on their IDA curves")

m = summary["collapse_margin"]
collapse = [r.get("collapse_intensity", math.inf) for r in summary["records"]]
collapse.sort()
n = len(collapse)
h = (n - 1) * 0.5
median = collapse[int(h)] if h == int(h) else collapse[int(h)] + (h - int(h)) * (collapse[int(h) + 1] - collapse[int(h)])
if math.isinf(median):
    assert m["s_ct_lower_bound"] and m["s_ct_g"] == summary["upper_intensity"], m
else:
    assert not m["s_ct_lower_bound"] and abs(m["s_ct_g"] - median) <= 1e-12 * median, (m, median)
assert abs(m["cmr"] - m["s_ct_g"] / 0.5) <= 1e-12 * m["cmr"], m
assert abs(m["acmr"] - m["ssf"] * m["cmr"]) <= 1e-12 * m["acmr"], m
T = min(max(m["period_s"], 0.5), 1.5)
closed = math.exp(0.14 * 3 ** 0.42 * (1.5 - 0.6 * (1.5 - T)))
assert abs(m["ssf"] - closed) <= 0.005 + 1e-12, (m["ssf"], closed)
assert m["beta_rtr"] == 0.4 and m["beta_total"] == 0.525, m
assert abs(m["acceptable_acmr_10"] - 1.96) < 0.005 and abs(m["acceptable_acmr_20"] - 1.56) < 0.005, m
assert m["passes_acmr_20"] == (m["acmr"] >= m["acceptable_acmr_20"]), m
print(f"S_CT {m['s_ct_g']} g, CMR {m['cmr']}, SSF {m['ssf']}, ACMR {m['acmr']}")
PY

# run: the tables against the profiles, and none unless asked
"$poundfe" run ida.prm --output run --set "Output/Plots=false" --set "Output/VTU interval=0" \
  --set "Ground motion/Stochastic/Duration=4" --set "Output/Demand tables=true" > /dev/null || die "run"
python3 - run <<'PY' || die "run's demand tables"
import csv, json, os, sys
d = sys.argv[1]
files = json.load(open(os.path.join(d, "summary.json")))["output"]["files"]
assert "demands_shear3.csv" in files and "demands_shear2.csv" in files, files
drift = {(r["building"], r["storey"]): float(r["peak_drift_ratio"]) for r in csv.DictReader(open(os.path.join(d, "drift_profile.csv")))}
accel = {(r["building"], r["floor"]): r for r in csv.DictReader(open(os.path.join(d, "acceleration_profile.csv")))}
for b, n in (("shear3", 3), ("shear2", 2)):
    rows = list(csv.reader(open(os.path.join(d, f"demands_{b}.csv"))))
    value = dict(zip(rows[0][1:], map(float, rows[2][1:])))
    unit = dict(zip(rows[0][1:], rows[1][1:]))
    for f in range(1, n + 1):
        assert value[f"1-PID-{f}-1"] == drift[(b, str(f))]
        a = float(accel[(b, str(f))]["peak_absolute_acc_m_s2"])
        assert abs(value[f"1-PFA-{f}-1"] - a / 9.80665) <= 1e-15 * a
        assert value[f"1-PFD-{f}-1"] == float(accel[(b, str(f))]["peak_floor_disp_m"])
    assert unit["1-PFA-1-1"] == "g" and unit["1-PID-1-1"] == "rad" and unit[f"1-PRD-{n}-1"] == "rad"
print("run's demand tables: the profiles")
PY
"$poundfe" run ida.prm --output plain --set "Output/Plots=false" --set "Output/VTU interval=0" \
  --set "Ground motion/Stochastic/Duration=2" > /dev/null || die "run without tables"
[ ! -e plain/demands_shear3.csv ] || die "a run wrote demand tables unasked"

# montecarlo: a table per building, a row per completed realization, each
# value the realization's own (realizations.csv); the new per-gap columns
# against the totals montecarlo always wrote (impacts summed over the gaps =
# n_impacts, the largest gap force = peak_contact_force)
"$poundfe" montecarlo ida.prm --output mc --set "Output/Plots=false" --set "Monte Carlo/Realizations=4" \
  --set "Ground motion/Stochastic/Duration=4" --set "Output/Demand tables=true" > mc.log ||
  die "montecarlo: $(cat mc.log)"
HERE=$here python3 - mc <<'PY' || die "montecarlo's demand tables"
import csv, json, os, sys
sys.path.insert(0, os.environ["HERE"])
from pelicun_schema import check_schema
d = sys.argv[1]
tables = json.load(open(os.path.join(d, "summary.json")))["demand_tables"]
assert tables["files"] == ["demands_shear3.csv", "demands_shear2.csv"], tables
runs = [r for r in csv.DictReader(open(os.path.join(d, "realizations.csv"))) if r["completed"] == "1"]
assert tables["realizations"] == len(runs) == 4, (tables, len(runs))
g = 9.80665
impacts = 0
for b, n in (("shear3", 3), ("shear2", 2)):
    head, data = check_schema(os.path.join(d, f"demands_{b}.csv"))
    assert len(data) == len(runs)
    for row, run in zip(data, runs):
        v = dict(zip(head, map(float, row[1:])))
        assert abs(v["1-PFA-0-1"] - float(run["peak_ground_acc_m_s2"]) / g) <= 1e-15 * v["1-PFA-0-1"]
        for f in range(1, n + 1):
            assert v[f"1-PID-{f}-1"] == float(run[f"{b}_storey{f}_peak_drift_ratio"])
            assert v[f"1-RID-{f}-1"] == abs(float(run[f"{b}_storey{f}_residual_drift_ratio"]))
            a = float(run[f"{b}_floor{f}_peak_acc_m_s2"])
            assert abs(v[f"1-PFA-{f}-1"] - a / g) <= 1e-15 * a
        gaps = [k for k in head if k.startswith("1-NIMP-")]
        assert gaps, head
        for k in gaps:
            _, _, floor, gap = k.split("-")
            assert v[k] == float(run[f"gap{gap}_impacts"])
            assert v[f"1-PIMF-{floor}-{gap}"] == float(run[f"gap{gap}_peak_contact_force"])
            assert v[f"1-PIMV-{floor}-{gap}"] == float(run[f"gap{gap}_peak_impact_velocity"])
for run in runs:
    gaps = [k[:-len("_impacts")] for k in run if k.startswith("gap") and k.endswith("_impacts")]
    assert sum(float(run[k + "_impacts"]) for k in gaps) == float(run["n_impacts"]), run
    assert max(float(run[k + "_peak_contact_force"]) for k in gaps) == float(run["peak_contact_force"])
    impacts += float(run["n_impacts"])
assert impacts > 0, "no realization pounded: the test checks nothing of the gaps"
print(f"montecarlo's demand tables: {len(runs)} realizations, {impacts:.0f} impacts, realizations.csv's values")
PY
"$poundfe" montecarlo ida.prm --output mc-plain --set "Output/Plots=false" --set "Monte Carlo/Realizations=2" \
  --set "Ground motion/Stochastic/Duration=2" > /dev/null || die "montecarlo without tables"
[ ! -e mc-plain/demands_shear3.csv ] || die "montecarlo wrote demand tables unasked"
! grep -q "peak_ground_acc" mc-plain/realizations.csv || die "montecarlo's journal has the tables' columns unasked"

# bad input
suite=(--set "IDA/Suite=$work/gen/records/suite.csv")
expect 1 "parameter 'IDA/Demand intensities': each must lie in (0, IDA/Upper intensity], got 9" \
  ida ida.prm "${short[@]}" "${suite[@]}" --set "IDA/Demand intensities=0.2, 9" --output out
expect 1 "it needs IDA/Intensity measure = Sa, not PGA" ida ida.prm "${short[@]}" "${suite[@]}" \
  --set "IDA/Intensity measure=PGA" --set "IDA/Collapse margin/MCE spectral acceleration=0.5" --output out
report "loss"
