#!/usr/bin/env bash
# Engine regression: every example in input/ (modal and run) and the probabilistic
# commands on a small input (montecarlo, subset, fragility) give the numbers
# of the committed reference digests to 1e-8 of each column's largest value
# (digest.py says how they are taken and compared, and why not round-off).
#   run.sh POUNDFE INPUT_DIR SMALL_PRM REFERENCE_DIR [--update]
set -eu
poundfe=$1 input=$2 small=$3 reference=$4 update=${5:-}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
check() { # name directory
  python3 "$here/digest.py" "$2" > "$work/$1.digest"
  if [ "$update" = --update ]; then
    cp "$work/$1.digest" "$reference/$1.digest"
  else
    python3 "$here/digest.py" --compare "$reference/$1.digest" "$work/$1.digest" || status=1
  fi
}
fail() { echo "FAIL $*"; status=1; }
# What every example's run must write besides its numbers: the outputs, the
# status 'completed', an energy balance closed to 1 %, no temporary files.
check_outputs() { # name directory
  local name=$1 out=$2 f error
  for f in summary.json drift.csv floor_acceleration.csv floor_displacement.csv energy.csv; do
    [ -s "$out/$f" ] || { fail "$name: no $f"; return; }
  done
  grep -q '"status": "completed"' "$out/summary.json" || { fail "$name: not completed"; return; }
  error=$(sed -n 's/.*"max_relative_balance_error": \([^,}]*\).*/\1/p' "$out/summary.json")
  awk -v e="$error" 'BEGIN { exit !(e != "" && e < 0.01) }' || { fail "$name: energy balance error $error"; return; }
  if grep -q '"hinges"' "$out/summary.json"; then
    [ -s "$out/hinges.csv" ] || fail "$name: no hinges.csv"
  fi
  if ls "$out" | grep -q '\.tmp$'; then fail "$name: temporary files left"; fi
}
for file in "$input"/*.prm; do
  name=$(basename "$file" .prm)
  # 116k equations, minutes per run: too long for CI. Its small variant,
  # tests/cli/city-block-small.prm, runs in cli/distributed-run.
  [ "$name" = city-block ] && continue
  # every example runs to completion in modal and in run (formerly cli/examples)
  "$poundfe" modal "$file" --output "$work/$name-modal" > /dev/null 2>&1 || fail "$name: modal failed"
  "$poundfe" run "$file" --output "$work/$name" > /dev/null 2>&1 || fail "$name: run failed"
  check_outputs "$name" "$work/$name"
  check "$name" "$work/$name"
done
for command in montecarlo subset fragility; do
  "$poundfe" $command "$small" --output "$work/$command" > /dev/null 2>&1 || true
  check "$command" "$work/$command"
done
exit $status
