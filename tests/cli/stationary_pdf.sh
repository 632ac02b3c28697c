#!/usr/bin/env bash
# stationary-pdf from the command line (issue 11):
#  - the linear oscillator under additive white noise against its exact
#    Gaussian stationary densities (stationary_pdf_check.py: variances and
#    histograms within 4 standard errors of N_eff = T / (2 tau_c) effectively
#    independent samples; one peak; the amplitude against the Rayleigh law);
#  - the frictionless SD oscillator (alpha = 0.4) against its exact
#    Fokker-Planck density: histograms of x and v bin by bin within 4
#    standard errors of the scatter of the realizations; two peaks at
#    +-sqrt(1 - alpha^2) within one bin; over alpha = 0.4, 0.5, 1.2, 1.5 (a
#    sweep) two peaks below alpha = 1 and one above, the change between 0.5
#    and 1.2 (exact: alpha = 1);
#  - mpirun -np 2 gives byte-identical pdf.csv, joint_pdf.csv and
#    realizations, and the summary of one rank;
#  - SIGINT stops a run after the realizations under way (exit status 130,
#    "interrupted"); the same command resumes to the uninterrupted bytes;
#  - bad input of the section: exit 1, one message, nothing written.
set -eu
poundfe=$1 mpirun=$2 input=$3 sd=$4
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
here=$(dirname "$0")
work=$(mktemp -d)
trap 'pkill -9 -f "$work" 2> /dev/null || true; rm -rf "$work"' EXIT
. "$here/helpers.sh"
set -m # background jobs receive SIGINT

"$poundfe" stationary-pdf "$input" --output "$work/one" > /dev/null
python3 "$here/stationary_pdf_check.py" "$work/one" linear 0.1 1 1
for f in pdf.png joint_pdf.png; do [ -s "$work/one/$f" ] || fail "no $f"; done
# a given Range: the grid is that range, and the estimates still match
sed 's/  set Bins                   = 40/  set Bins = 32\n  set Range = -1.6, 1.6, -2, 2/' "$input" > "$work/given-range.prm"
"$poundfe" stationary-pdf "$work/given-range.prm" --output "$work/given-range" > /dev/null
python3 "$here/stationary_pdf_check.py" "$work/given-range" linear 0.1 1 1 > /dev/null
# first bin centres: low + width/2 of x, v and a (a: 0 .. sqrt(1.6^2 + 2^2/omega^2), omega = 1)
sed -n 2p "$work/given-range/pdf.csv" | awk -F, '{
  x = -1.6 + 3.2 / 64; v = -2 + 4 / 64; a = sqrt(1.6^2 + 2^2) / 64
  exit !(($1 - x)^2 + ($4 - v)^2 + ($7 - a)^2 < 1e-24) }' ||
  fail "Range: first bin centres $(sed -n 2p "$work/given-range/pdf.csv" | cut -d, -f1,4,7)"
echo "ok   a given Range: the bins span it (x, v, and a to its corner), estimates match"
"$poundfe" stationary-pdf "$sd" --output "$work/sd" > /dev/null
python3 "$here/stationary_pdf_check.py" "$work/sd" sd 0.05 0.25 0.4
# Bandwidth rule = auto: Sheather-Jones for the bimodal x, Silverman for the
# one-peaked v; the densities still meet the exact one
sed 's/  set Bins                   = 40/  set Bins = 40\n  set Bandwidth rule = auto/' "$sd" > "$work/sd-auto.prm"
"$poundfe" stationary-pdf "$work/sd-auto.prm" --output "$work/sd-auto" > /dev/null
python3 "$here/stationary_pdf_check.py" "$work/sd-auto" sd 0.05 0.25 0.4 > /dev/null
python3 - "$work/sd-auto/summary.json" <<'PY' || fail "Bandwidth rule = auto: wrong rules"
import json, sys
s = json.load(open(sys.argv[1]))
assert s["x"]["bandwidth_rule"].startswith("Sheather-Jones"), s["x"]["bandwidth_rule"]
assert s["v"]["bandwidth_rule"].startswith("Silverman (one peak)"), s["v"]["bandwidth_rule"]
PY
echo "ok   Bandwidth rule = auto: Sheather-Jones on the two-peaked x, Silverman on v"
# P-bifurcation over alpha (the SD spring's H): 8 realizations per value
sed 's/  set Bins                   = 40/  set Bins = 40\n  set Parameter = Springs\/SD springs:6\n  set Values = 0.4, 0.5, 1.2, 1.5/
     s/set Number of realizations = 32/set Number of realizations = 8/' "$sd" > "$work/alpha.prm"
"$poundfe" stationary-pdf "$work/alpha.prm" --output "$work/alpha" > /dev/null
python3 "$here/stationary_pdf_check.py" "$work/alpha" p-bifurcation 0.4 0.5 1.2 1.5
for f in p_bifurcation.csv p_bifurcation_density.csv p_bifurcation.png; do
  [ -s "$work/alpha/$f" ] || fail "P-bifurcation: no $f"
done
[ "$(wc -l < "$work/alpha/p_bifurcation.csv")" -eq 5 ] || fail "P-bifurcation: not 4 rows"
"$mpirun" -np 2 "$poundfe" stationary-pdf "$work/alpha.prm" --output "$work/alpha-two" > /dev/null
for f in p_bifurcation.csv p_bifurcation_density.csv; do
  cmp -s "$work/alpha/$f" "$work/alpha-two/$f" || fail "P-bifurcation -np 2: $f differs from one rank"
done
echo "ok   P-bifurcation -np 2: p_bifurcation.csv and p_bifurcation_density.csv of one rank"

"$mpirun" -np 2 "$poundfe" stationary-pdf "$input" --output "$work/two" > /dev/null
for f in pdf.csv joint_pdf.csv; do
  cmp -s "$work/one/$f" "$work/two/$f" || fail "-np 2: $f differs from one rank"
done
diff <(rows "$work/one/realizations.csv") <(rows "$work/two/realizations.csv") > /dev/null ||
  fail "-np 2: the realizations differ from one rank"
same_summary "$work/one/summary.json" "$work/two/summary.json" "-np 2: summary differs from one rank"
echo "ok   stationary-pdf -np 2: pdf.csv, joint_pdf.csv, realizations and summary of one rank"

# 300 realizations of 20 + 500 s: SIGINT once 4 are in, then resume.
sed 's/set Number of realizations = 32/set Number of realizations = 300/
     s/set Duration          = 2020/set Duration          = 520/' "$input" > "$work/long.prm"
"$poundfe" stationary-pdf "$work/long.prm" --output "$work/reference" > /dev/null
d=$work/stopped status=0
"$poundfe" stationary-pdf "$work/long.prm" --output "$d" > "$d.log" 2>&1 &
job=$!
wait_for_rows "$d/realizations.csv" 4
kill -INT "$job"
wait "$job" 2> /dev/null || status=$?
[ "$status" -eq 130 ] || fail "SIGINT: exit status $status: $(cat "$d.log")"
grep -q '"status": "interrupted"' "$d/summary.json" || fail "SIGINT: not interrupted (too late?)"
[ -z "$(find "$d" -name '*.tmp')" ] || fail "SIGINT: temporary files left"
n=$(($(wc -l < "$d/realizations.csv") - 1))
"$mpirun" -np 2 "$poundfe" stationary-pdf "$work/long.prm" --output "$d" > "$d.resumed.log"
grep -q "resuming: $n of 300" "$d.resumed.log" || fail "did not resume from $n: $(cat "$d.resumed.log")"
for f in pdf.csv joint_pdf.csv; do
  cmp -s "$work/reference/$f" "$d/$f" || fail "resumed: $f differs from an uninterrupted run"
done
same_summary "$work/reference/summary.json" "$d/summary.json" "resumed: summary differs"
echo "ok   stationary-pdf, SIGINT after $n of 300 (exit status 130), resumed on 2 ranks to the uninterrupted bytes"

expect_bad() { # expected-text file
  rm -rf "$work/bad"
  if "$poundfe" stationary-pdf "$2" --output "$work/bad" > /dev/null 2> "$work/stderr"; then fail "$2 succeeded"; fi
  grep -qF -- "$1" "$work/stderr" || fail "$2: message lacks '$1': $(cat "$work/stderr")"
  grep -qF -- "$(basename "$2")" "$work/stderr" || fail "$2: message lacks the file: $(cat "$work/stderr")"
  [ "$(wc -l < "$work/stderr")" -eq 1 ] || fail "$2: not one line: $(cat "$work/stderr")"
  [ -e "$work/bad" ] && fail "$2: output written despite bad input"
  echo "ok   bad input: $(cat "$work/stderr")"
}
bad() { # name sed-script: a copy of the input
  sed "$2" "$input" > "$work/$1.prm"
  echo "$work/$1.prm"
}
expect_bad "building must be 1..1" "$(bad building 's/set Response               = 1 1 0/set Response = 2 1 0/')"
expect_bad "expected 'building floor node'" "$(bad extra 's/set Response               = 1 1 0/set Response = 1 1 0 rz/')"
expect_bad "before the burn-in ends" "$(bad burn-in 's/set Burn-in time           = 20/set Burn-in time = 3000/')"
expect_bad "the runs last 3020 s but the noise ends at 2020 s" \
  "$(bad sampling 's/set Burn-in time           = 20/set Burn-in time = 20\n  set Sampling time = 3000/')"
expect_bad "needs 4 values" "$(bad range 's/set Bins                   = 40/set Range = -1, 1, 2/')"
expect_bad "must be a whole number of time steps" \
  "$(bad interval 's/set Sample interval        = 0.1/set Sample interval = 0.07/')"
expect_bad "needs random loading" "$(bad none 's/set Type = white-noise/set Type = none/')"
expect_bad "a P-bifurcation needs at least 2 values" \
  "$(bad one-value 's/set Bins                   = 40/set Parameter = Ground motion\/Stochastic\/D\n  set Values = 0.1/')"
expect_bad "must be at most 1e15 time steps" \
  "$(bad huge-interval 's/set Sample interval        = 0.1/set Sample interval = 1e200/')"
# an interval longer than the sampled time (20 s after 10 s sampled) is
# workable: one sample per realization, at the end of the burn-in
"$poundfe" stationary-pdf "$input" --output "$work/long-interval" --set Output/Plots=false \
  --set "Stationary PDF/Sampling time=10" --set "Stationary PDF/Sample interval=20" \
  --set "Stationary PDF/Number of realizations=3" > /dev/null 2> "$work/stderr" ||
  fail "Sample interval longer than the sampled time refused: $(cat "$work/stderr")"
python3 - "$work/long-interval/summary.json" <<'PY' || fail "long interval: not one sample per realization"
import json, sys
s = json.load(open(sys.argv[1]))
assert s["samples"] == 3 and s["sample_interval_s"] == 20, (s["samples"], s["sample_interval_s"])
PY
echo "ok   a Sample interval longer than the sampled time: one sample per realization"
