#!/usr/bin/env bash
# Elements replaced under a kept integrator: montecarlo with random yield
# drifts builds every realization's nonlinear elements afresh
# (TimeHistory::replace_nonlinear_elements) while the integrator and its
# factorisations are kept. Each realization (the first and those after a
# replacement) against `poundfe run` of the file with the realization's
# motion and sampled yield drifts written in: the storeys' peak drifts, the
# largest drift, impacts and peak contact force to 1e-9 relative (the same
# engine and operations; CSV keeps 17 digits).
set -eu
poundfe=$1 input=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/helpers.sh" # fail

"$poundfe" montecarlo "$input" --output "$work/mc" > /dev/null 2> "$work/mc.err" ||
  fail "montecarlo exited $?: $(head -c 300 "$work/mc.err")"
for k in 0 1 2; do
  read -r y1 y2 <<< "$(python3 - "$work/mc/realizations.csv" "$k" <<'PY'
import csv, sys
rows = [r for r in csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#"))
        if r["realization"] == sys.argv[2]]
assert len(rows) == 1, rows
print(rows[0]["y1"], rows[0]["y2"])
PY
)"
  "$poundfe" run "$input" --set "Ground motion/Stochastic/Realization=$k" \
    --set "Building 1/Storey yield drifts=$y1" --set "Building 2/Storey yield drifts=$y2" \
    --output "$work/run$k" > /dev/null 2> "$work/run.err" ||
    fail "run of realization $k exited $?: $(head -c 300 "$work/run.err")"
  python3 - "$work/mc/realizations.csv" "$k" "$work/run$k/summary.json" <<'PY' ||
import csv, json, sys
path, k, summary = sys.argv[1:]
row = [r for r in csv.DictReader(l for l in open(path) if not l.startswith("#"))
       if r["realization"] == k][0]
s = json.load(open(summary))
drifts = {f"{b['name']}_storey{i + 1}_peak_drift_ratio": st["peak_drift_ratio"]
          for b in s["buildings"] for i, st in enumerate(b["storeys"])}
pairs = [(float(row[name]), value) for name, value in drifts.items()]
pairs.append((float(row["max_drift_ratio"]), max(drifts.values())))
pairs.append((float(row["n_impacts"]), sum(g["impacts"] for g in s["gaps"])))
assert pairs[-1][1] > 0, "no impacts: the contact is not exercised"
for mc, run in pairs:
    assert abs(mc - run) <= 1e-9 * max(abs(mc), abs(run), 1e-300), (k, mc, run)
PY
    fail "realization $k differs from run's at y1 = $y1, y2 = $y2"
  echo "ok   montecarlo realization $k (y1 = $y1, y2 = $y2) = run's"
done
