#!/usr/bin/env bash
# The thesis's shear building with truncated-normal random storey yield
# strengths (input/thesis-shear-building-subset.prm; thesis sec. 2.3,
# Table 2.5): Subset Simulation of P(peak drift ratio > b) at the thesis's
# (p0, N) = (0.10, 950), (0.15, 925), (0.20, 900), (0.35, 825) against
# crude Monte Carlo of the same input (3000 realizations, the independent
# reference). Each Subset estimate must lie within 3 combined standard
# errors of the Monte Carlo one: sqrt((CoV_ss P_ss)^2 + (CoV_mc P_mc)^2),
# the CoVs the commands report (for Subset the upper bound, its levels fully
# correlated: the lower bound, levels uncorrelated, understates the scatter;
# the binomial one for Monte Carlo).
# The limit-state form (Random parameters/Limit states: 0.005 -
# max_drift_ratio) gives the Monte Carlo count of the drift limit.
set -eu
poundfe=$1 input=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL $*"; exit 1; }

"$poundfe" montecarlo "$input" --output "$work/mc" > "$work/mc.log"
for pair in 0.10:950 0.15:925 0.20:900 0.35:825; do
  p0=${pair%:*} n=${pair#*:}
  sed -e "s/set Conditional probability = 0.1$/set Conditional probability = $p0/" \
      -e "s/set Samples per level       = 950/set Samples per level       = $n/" "$input" > "$work/ss-$p0.prm"
  "$poundfe" subset "$work/ss-$p0.prm" --output "$work/ss-$p0" > "$work/ss-$p0.log"
done
python3 - "$work" << 'PY' || fail "Subset Simulation and Monte Carlo disagree"
import json, sys
w = sys.argv[1]
mc = json.load(open(w + "/mc/summary.json"))
limit = mc["probabilities"]["drift_limit_exceedance"][0]
state = mc["limit_states"]["limit_states"][0]
assert limit["failures"] == state["failures"], (limit, state)
p_mc, cov_mc = limit["probability"], limit["coefficient_of_variation"]
print(f"     crude Monte Carlo: P = {p_mc:.4g} (CoV {cov_mc:.3f}, {limit['realizations']} realizations)")
ok = True
for p0 in ("0.10", "0.15", "0.20", "0.35"):
    s = json.load(open(f"{w}/ss-{p0}/summary.json"))
    p, cov = s["failure_probability"], s["coefficient_of_variation_upper_bound"]
    assert s["coefficient_of_variation"] <= cov, s
    assert s["conditional_probability"] == float(p0) and s["random_model_parameters"] == 3
    sigma = ((cov * p) ** 2 + (cov_mc * p_mc) ** 2) ** 0.5
    z = (p - p_mc) / sigma
    print(f"     p0 = {p0}, N = {s['samples_per_level']}: P = {p:.4g} (CoV {s['coefficient_of_variation']:.3f} to {cov:.3f}), "
          f"{s['model_runs']} runs, {len(s['levels'])} levels, z = {z:+.2f}")
    ok = ok and abs(z) < 3
sys.exit(0 if ok else 1)
PY
echo "ok   thesis shear building: Subset Simulation at p0 = 0.10/0.15/0.20/0.35 agrees with crude Monte Carlo"
