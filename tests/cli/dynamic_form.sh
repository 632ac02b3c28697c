#!/usr/bin/env bash
# Dynamic FORM (`poundfe dynamic-form`, theory §6.8) on a linear SDOF under
# held white noise (tests/cli/dynamic-form-sdof.prm):
#  - exact: the final drift ratio is linear in the 21 loading normals, so
#    FORM is exact; beta, Pf, alpha and u* against a second implementation
#    of the Newmark recurrence in dynamic_form_check.py (1e-6: finite
#    differences of a linear function and round-off only);
#  - approximate: with a lognormal storey stiffness (cov 0.15) too, FORM's
#    Pf against crude Monte Carlo (`montecarlo`, the same variables);
#  - SORM (Breitung, Tvedt) and importance sampling around u* on the same
#    linear limit state: SORM = FORM, IS = Phi(-beta) within its COV;
#  - bad input: more Excitation variables than the loading has: exit 1.
set -eu
poundfe=$1 input=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/helpers.sh"
check=$(dirname "$0")/dynamic_form_check.py

# (with SORM and 1000 importance samples after FORM)
sed 's|set Gradient step        = 0.01|set Gradient step        = 0.01\n    set SORM = true\n    set Importance samples = 1000|' \
  "$input" > "$work/exact.prm"
"$poundfe" dynamic-form "$work/exact.prm" --output "$work/exact" > "$work/exact.log"
result=$(python3 "$check" "$work/exact/summary.json" 0.02) ||
  fail "dynamic-form: not the exact answer of a linear limit state"
echo "ok   dynamic FORM exact on a linear SDOF: $result"
# SORM on the linear limit state: every curvature 0 (central second
# differences of a linear function: round-off / h^2 ~ 1e-12), so Breitung
# and Tvedt are Phi(-beta) (1e-6 relative); importance sampling around u*
# agrees with Phi(-beta) within 3 of its COVs (unbiased; sampling error only)
result=$(python3 - "$work/exact/summary.json" << 'PY'
import json, sys
s = json.load(open(sys.argv[1]))
pf, sorm, imp = s["failure_probability"], s["sorm"], s["importance_sampling"]
assert max(abs(k) for k in sorm["curvatures"]) < 1e-6, sorm["curvatures"]
for key in ("breitung", "tvedt"):
    assert abs(sorm[key] / pf - 1) < 1e-6, (key, sorm[key], pf)
assert imp["samples"] == 1000, imp
assert abs(imp["failure_probability"] - pf) <= 3 * imp["cov"] * imp["failure_probability"], (imp, pf)
print("Pf FORM %.6g, Breitung %.6g, Tvedt %.6g (largest |kappa| %.1e, %d time histories), "
      "IS %.4g (COV %.3f, %d samples)" % (pf, sorm["breitung"], sorm["tvedt"],
      max(abs(k) for k in sorm["curvatures"]), sorm["time_histories"],
      imp["failure_probability"], imp["cov"], imp["samples"]))
PY
) || fail "dynamic-form: SORM or importance sampling on the linear limit state"
echo "ok   dynamic SORM and importance sampling on the linear SDOF: $result"

# a random stiffness: FORM against Monte Carlo. (Tolerance 1e-2: HL-RF's
# distance from the line of alpha falls slowly in the stiffness direction;
# beta moves by 1e-5 between 1e-2 and 1e-3.)
sed -e 's|set Limit states = final: 0.02 - A_storey1_residual_drift_ratio|set Variables = k: Building 1/Storey stiffnesses[1] ~ lognormal mean 39478.417604357434 cov 0.15\n  set Limit states = final: 0.012 - A_storey1_residual_drift_ratio|' \
  -e 's|set Gradient step        = 0.01|set Gradient step        = 0.01\n    set Tolerance = 1e-2|' \
  "$input" > "$work/k.prm"
"$poundfe" dynamic-form "$work/k.prm" --output "$work/form-k" > /dev/null
"$poundfe" montecarlo "$work/k.prm" --output "$work/mc-k" > /dev/null
cat > "$work/compare.py" << 'PY'
import json, math, sys
form = json.load(open(sys.argv[1]))
mc = json.load(open(sys.argv[2]))["limit_states"]["system"]
p, n = mc["probability"], mc["realizations"]
sd = math.sqrt(p * (1 - p) / n)
assert form["converged"]
pf = form["failure_probability"]
# FORM's own error here (a mildly curved surface in the stiffness) is a few
# per cent of Pf; Monte Carlo's 3 standard errors (27 %) dominate
assert abs(pf - p) <= 3 * sd + 0.05 * p, (pf, p, sd)
print("FORM Pf %.4g (beta %.4f, %d time histories), Monte Carlo %.4g +- %.2g (%d realizations)"
      % (pf, form["beta"], form["time_histories"], p, sd, n))
PY
result=$(python3 "$work/compare.py" "$work/form-k/summary.json" "$work/mc-k/summary.json") ||
  fail "dynamic-form: FORM and Monte Carlo disagree"
echo "ok   dynamic FORM with a random stiffness against Monte Carlo: $result"

sed 's/set Excitation variables = all/set Excitation variables = 22/' "$input" > "$work/bad.prm"
set +e
"$poundfe" dynamic-form "$work/bad.prm" --output "$work/bad" > /dev/null 2> "$work/bad.err"
status=$?
set -e
[ $status -eq 1 ] && grep -q "Random parameters/FORM/Excitation variables" "$work/bad.err" &&
  [ ! -e "$work/bad" ] || fail "too many excitation variables: exit $status, $(cat "$work/bad.err")"
echo "ok   bad input: $(cat "$work/bad.err")"
