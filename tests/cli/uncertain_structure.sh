#!/usr/bin/env bash
# Random model parameters (Random parameters section, issue 24) in the
# time-history sampling commands:
#  - montecarlo on one rank and on two (mpirun -np 2) gives the same
#    realizations (loading and sampled parameters) and summary; the limit
#    states' probabilities equal the counts of their failures in
#    realizations.csv;
#  - subset with Response = limit state: one rank equals two;
#  - bad input (unknown path, a path that is not a number poundfe can vary,
#    geometry, a restitution without restitution damping, no foundation,
#    no bumper, a Links list without its field, no SD spring,
#    a distribution that samples impossible values, impossible distribution
#    parameters, a limit state naming an unknown response, a sample beyond
#    1e150 refused when its realization is built): exit 1, one
#    message naming Random parameters/..., nothing written.
set -eu
poundfe=$1 mpirun=$2 input=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/helpers.sh"

sed 's/set Realizations = 40/set Realizations = 12/' "$input" > "$work/mc.prm"
"$poundfe" montecarlo "$work/mc.prm" --output "$work/one" > "$work/one.log"
"$mpirun" -np 2 "$poundfe" montecarlo "$work/mc.prm" --output "$work/two" > /dev/null
n=$(rows "$work/one/realizations.csv" | wc -l)
[ "$n" -eq 12 ] || fail "montecarlo: $n realizations instead of 12"
head -1 "$work/one/realizations.csv" | grep -q ',k1,zeta,uy2,gap,kc$' ||
  fail "montecarlo: realizations.csv has no columns of the random parameters"
diff <(rows "$work/one/realizations.csv") <(rows "$work/two/realizations.csv") > /dev/null ||
  fail "montecarlo: the realizations differ between 1 and 2 ranks"
same_summary "$work/one/summary.json" "$work/two/summary.json" "montecarlo: summary differs between 1 and 2 ranks"
# the limit states' failures counted again from realizations.csv
python3 - "$work/one" << 'PY' || fail "montecarlo: limit-state probabilities differ from realizations.csv"
import csv, json, sys
d = sys.argv[1]
rows = list(csv.DictReader(open(d + "/realizations.csv")))
s = json.load(open(d + "/summary.json"))["limit_states"]
drift = sum(0.002 - float(r["max_drift_ratio"]) <= 0 for r in rows)
contact = sum(6e4 - float(r["peak_contact_force"]) <= 0 for r in rows)
either = sum(0.002 - float(r["max_drift_ratio"]) <= 0 or 6e4 - float(r["peak_contact_force"]) <= 0 for r in rows)
got = [x["failures"] for x in s["limit_states"]] + [s["system"]["failures"]]
assert got == [drift, contact, either], (got, [drift, contact, either])
PY
grep -q '^P(drift <= 0) = ' "$work/one.log" || fail "montecarlo: no limit-state line"
echo "ok   montecarlo with random parameters: -np 2 equals one rank; limit states counted"

cat "$input" - > "$work/ss.prm" << 'PRM'
subsection Subset simulation
  set Response                = limit state
  set Samples per level       = 20
  set Conditional probability = 0.25
  set Maximum levels          = 2
end
PRM
"$poundfe" subset "$work/ss.prm" --output "$work/ss1" > /dev/null
"$mpirun" -np 2 "$poundfe" subset "$work/ss.prm" --output "$work/ss2" > /dev/null
same_summary "$work/ss1/summary.json" "$work/ss2/summary.json" "subset (limit state): 2 ranks differ from 1"
grep -q '"random_model_parameters": 5' "$work/ss1/summary.json" || fail "subset: random parameters not counted"
echo "ok   subset on a limit state with random parameters: -np 2 equals one rank"

bad() { # name, replacement of the Variables line, expected words
  local name=$1 variables=$2 expected=$3
  awk -v v="$variables" '/set Variables =/ { print "  set Variables = " v; skip = 1; next }
       skip && /\\$/ { next } skip { skip = 0; next } { print }' "$input" |
    sed '/set Correlation =/d' > "$work/$name.prm"
  set +e
  "$poundfe" montecarlo "$work/$name.prm" --output "$work/$name" > "$work/$name.out" 2> "$work/$name.err"
  local status=$?
  set -e
  [ $status -eq 1 ] || fail "$name: exit $status instead of 1"
  [ "$(wc -l < "$work/$name.err")" -eq 1 ] || fail "$name: not one message: $(cat "$work/$name.err")"
  grep -q "Random parameters/" "$work/$name.err" || fail "$name: message names no entry"
  grep -q "$expected" "$work/$name.err" || fail "$name: message lacks '$expected': $(cat "$work/$name.err")"
  [ ! -e "$work/$name" ] || fail "$name: wrote $work/$name"
  echo "ok   bad input $name: $(cat "$work/$name.err")"
}
bad unknown-path 'k: Building 1/Storey stifness[1] ~ lognormal mean 5e6 cov 0.2' "is not a parameter"
bad not-numeric 'k: Building 1/Name ~ lognormal mean 5e6 cov 0.2' "is not a parameter"
bad storey-out-of-range 'k: Building 2/Storey stiffnesses[3] ~ lognormal mean 5e6 cov 0.2' "storeys 1..2"
bad normal-stiffness 'k: Building 1/Storey stiffnesses[1] ~ normal mean 5e6 sd 1e6' "can sample values <= 0"
bad negative-sd 'k: Building 1/Storey stiffnesses[1] ~ lognormal mean 5e6 sd -1' "variable 'k'"
bad no-tilde 'k: Building 1/Storey stiffnesses[1] lognormal mean 5e6 sd 1' "NAME: PATH ~ DISTRIBUTION"
bad geometry 'h: Building 1/Storey heights[1] ~ lognormal mean 3 cov 0.1' "geometry"
bad restitution-undamped 'e: Contact/Coefficient of restitution ~ uniform lower 0.5 upper 0.8' "does not come from the restitution"
bad no-foundation 'v: Building 2/Foundation/Shear-wave velocity ~ lognormal mean 200 cov 0.2' "no compliant foundation"
bad no-bumper 't: Bumpers/Thickness ~ uniform lower 0.001 upper 0.002' "no bumper"
bad link-without-field 'k: Links/Maxwell links ~ lognormal mean 1e6 cov 0.2' "FIELD one of k, c"
bad no-sd-spring 'K: Springs/SD springs/K ~ lognormal mean 1e6 cov 0.2' "no entries of 'Springs/SD springs'"
# refused only when a realization applies its sample, after the command has
# begun writing: its files are removed again (bad input writes nothing)
bad huge-sample 'k: Building 1/Storey stiffnesses[1] ~ uniform lower 1e299 upper 1e300; gap: Model/Separations[1] ~ lognormal mean 0.01 cov 0.5' "1e150"
# A sample refused only when its realization is built, after the command has
# begun writing (mu_k > mu_s drawn from two uniforms): exit 1, one message,
# and the files it wrote (realizations.csv and its record) removed again.
awk -v v="mus: Friction/Static coefficient ~ uniform lower 0.2 upper 0.4; muk: Friction/Kinetic coefficient ~ uniform lower 0.2 upper 0.4; gap: Model/Separations[1] ~ lognormal mean 0.01 cov 0.5" \
  '/set Variables =/ { print "  set Variables = " v; skip = 1; next }
   skip && /\\$/ { next } skip { skip = 0; next } { print }' "$input" | sed '/set Correlation =/d' > "$work/late.prm"
printf 'subsection Friction\n  set Surfaces = 2 1 0\n  set Static coefficient = 0.35\n  set Kinetic coefficient = 0.25\n  set Normal force = 1e4\nend\n' >> "$work/late.prm"
set +e
"$poundfe" montecarlo "$work/late.prm" --output "$work/late" > /dev/null 2> "$work/late.err"
status=$?
set -e
[ $status -eq 1 ] && [ "$(wc -l < "$work/late.err")" -eq 1 ] && grep -q "mu_k = .* > mu_s" "$work/late.err" ||
  fail "late refusal: exit $status, $(cat "$work/late.err")"
[ ! -e "$work/late" ] || fail "late refusal: left $(ls -A "$work/late")"
echo "ok   a sample refused mid-run: exit 1, $(cat "$work/late.err"), its files removed"
sed 's/contact: 6e4 - peak_contact_force - 0\*gap/contact: 6e4 - peak_force/' "$input" > "$work/unknown-response.prm"
set +e
"$poundfe" montecarlo "$work/unknown-response.prm" --output "$work/unknown-response" > /dev/null 2> "$work/unknown-response.err"
status=$?
set -e
[ $status -eq 1 ] && grep -q "Random parameters/Limit states" "$work/unknown-response.err" &&
  grep -q "peak_force" "$work/unknown-response.err" && [ ! -e "$work/unknown-response" ] ||
  fail "unknown response: exit $status, $(cat "$work/unknown-response.err")"
echo "ok   bad input unknown-response: $(cat "$work/unknown-response.err")"

# fragility with modelling uncertainty: the split of each curve's dispersion.
# A random separation of buildings that never reach each other (1 m) changes
# no response: the run with it and the nominal model's run (the same loading
# normals) give the same curves, so beta_total = beta_record_to_record
# exactly and beta_modelling = 0.
frag() { # name, Variables line
  awk -v v="$2" '/set Variables =/ { print "  set Variables = " v; skip = 1; next }
       skip && /\\$/ { next } skip { skip = 0; next } { print }' "$input" |
    sed -e '/set Correlation =/d' -e '/set Limit states =/,/peak_contact_force/d' \
        -e 's/set Separations         = 0.01/set Separations         = 1/' \
        -e 's/set Realizations = 40/set Drift limits = 0.0015/' > "$work/$1.prm"
  cat >> "$work/$1.prm" << 'PRM'
subsection Fragility
  set PGA levels             = 0.25, 0.35, 0.45, 0.55
  set Realizations per level = 10
end
PRM
  "$poundfe" fragility "$work/$1.prm" --output "$work/$1" > "$work/$1.log"
}
frag null-parameter 'sep: Model/Separations[1] ~ lognormal mean 1 cov 0.1'
python3 - "$work/null-parameter/summary.json" << 'PY' || fail "fragility: a parameter that changes nothing has a modelling dispersion"
import json, sys
d = json.load(open(sys.argv[1]))["dispersion"]
drift = [x for x in d if x["name"].startswith("drift")][0]
assert drift["beta_total"] == drift["beta_record_to_record"] and drift["beta_modelling"] == 0, drift
PY
[ -s "$work/null-parameter/record-to-record/pga_0.45g/realizations.csv" ] || fail "fragility: no record-to-record realizations"
frag stiffness 'k1: Building 1/Storey stiffnesses ~ lognormal mean 4e6 cov 0.3; zeta: Building 1/Damping/Damping ratio ~ uniform lower 0.01 upper 0.05'
grep -q "record-to-record +" "$work/stiffness.log" || fail "fragility: no dispersion split printed"
echo "ok   fragility with random parameters: the dispersion split (a null parameter gives beta_modelling = 0): $(grep 'record-to-record +' "$work/stiffness.log" | head -1)"
