#!/usr/bin/env bash
# Contact/Model = nonsmooth (rigid contact, doc/theory.md §3.9d) through the
# commands that run time histories, each against an independent reference:
# a run of the same realization, record or value (`poundfe run`, itself
# checked by rigid_contact.sh and python/siconos_moreau_jean), on the shear
# pair of input/shear-pair-pounding.prm at 2 mm, e = 0.65, 4 s at 1e-3 s:
#   - montecarlo: realization 1's row equals run's Realization 1; with a
#     random separation, run's at the realization's separation;
#   - subset: level 0's sample k is realization k: equal to run's;
#   - fragility: the one realization at PGA 0.5 g equals run's at 0.5 g;
#   - sweep: the point at a separation of 4 mm equals run's at 4 mm, and
#     with a damped law the point at e = 0.3 run's at 0.3;
#   - separation: the free responses (no contact) are the penalty model's;
#   - mitigation: the bare pair's row equals run's realization 0; bumper
#     cases are refused (exit 1, nothing written);
#   - msa and ida: a record at an intensity equals run's of the record
#     times the scale factor the command wrote;
# the same numbers, so to 1e-9 relative (the engines are the same code
# path); each with impacts, so that the contact was exercised. dynamic-form
# and bifurcation refuse nonsmooth saying why (rigid_stationary.sh, which
# also checks stationary-pdf).
set -u
poundfe=$1 input=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
cd "$work"
. "$here/expect.sh"

if ! "$poundfe" --version | grep -q "nonsmooth"; then
  echo "rigid-commands: this build has no Siconos (penalty only): nothing to check"
  exit 0
fi
sed -e '/^subsection Contact/a\  set Model = nonsmooth\n  set Coefficient of restitution = 0.65' \
    -e 's/^\( *set Separations *=\).*/\1 0.002/' \
    -e 's/^\( *set Duration *=\).*/\1 4/' -e '/^subsection Output/a\  set Plots = false' \
    "$input" > pair.prm
printf 'subsection Monte Carlo\n  set Realizations = 2\nend\n' >> pair.prm

# run's peak drift of storey 1 of shear3, impacts, largest drift: "a b c"
run_peaks() {
  python3 - "$1" <<'PY'
import json, sys
s = json.load(open(f"{sys.argv[1]}/summary.json"))
drifts = [st["peak_drift_ratio"] for b in s["buildings"] for st in b["storeys"]]
print(s["buildings"][0]["storeys"][0]["peak_drift_ratio"], sum(g["impacts"] for g in s["gaps"]), max(drifts))
PY
}
# the row of CSV $1 whose column $2 is $3: columns $4... as "a b ..."
csv_row() {
  python3 - "$@" <<'PY'
import csv, sys
path, key, value, *columns = sys.argv[1:]
rows = [r for r in csv.DictReader(l for l in open(path) if not l.startswith("#")) if r[key] == value]
assert len(rows) == 1, (path, key, value, len(rows))
print(" ".join(rows[0][c] for c in columns))
PY
}
# same WHAT "a b ..." "a b ...": every number equal to 1e-9 relative
same() {
  python3 - "$@" <<'PY' || { fail "$1: $2 against $3"; return; }
import sys
what, a, b = sys.argv[1:]
x, y = [float(v) for v in a.split()], [float(v) for v in b.split()]
assert x and len(x) == len(y), (x, y)
for u, v in zip(x, y):
    assert abs(u - v) <= 1e-9 * max(abs(u), abs(v), 1e-300), (what, u, v)
PY
  echo "ok   $1: $2"
}
run() { "$poundfe" run "$@" > /dev/null 2> run.err || fail "run $*: exit $? $(head -c 300 run.err)"; }

run pair.prm --output run0
read -r drift0 impacts0 max0 <<< "$(run_peaks run0)"
[ "$impacts0" -gt 0 ] || fail "no impacts in the reference run"
run pair.prm --set "Ground motion/Stochastic/Realization=1" --output run1

# montecarlo: realization 1
"$poundfe" montecarlo pair.prm --output mc > /dev/null 2>&1 || fail "montecarlo exited $?"
same "montecarlo realization 1 = run's" \
  "$(csv_row mc/realizations.csv realization 1 shear3_storey1_peak_drift_ratio n_impacts max_drift_ratio)" \
  "$(run_peaks run1)"

# montecarlo with a random separation: each realization's own gaps (the
# rigid-contact engine made again; kept, it would step the file's 2 mm)
printf 'subsection Random parameters\n  set Variables = s: Model/Separations ~ uniform lower 0.001 upper 0.004\nend\n' > random.prm
cat pair.prm random.prm > pair-random.prm
"$poundfe" montecarlo pair-random.prm --output mc-random > /dev/null 2>&1 || fail "montecarlo (random separation) exited $?"
separation=$(csv_row mc-random/realizations.csv realization 1 s)
run pair.prm --set "Ground motion/Stochastic/Realization=1" --set "Model/Separations=$separation" \
  --output run1-random
same "montecarlo realization 1 at its random separation $separation m = run's" \
  "$(csv_row mc-random/realizations.csv realization 1 shear3_storey1_peak_drift_ratio n_impacts max_drift_ratio)" \
  "$(run_peaks run1-random)"

# subset: level 0's samples are the realizations 0, 1, ...
printf 'subsection Subset simulation\n  set Response = peak drift ratio\n  set Building = 1\n  set Storey = 1\n  set Threshold = %s\n  set Samples per level = 4\n  set Conditional probability = 0.25\nend\n' \
  "$drift0" > subset.prm
cat pair.prm subset.prm > pair-subset.prm
"$poundfe" subset pair-subset.prm --output subset > /dev/null 2>&1 || fail "subset exited $?"
same "subset level 0 sample 0 = run's realization 0" \
  "$(python3 -c "
import csv; print([r for r in csv.DictReader(l for l in open('subset/subset_runs.csv') if not l.startswith('#')) if r['level'] == '0' and r['sample'] == '0'][0]['response'])")" \
  "$drift0"

# fragility: one realization at 0.5 g
printf 'subsection Fragility\n  set PGA levels = 0.5\n  set Realizations per level = 1\nend\n' > fragility.prm
cat pair.prm fragility.prm > pair-fragility.prm
"$poundfe" fragility pair-fragility.prm --output fragility > /dev/null 2>&1 || fail "fragility exited $?"
run pair.prm --set "Ground motion/Stochastic/Target PGA=0.5" --output run-pga
same "fragility at 0.5 g = run's" \
  "$(csv_row fragility/pga_0.5g/realizations.csv realization 0 shear3_storey1_peak_drift_ratio n_impacts max_drift_ratio)" \
  "$(run_peaks run-pga)"

# sweep: the point at 4 mm
printf 'subsection Sweep\n  set Parameter = Model/Separations\n  set Values = 0.002, 0.004\nend\n' > sweep.prm
cat pair.prm sweep.prm > pair-sweep.prm
"$poundfe" sweep pair-sweep.prm --output sweep > /dev/null 2>&1 || fail "sweep exited $?"
run pair.prm --set "Model/Separations=0.004" --output run-4mm
read -r d4 n4 m4 <<< "$(run_peaks run-4mm)"
same "sweep at 2 mm = run's" \
  "$(csv_row sweep/sweep.csv Model_Separations 0.002 shear3_storey1_peak_drift_ratio)" "$drift0"
same "sweep at 4 mm = run's" \
  "$(csv_row sweep/sweep.csv Model_Separations 0.004 shear3_storey1_peak_drift_ratio)" "$d4"

# sweep of the restitution (a damped law, whose registered e would refit
# only its damping): the point at e = 0.3 is run's at 0.3
printf 'subsection Sweep\n  set Parameter = Contact/Coefficient of restitution\n  set Values = 0.65, 0.3\nend\n' > sweep-e.prm
sed 's/set Law *= linear/set Law = hertz-damp/' pair.prm > pair-damped.prm
cat pair-damped.prm sweep-e.prm > pair-sweep-e.prm
"$poundfe" sweep pair-sweep-e.prm --output sweep-e > /dev/null 2>&1 || fail "sweep of e exited $?"
run pair-damped.prm --set "Contact/Coefficient of restitution=0.3" --output run-e
read -r de ne me <<< "$(run_peaks run-e)"
same "sweep at e = 0.3 = run's" \
  "$(csv_row sweep-e/sweep.csv Contact_Coefficient_of_restitution 0.3 shear3_storey1_peak_drift_ratio n_impacts)" \
  "$de $ne"

# separation: the free responses have no contact, whatever its model
"$poundfe" separation pair.prm --set "Monte Carlo/Realizations=1" --output sep-rigid > /dev/null 2>&1 ||
  fail "separation (nonsmooth) exited $?"
"$poundfe" separation pair.prm --set "Monte Carlo/Realizations=1" --set "Contact/Model=penalty" \
  --output sep-penalty > /dev/null 2>&1 || fail "separation (penalty) exited $?"
diff sep-rigid/separation.csv sep-penalty/separation.csv > /dev/null &&
  echo "ok   separation: separation.csv as the penalty model's" ||
  fail "separation: nonsmooth and penalty free responses differ"

# mitigation: the bare pair over one realization; bumpers refused
printf 'subsection Mitigation\n  set Damper locations = 1 2 0 2 2 0\n  set Damper coefficients = 2e4\nend\n' > mitigation.prm
cat pair.prm mitigation.prm > pair-mitigation.prm
"$poundfe" mitigation pair-mitigation.prm --set "Monte Carlo/Realizations=1" --output mitigation \
  > /dev/null 2>&1 || fail "mitigation exited $?"
same "mitigation bare pair = run's realization 0" \
  "$(csv_row mitigation/mitigation.csv case bare peak_drift_ratio_shear3 n_impacts max_drift_ratio)" \
  "$drift0 $impacts0 $max0"
# (without the law's Stiffness, whose warning would come first)
sed '/set Stiffness/d' pair-mitigation.prm > pair-bumpers.prm
expect 1 "parameter 'Contact/Model'" mitigation pair-bumpers.prm \
  --set "Mitigation/Bumper thicknesses=0.001" --set "Mitigation/Bumper stiffnesses=2e6" --output out

# msa and ida on a suite of two generated records
"$poundfe" ground-motion pair.prm --realizations 2 --write-at2 --set "Contact/Model=penalty" \
  --output gm > /dev/null 2>&1 ||
  fail "ground-motion exited $?"
printf 'subsection IDA\n  set Suite = gm/records/suite.csv\n  set Intensity measure = PGA\n  set Collapse drift ratio = 0.002\nend\nsubsection MSA\n  set Intensities = 0.5\n  set Cloud = false\nend\n' > records.prm
cat pair.prm records.prm > pair-records.prm
# run of record $1 (realization_$1) times $2, into $3
record_run() {
  run pair-records.prm --set "Ground motion/Type=record" \
    --set "Ground motion/Record/File=gm/records/realization_$1.AT2" \
    --set "Ground motion/Scale factor=$2" --output "$3"
}
"$poundfe" msa pair-records.prm --output msa > /dev/null 2>&1 || fail "msa exited $?"
scale=$(csv_row msa/msa.csv name realization_1 scale_factor)
record_run 1 "$scale" run-msa
read -r dm nm mm <<< "$(run_peaks run-msa)"
[ "$nm" -gt 0 ] || fail "msa: no impacts at 0.5 g"
same "msa realization_1 at 0.5 g = run's" \
  "$(csv_row msa/msa.csv name realization_1 shear3_storey1_peak_drift_ratio)" "$dm"
"$poundfe" ida pair-records.prm --output ida > /dev/null 2>&1 || fail "ida exited $?"
row=$(python3 -c "
import csv
rows = [r for r in csv.DictReader(open('ida/ida.csv')) if r['name'] == 'realization_0']
r = max(rows, key=lambda r: float(r['intensity']))
print(r['scale_factor'], r['shear3_storey1_peak_drift_ratio'])")
read -r scale drift <<< "$row"
record_run 0 "$scale" run-ida
read -r di ni mi <<< "$(run_peaks run-ida)"
same "ida realization_0 at its highest intensity = run's" "$drift" "$di"

# what refuses rigid contact: dynamic-form; a random restitution
printf 'subsection Random parameters\n  set Variables = e: Contact/Coefficient of restitution ~ uniform lower 0.3 upper 0.9\nend\n' > random-e.prm
cat pair-damped.prm random-e.prm > pair-random-e.prm
expect 1 "parameter 'Random parameters/Variables'" montecarlo pair-random-e.prm --output out
expect 1 "parameter 'Contact/Model'" dynamic-form pair.prm --output out
echo "rigid-commands: $n refusals checked, $failures failures"
exit $((failures > 0))
