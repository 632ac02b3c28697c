#!/usr/bin/env bash
# bench/check-step-rate.sh and poundfe-bench --step-rate, untimed: against a
# stand-in benchmark and table the script prints each figure's change in per
# cent and exits 1 only when one fell by more than -t; the real benchmark
# prints one "step-rate MODEL CASE STEPS/S" line per case asked for and
# refuses a model the table does not have, a model with alternating runs
# against a baseline gets the ratio of those recorded figures (not of
# today's), and every model of bench/step-rate.txt names an input that
# exists and has 0 or 4 figures of alternating runs.
#   step_rate_check.sh POUNDFE_BENCH   (from the repository root)
set -u
bench=$1 root=$PWD
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL $*"; exit 1; }

mkdir -p "$work/bench"
cat > "$work/bench/step-rate.txt" <<'TABLE'
# recorded: abc1234, 2026-01-01, load average 0.1
# baseline: 0123abc, alternately
# model  input      off   csv  alt_off  alt_csv  base_off  base_csv
one      one.prm    1000  2000
two      two.prm    4000  1
three    three.prm  100   100  60       800      30        3200
TABLE
cat > "$work/fake-bench" <<'FAKE'
#!/usr/bin/env bash
echo "step-rate one off 900"
echo "step-rate one csv 2500"
echo "step-rate two off 4000"
echo "step-rate new off 10"
echo "step-rate three off 100"
echo "step-rate three csv 100"
FAKE
chmod +x "$work/fake-bench"
cd "$work"
out=$(bash "$root/bench/check-step-rate.sh" -r 1 -b "$work/fake-bench") || fail "exit status $? without -t"
echo "$out"
grep -q '^recorded: abc1234' <<< "$out" || fail "no recorded commit"
grep -Eq '^one +off +recorded +1000 +today +900 +-10.0 %$' <<< "$out" || fail "one off: not -10.0 %"
grep -Eq '^one +csv +recorded +2000 +today +2500 +\+25.0 %$' <<< "$out" || fail "one csv: not +25.0 %"
grep -Eq '^two +off +recorded +4000 +today +4000 +\+0.0 %$' <<< "$out" || fail "two off: not +0.0 %"
grep -Eq '^new +off +recorded +- +today +10$' <<< "$out" || fail "a model without a recorded figure"
grep -q '^baseline: 0123abc' <<< "$out" || fail "no baseline named"
grep -Eq '^three +off +recorded +100 +today +100 +\+0.0 % +recorded alternately: 2.00x baseline$' <<< "$out" ||
  fail "three off: not 2.00x (60 over 30 as recorded, not today's 100 over 30)"
grep -Eq '^three +csv +recorded +100 +today +100 +\+0.0 % +recorded alternately: 0.25x baseline$' <<< "$out" ||
  fail "three csv: not 0.25x (800 over 3200 as recorded, not today's 100 over 3200)"
grep -Eq '^(one|two) .*baseline' <<< "$out" && fail "a ratio for a model without alternating runs"
bash "$root/bench/check-step-rate.sh" -r 1 -b "$work/fake-bench" -t 20 > /dev/null ||
  fail "-t 20 fails on a 10 % fall"
bash "$root/bench/check-step-rate.sh" -r 1 -b "$work/fake-bench" -t 5 > /dev/null &&
  fail "-t 5 passes a 10 % fall"
cd "$root"

out=$("$bench" --step-rate 1 bouc-wen-sdof off) || fail "poundfe-bench --step-rate: exit status $?"
echo "$out"
grep -Eq '^step-rate bouc-wen-sdof off [1-9][0-9]*$' <<< "$out" && [ "$(wc -l <<< "$out")" -eq 1 ] ||
  fail "not one line for bouc-wen-sdof off"
"$bench" --step-rate 1 no-such-model > /dev/null 2>&1 && fail "--step-rate takes a model the table does not have"
grep -v '^#' bench/step-rate.txt | while read -r model input off csv alternating; do
  [ -z "$model" ] && continue
  [ -r "$input" ] || fail "$model: no $input"
  [ "${off:-0}" -gt 0 ] && [ "${csv:-0}" -gt 0 ] || fail "$model: no recorded figures"
  n_alternating=$(wc -w <<< "$alternating")
  [ "$n_alternating" -eq 0 ] || [ "$n_alternating" -eq 4 ] ||
    fail "$model: $n_alternating figures of alternating runs, not 0 or 4"
done || exit 1
echo "step-rate check: passed"
