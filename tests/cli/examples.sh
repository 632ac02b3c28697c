#!/usr/bin/env bash
# Every example in input/ runs to completion (modal and run) and writes its
# outputs; the summary's status is 'completed'.
set -eu
poundfe=$1 input=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for file in "$input"/*.prm; do
  name=$(basename "$file" .prm)
  # 116k equations, minutes per run: too long for CI. Its small variant,
  # tests/cli/city-block-small.prm, runs in cli/distributed-run.
  [ "$name" = city-block ] && continue
  "$poundfe" modal "$file" --output "$work/$name/modal" > /dev/null
  "$poundfe" run "$file" --output "$work/$name" > /dev/null
  for f in summary.json drift.csv floor_acceleration.csv floor_displacement.csv; do
    [ -s "$work/$name/$f" ] || { echo "FAIL $name: no $f"; exit 1; }
  done
  grep -q '"status": "completed"' "$work/$name/summary.json" || { echo "FAIL $name: not completed"; exit 1; }
  [ -s "$work/$name/energy.csv" ] || { echo "FAIL $name: no energy.csv"; exit 1; }
  # the energy balance closes to 1 % on every example
  error=$(sed -n 's/.*"max_relative_balance_error": \([^,}]*\).*/\1/p' "$work/$name/summary.json")
  awk -v e="$error" 'BEGIN { exit !(e != "" && e < 0.01) }' || { echo "FAIL $name: energy balance error $error"; exit 1; }
  if grep -q '"hinges"' "$work/$name/summary.json"; then
    [ -s "$work/$name/hinges.csv" ] || { echo "FAIL $name: no hinges.csv"; exit 1; }
  fi
  if ls "$work/$name" | grep -q '\.tmp$'; then echo "FAIL $name: temporary files left"; exit 1; fi
  echo "ok   $name (energy balance error $error)"
done
