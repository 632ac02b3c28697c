#!/usr/bin/env bash
# `poundfe sweep` against `poundfe run` on files with the swept value written
# in: input/two-buildings.prm over Model/Separations = 0, 0.005 (pounding at
# both). For each value, every storey's peak drift ratio, every floor's peak
# displacement and absolute acceleration, and the number of impacts of the
# sweep's row equal the run's summary.json to 1e-12 relative (the same
# arithmetic reached through an override instead of the file). Also: the
# files the sweep writes, and no temporary file left. Frames are placed by
# the separation, so their model is built from each value's input
# (summary.json: model_built_once false). A pair of shear buildings is
# built once and each value set in place (model_built_once true): its
# sweep.csv rows equal, to the last digit, those of one-value sweeps, whose
# model is built from the input with that value.
set -eu
poundfe=$1 file=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
values="0, 0.005"
{ cat "$file"; printf 'subsection Sweep\n  set Parameter = Model/Separations\n  set Values = %s\nend\n' "$values"; } > "$work/sweep.prm"
"$poundfe" sweep "$work/sweep.prm" --output "$work/sweep" > /dev/null
for f in sweep.csv summary.json sweep.png; do
  [ -s "$work/sweep/$f" ] || { echo "FAIL: no $f"; exit 1; }
done
if ls -a "$work/sweep" | grep -q '\.tmp$'; then echo "FAIL: temporary files left"; exit 1; fi
for value in 0 0.005; do
  sed "s/^\( *set Separations *=\).*/\1 $value/" "$file" > "$work/run-$value.prm"
  "$poundfe" run "$work/run-$value.prm" --output "$work/run-$value" > /dev/null
done
python3 - "$work" <<'PY'
import csv, json, sys
work = sys.argv[1]
rows = list(csv.DictReader(open(f"{work}/sweep/sweep.csv")))
failures = 0
def check(name, got, want):
    global failures
    if abs(got - want) > 1e-12 * max(abs(want), 1e-300):
        print(f"FAIL {name}: sweep {got!r}, run {want!r}"); failures += 1
for row, value in zip(rows, ["0", "0.005"]):
    assert float(row["Model_Separations"]) == float(value), row["Model_Separations"]
    assert row["completed"] == "1"
    summary = json.load(open(f"{work}/run-{value}/summary.json"))
    n = 0
    for b in summary["buildings"]:
        for s in b["storeys"]:
            i = s["storey"]
            check(f"{value} {b['name']} storey {i} drift", float(row[f"{b['name']}_storey{i}_peak_drift_ratio"]), s["peak_drift_ratio"])
            check(f"{value} {b['name']} floor {i} displacement", float(row[f"{b['name']}_floor{i}_peak_displacement_m"]), s["peak_floor_displacement_m"])
            check(f"{value} {b['name']} floor {i} acceleration", float(row[f"{b['name']}_floor{i}_peak_acc_m_s2"]), s["peak_absolute_floor_acceleration_m_s2"])
            n += 3
    impacts = sum(1 for _ in open(f"{work}/run-{value}/impacts.csv")) - 1
    check(f"{value} impacts", float(row["n_impacts"]), impacts)
    print(f"ok   Separations = {value}: {n} peaks and {impacts} impacts as run")
sys.exit(1 if failures else 0)
PY
built_once() { python3 -c "import json, sys; print(json.load(open(sys.argv[1]))['model_built_once'])" "$1"; }
[ "$(built_once "$work/sweep/summary.json")" = False ] || { echo "FAIL: frames placed by the separation built once"; exit 1; }
pair=$(dirname "$0")/../dynamics/uncertain-shear-pair.prm
shear_sweep() { # name values
  { cat "$pair"; printf 'subsection Sweep\n  set Parameter = Model/Separations\n  set Values = %s\nend\n' "$2"; } > "$work/$1.prm"
  "$poundfe" sweep "$work/$1.prm" --output "$work/$1" > /dev/null
}
shear_sweep shear "0.004, 0.008"
[ "$(built_once "$work/shear/summary.json")" = True ] || { echo "FAIL: the shear pair's sweep read every value"; exit 1; }
shear_sweep one-0.004 0.004
shear_sweep one-0.008 0.008
[ "$(sed -n 2p "$work/shear/sweep.csv")" = "$(sed -n 2p "$work/one-0.004/sweep.csv")" ] &&
  [ "$(sed -n 3p "$work/shear/sweep.csv")" = "$(sed -n 2p "$work/one-0.008/sweep.csv")" ] ||
  { echo "FAIL: the values set in place differ from the models built with them"; exit 1; }
grep -q "n_impacts" "$work/shear/sweep.csv" || { echo "FAIL: no contact columns"; exit 1; }
echo "ok   shear pair built once: Separations = 0.004, 0.008 equal the models built with them, to the last digit"
