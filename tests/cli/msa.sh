#!/usr/bin/env bash
# msa (multiple stripes and cloud) and select-records:
#  - msa of a LINEAR model: every demand divided by the stripe's intensity
#    is the same at every stripe, record by record (1e-9 relative to the
#    column's largest: round-off of ~1000 steps);
#  - the cloud of a linear oscillator (one storey, 5 % modal damping) with
#    Sa(T1, 5 %) as the measure: ln(drift) on ln(Sa) has slope 1 (0.01: the
#    integrator's period error against the exact oscillator of the
#    spectrum, (dt/T)^2 ~ 1e-4, and the peaks' sampling) and a dispersion
#    below 0.01;
#  - one rank and two give the same msa.csv (the runs dealt one by one to
#    the free rank); a second run resumes from the journal and runs
#    nothing; a journal cut to half its runs and a partial line (a killed
#    run) is resumed on two ranks: only the missing runs run, the same
#    msa.csv;
#  - the example input (shortened) at the return periods of a hazard curve,
#    with limit states on pounding: every file, an annual rate per state;
#    with Output/Demand tables, a pelicun demand table per building and
#    stripe (pelicun's schema, 1-PID-1-1 ...): a row per run that did not
#    collapse, its demands those of msa.csv (1e-9 relative: the same
#    numbers printed twice);
#  - select-records writes a suite that msa reads; its mean spectrum is
#    within the factor it reports of the target; selected to a conditional
#    mean spectrum, the set's +/- 1 sigma of ln Sa is the spread computed
#    in the test from the records' columns (1e-9 in ln Sa: printed
#    numbers), the target's band symmetric in ln Sa and up to BSSA14's
#    sigma wide (0.1 to 1);
#  - with MSA/Cloud, a demand table of the cloud too (a row per unscaled
#    run that did not collapse, its demands those of cloud.csv, its PGA the
#    run's intensity, 1e-9 relative);
#  - the example's Ground motion section (its suite's generator) draws no
#    warning from msa;
#  - bad input: one line naming file, line and parameter, exit 1, nothing
#    written; among it Sa's period outside what every record resolves
#    (twice its time step to its duration), and select-records' fit range
#    or Scaling = intensity's period outside it.
poundfe=$(realpath "$1") mpirun=$2 example=$(realpath "$3")
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
# shellcheck source=/dev/null
. "$here/expect.sh"
die() { echo "FAIL $*"; exit 1; }

"$poundfe" ground-motion "$example" --realizations 4 --write-at2 --output gen \
  --set "Ground motion/Stochastic/Duration=4" --set "Output/Plots=false" > /dev/null ||
  die "ground-motion --write-at2"
suite=(--set "IDA/Suite=$work/gen/records/suite.csv")

# a linear model: demands proportional to the intensity
"$poundfe" msa "$here/msa/linear.prm" --output linear "${suite[@]}" > linear.log ||
  die "msa linear: $(cat linear.log)"
python3 - linear/msa.csv <<'PY' || die "linear msa not proportional"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
demands = [c for c in rows[0] if c.startswith(("storey", "floor", "max_"))]
assert len(rows) == 12 and demands, (len(rows), demands)
for c in demands:
    top = max(abs(float(r[c])) for r in rows) or 1
    for rec in {r["record"] for r in rows}:
        ratios = [float(r[c]) / float(r["intensity"]) for r in rows if r["record"] == rec]
        if max(ratios) - min(ratios) > 1e-9 * top:
            sys.exit(f"{c} of record {rec}: {ratios}")
print("linear: every demand proportional to the intensity")
PY
grep -q '"name": "max_drift_ratio > 0.004"' linear/summary.json || die "no limit state in summary.json"

# the cloud of a linear oscillator: slope 1
"$poundfe" msa "$here/msa/sdof.prm" --output sdof "${suite[@]}" > sdof.log || die "msa sdof: $(cat sdof.log)"
python3 - sdof/summary.json <<'PY' || die "cloud slope"
import json, sys
cloud = json.load(open(sys.argv[1]))["cloud"]
assert cloud["fitted"] and cloud["points"] == 4, cloud
if abs(cloud["b"] - 1) > 0.01 or cloud["dispersion"] > 0.01:
    sys.exit(f"cloud of a linear oscillator: {cloud}")
print(f"cloud: slope {cloud['b']}, dispersion {cloud['dispersion']}")
PY

# two ranks: the same runs; resumed: nothing runs again
"$mpirun" -np 2 "$poundfe" msa "$here/msa/linear.prm" --output two "${suite[@]}" > /dev/null ||
  die "msa on two ranks"
cmp linear/msa.csv two/msa.csv || die "one rank and two give different msa.csv"
"$poundfe" msa "$here/msa/linear.prm" --output linear "${suite[@]}" > again.log || die "resumed msa"
grep -q '"runs_now": 0' linear/summary.json || die "a finished msa ran again"
cmp linear/msa.csv two/msa.csv || die "the resumed run changed msa.csv"

# a killed run's journal (two ranks): a prefix of its stripes' runs and a
# partial line; the same command on two ranks runs only the missing runs
journal=two/journal/stripes/realizations.csv
total=$(($(wc -l < "$journal") - 1))
keep=$((total / 2))
head -n $((keep + 1)) "$journal" > cut.csv
printf '%s' "$(sed -n "$((keep + 2))p" "$journal" | cut -c1-12)" >> cut.csv
mv cut.csv "$journal"
"$mpirun" -np 2 "$poundfe" msa "$here/msa/linear.prm" --output two "${suite[@]}" > /dev/null ||
  die "msa resumed on two ranks"
grep -Eq "\"runs_now\": $((total - keep))([^0-9]|\$)" two/summary.json ||
  die "resumed from $keep of $total runs: $(grep runs_now two/summary.json), expected $((total - keep))"
cmp linear/msa.csv two/msa.csv || die "the run resumed on two ranks changed msa.csv"

# the example, short, on a hazard curve of PGA
printf 'intensity,pga_g,annual_rate_per_year\n' > hazard.csv
for x in 0.01 0.02 0.05 0.1 0.2 0.5 1 2; do
  python3 -c "print(f'{$x},{$x},{1e-4 * $x ** -2.5}')" >> hazard.csv
done
"$poundfe" msa "$example" --output example "${suite[@]}" --set "MSA/Hazard curve=$work/hazard.csv" \
  --set "MSA/Return periods=475" --set "MSA/Intensities=0.2, 0.8" \
  --set "Ground motion/Stochastic/Duration=4" --set "Output/Plots=false" \
  --set "Output/Demand tables=true" > example.log 2> example.err || die "msa example: $(cat example.log example.err)"
for f in summary.json msa.csv msa_stripes.csv msa_fragility.csv msa_curves.csv cloud.csv; do
  [ -f "example/$f" ] || die "msa wrote no $f"
done
grep -q "gap1_impacts_gt_0" example/msa_fragility.csv || die "no pounding limit state"
[ "$(wc -l < example/msa.csv)" -eq 13 ] || die "expected 3 stripes x 4 records in msa.csv"
HERE=$here python3 - example <<'PY' || die "msa's demand tables"
import csv, json, os, sys
sys.path.insert(0, os.environ["HERE"])
from pelicun_schema import check_schema
d = sys.argv[1]
runs = list(csv.DictReader(open(f"{d}/msa.csv")))
listed = json.load(open(f"{d}/summary.json"))["demand_tables"]
assert len(listed) == 4 and listed[3]["cloud"] is True and "intensity" not in listed[3], listed
for j, entry in enumerate(listed[:3], 1):
    stripe = [r for r in runs if r["stripe"] == str(j)]
    kept = [r for r in stripe if r["collapsed"] == "0"]
    assert entry["collapsed"] == len(stripe) - len(kept) and len(entry["records"]) == len(kept), entry
    for b, n in (("shear3", 3), ("shear2", 2)):
        name = f"demands_{b}_stripe{j}.csv"
        assert name in entry["files"], (name, entry)
        head, rows = check_schema(f"{d}/{name}")
        assert head[0] == "1-PFA-0-1" and "1-PID-1-1" in head and f"1-RID-{n}-1" in head, head
        assert any(h.startswith("1-NIMP-") for h in head), head
        assert len(rows) == len(kept), (name, len(rows), len(kept))
        for row, run in zip(rows, kept):
            v = dict(zip(head, map(float, row[1:])))
            for s in range(1, n + 1):  # the run's own demands, exactly as msa.csv prints them
                for col, key, f in ((f"1-PID-{s}-1", f"{b}_storey{s}_peak_drift_ratio", float),
                                    (f"1-RID-{s}-1", f"{b}_storey{s}_residual_drift_ratio",
                                     lambda x: abs(float(x))),
                                    (f"1-PFA-{s}-1", f"{b}_floor{s}_peak_acc_m_s2",
                                     lambda x: float(x) / 9.80665)):
                    if abs(v[col] - f(run[key])) > 1e-9 * max(1e-12, abs(v[col])):
                        sys.exit(f"{name} {col}: {v[col]} against {run[key]} of msa.csv")
# the cloud's: a row per unscaled run that did not collapse, its demands
# those of cloud.csv, PGA (the measure) the record's own
cloud = list(csv.DictReader(open(f"{d}/cloud.csv")))
kept = [r for r in cloud if r["collapsed"] == "0"]
assert len(listed[3]["records"]) == len(kept) and kept, listed[3]
for b, n in (("shear3", 3), ("shear2", 2)):
    name = f"demands_{b}_cloud.csv"
    assert name in listed[3]["files"], listed[3]
    head, rows = check_schema(f"{d}/{name}")
    assert len(rows) == len(kept), (name, len(rows), len(kept))
    for row, run in zip(rows, kept):
        v = dict(zip(head, map(float, row[1:])))
        if abs(v["1-PFA-0-1"] - float(run["intensity"])) > 1e-9 * v["1-PFA-0-1"]:
            sys.exit(f"{name}: PGA {v['1-PFA-0-1']} g against the run's {run['intensity']}")
        for s in range(1, n + 1):
            want = float(run[f"{b}_storey{s}_peak_drift_ratio"])
            if abs(v[f"1-PID-{s}-1"] - want) > 1e-9 * max(1e-12, abs(want)):
                sys.exit(f"{name} 1-PID-{s}-1: {v[f'1-PID-{s}-1']} against {want} of cloud.csv")
print("msa: a pelicun demand table per building and stripe, and of the cloud, the runs' own demands")
PY
# the example's Ground motion section is its suite's generator (ground-motion
# --write-at2), its documented workflow: msa runs it without a warning of it
n=$((n + 1))
! grep -q "Ground motion" example.err ||
  die "msa warns of the Ground motion section: $(cat example.err)"
python3 -c 'import json, sys
sys.exit(any("Ground motion" in w for w in json.load(open(sys.argv[1])).get("warnings", [])))' \
  example/summary.json || die "summary.json warns of the Ground motion section"
echo "ok   msa takes the example's Ground motion section without a warning"

# select-records: a suite msa reads
"$poundfe" select-records "$example" --output sel "${suite[@]}" --set "Selection/Records=2" \
  --set "Selection/Target=asce7" --set "Selection/Scale limits=0.05, 20" \
  --set "Output/Plots=false" > sel.log || die "select-records: $(cat sel.log)"
[ "$(grep -vc '^name' sel/selected_suite.csv)" -eq 2 ] || die "not two records selected"
python3 - sel/selection.csv sel/summary.json <<'PY' || die "selection mean"
import csv, json, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
worst = max(abs(math.log(float(r["mean_g"]) / float(r["target_g"]))) for r in rows)
said = json.load(open(sys.argv[2]))["max_mean_log_misfit"]
assert abs(worst - said) < 1e-9 and worst < 1.0, (worst, said)
print(f"selection: mean within exp({worst:.3f}) of the target")
PY
# to a conditional mean spectrum: the set's +/- 1 sigma of ln Sa in
# selection.csv against the spread computed here from its records' columns,
# and the target's band exp(+/- sigma) about its median
"$poundfe" select-records "$example" --output cms "${suite[@]}" --set "Selection/Records=3" \
  --set "Selection/Target=cms" --set "Selection/Scale limits=0.05, 20" \
  --set "Output/Plots=false" > cms.log || die "select-records to a CMS: $(cat cms.log)"
python3 - cms/selection.csv <<'PY' || die "the selected set's spread against a CMS"
import csv, math, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
fixed = {"period_s", "target_g", "target_minus_g", "target_plus_g", "mean_g", "mean_minus_g",
         "mean_plus_g"}
records = [c for c in rows[0] if c not in fixed]
assert len(records) == 3, records
widest = 0
for r in rows:
    ln = [math.log(float(r[c])) for c in records]
    m, s = statistics.mean(ln), statistics.stdev(ln)
    for col, want in (("mean_g", m), ("mean_minus_g", m - s), ("mean_plus_g", m + s)):
        assert abs(math.log(float(r[col])) - want) < 1e-9, (r["period_s"], col, r[col], want)
    lo, mid, hi = (math.log(float(r[c])) for c in ("target_minus_g", "target_g", "target_plus_g"))
    assert abs((hi - mid) - (mid - lo)) < 1e-9 and hi >= mid, r
    widest = max(widest, hi - mid)
assert 0.1 < widest < 1, widest  # BSSA14's sigma, reduced by the correlation
print(f"selection to a CMS: the set's spread as computed here; conditional sigma up to {widest:.3f}")
PY
"$poundfe" msa "$example" --output selected --set "IDA/Suite=$work/sel/selected_suite.csv" \
  --set "MSA/Intensities=0.3" --set "MSA/Hazard curve=" --set "MSA/Return periods=" \
  --set "MSA/Cloud=false" --set "Output/Plots=false" > selected.log || die "msa on the selected suite"

# bad input
m=$work/msa/linear.prm
mkdir -p msa && cp "$here/msa/linear.prm" msa/
printf 'period_s,sa_g\n0.05,0.5\n0.5,0\n3,0.2\n' > zero.csv
printf 'period_s,sa_g\n0.05,0.5\n0.5,-1\n3,0.2\n' > negative.csv
printf 'period_s,sa_g\n0.5,0.5\n1,0.4\n' > narrow.csv
sel=(select-records "$m" "${suite[@]}" --output out --set "Selection/Records=2")
expect 1 "zero.csv:3: parameter 'sa_g': a target spectrum must be positive" "${sel[@]}" \
  --set "Selection/Target=table" --set "Selection/Spectrum table=$work/zero.csv"
expect 1 "negative.csv:3: parameter 'sa_g': a target spectrum must be positive, got -1 g" "${sel[@]}" \
  --set "Selection/Target=table" --set "Selection/Spectrum table=$work/negative.csv"
expect 1 "parameter 'Selection/Minimum period': the period range is outside the spectrum table's" \
  "${sel[@]}" --set "Selection/Target=table" --set "Selection/Spectrum table=$work/narrow.csv"
expect 1 "parameter 'Selection/Maximum period': is outside BSSA14's periods" "${sel[@]}" \
  --set "Selection/Target=cms" --set "Selection/Maximum period=12"
expect 1 "parameter 'Selection/Records': the suite has 4 records, fewer than the 9 requested" \
  "${sel[@]}" --set "Selection/Records=9"
expect 1 "parameter 'Selection/Scale limits': only 0 of the 4 records have a scale factor within [100, 200]" \
  "${sel[@]}" --set "Selection/Records=2" --set "Selection/Scale limits=100, 200"
expect 1 "parameter 'IDA/Damping ratio': a conditional mean spectrum (BSSA14) is of 5 % damping" \
  "${sel[@]}" --set "Selection/Target=cms" --set "IDA/Damping ratio=0.02"
ms=(msa "$m" "${suite[@]}" --output out)
expect 1 "parameter 'MSA/Return periods': stripes at return periods need a MSA/Hazard curve" \
  "${ms[@]}" --set "MSA/Return periods=475"
expect 1 "parameter 'MSA/Return periods': the return period" \
  "${ms[@]}" --set "MSA/Return periods=1e6" --set "MSA/Hazard curve=$work/hazard.csv" \
  --set "MSA/Hazard column=pga_g"
expect 1 "parameter 'MSA/Limit states': 'gap1_impacts' is not a demand of this model" \
  "${ms[@]}" --set "MSA/Limit states=gap1_impacts > 0"
expect 1 "parameter 'MSA/Limit states': expected 'demand > threshold', got 'max_drift_ratio 0.01'" \
  "${ms[@]}" --set "MSA/Limit states=max_drift_ratio 0.01"
expect 1 "parameter 'MSA/Intensities': msa needs stripes" "${ms[@]}" --set "MSA/Intensities="
# an incidence angle on a planar model: refused as run refuses it, not ignored
expect 1 "parameter 'Ground motion/Incidence angle': an incidence angle needs Model/Dimension = 3" \
  "${ms[@]}" --set "Ground motion/Incidence angle=30"
expect 1 "parameter 'Ground motion/Incidence angle': an incidence angle needs Model/Dimension = 3" \
  ida "$m" "${suite[@]}" --output out --set "Ground motion/Incidence angle=90"
expect 1 "parameter 'intensity': the hazard curve has no column 'intensity'" "${ms[@]}" \
  --set "MSA/Hazard curve=$work/zero.csv" --set "MSA/Hazard column=intensity"
# Sa's periods outside those every record resolves (twice its time step to
# its duration): refused naming the entry, with its line when written
resolves="outside the periods every record of the suite resolves"
expect 1 "parameter 'IDA/Period': Sa's period, 0.001 s, lies $resolves" "${ms[@]}" --set "IDA/Period=0.001"
expect 1 "parameter 'IDA/Period': Sa's period, 1000 s, lies $resolves" \
  ida "$m" "${suite[@]}" --output out --set "IDA/Period=1000"
expect 1 "parameter 'IDA/Sa_avg range': Sa_avg's periods, 0.2 to 1000 s, lie $resolves" "${ms[@]}" \
  --set "IDA/Intensity measure=Sa_avg" --set "IDA/Period=1" --set "IDA/Sa_avg range=0.2, 1000"
# Sa_avg about a written period that is itself out of range: the period is blamed
expect 1 "parameter 'IDA/Period': Sa_avg's periods, 200 to 1000 s, lie $resolves" "${ms[@]}" \
  --set "IDA/Intensity measure=Sa_avg" --set "IDA/Period=1000" --set "IDA/Sa_avg range=0.2, 1"
sed 's/^  set Intensity measure    = Sa$/&\n  set Period               = 0.001/' "$m" > period.prm
expect 1 "period.prm:17: parameter 'IDA/Period': Sa's period, 0.001 s, lies $resolves" \
  msa "$work/period.prm" "${suite[@]}" --output out
expect 0 "runs" msa "$m" "${suite[@]}" --output periods --set "IDA/Period=0.05" --set "MSA/Intensities=0.1"
rm -rf periods
# select-records: the fit's period range, and Scaling = intensity's Sa
# period, outside the periods every record resolves (its time step of
# 0.005 s: 0.01 s; its duration: 4 s); a range within them is taken
expect 1 "parameter 'Selection/Maximum period': the fit's periods, 0.1 to 10 s, lie $resolves, 0.01 to 4 s" \
  "${sel[@]}" --set "Selection/Maximum period=10"
expect 1 "parameter 'Selection/Minimum period': the fit's periods, 0.005 to 2 s, lie $resolves" \
  "${sel[@]}" --set "Selection/Minimum period=0.005"
printf 'subsection Selection\n  set Minimum period = 0.05\n  set Maximum period = 5\nend\n' > fit.prm
cat "$m" fit.prm > fit-range.prm
expect 1 "fit-range.prm:31: parameter 'Selection/Maximum period': the fit's periods, 0.05 to 5 s" \
  select-records "$work/fit-range.prm" "${suite[@]}" --output out --set "Selection/Records=2"
expect 1 "parameter 'IDA/Period': Sa's period, 6 s, lies $resolves" "${sel[@]}" \
  --set "Selection/Scaling=intensity" --set "Selection/Target intensity=0.3" --set "IDA/Period=6"
expect 0 "results in" select-records "$m" "${suite[@]}" --output periods --set "Selection/Records=2" \
  --set "Selection/Minimum period=0.01" --set "Selection/Maximum period=4"
rm -rf periods
report "msa"
