#!/usr/bin/env bash
# The outputs' writer thread (output/output_queue.h): a pounding pair whose
# run fails half-way (one Newton iteration, no step cuts: the step at
# 2.1795 s fails, exit 2), every table at every step, in CSV and in .npy,
# with --threads 1 (formatted and written inline) and --threads 2 (CSV on
# the writer thread; .npy stays inline): the same files byte for byte (summary.json but for its
# wall time and steps/s), and both keep the rows up to the failure. The
# same for `poundfe opensees` on OpenSees scripts with Node, Element,
# Drift and Envelope recorders (-precision 16, -dT, -time).
set -eu
poundfe=$1 input=$2
shift 2 # the Tcl scripts, each taking its output directory as argv
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
for format in csv npy; do
  for threads in 1 2; do
    status=0
    "$poundfe" run "$input" --threads $threads --output "$work/$format-$threads" \
      --set "Output/Output interval=5e-4" --set "Output/Plots=false" --set "Output/Format=$format" \
      --set "Time integration/Newton maximum iterations=1" \
      --set "Time integration/Maximum step cuts=0" > "$work/log" 2>&1 || status=$?
    [ $status -eq 2 ] || { echo "FAIL $format, --threads $threads: exit $status, not 2"; cat "$work/log"; failures=$((failures + 1)); }
  done
  a=$work/$format-1 b=$work/$format-2
  [ "$(ls "$a")" = "$(ls "$b")" ] || { echo "FAIL $format: files differ: $(ls "$a") / $(ls "$b")"; failures=$((failures + 1)); }
  n=0
  for f in "$a"/*; do
    name=$(basename "$f")
    if [ "$name" = summary.json ]; then
      diff <(grep -v '"wall_time_s"\|"steps_per_second"' "$f") \
           <(grep -v '"wall_time_s"\|"steps_per_second"' "$b/$name") > /dev/null ||
        { echo "FAIL $format: summary.json differs"; failures=$((failures + 1)); }
    else
      cmp -s "$f" "$b/$name" || { echo "FAIL $format: $name differs"; failures=$((failures + 1)); }
      n=$((n + 1))
    fi
  done
  echo "$format: $n files the same"
done
# the rows up to the failure: 2.179 s at 5e-4 s, the header and step 0
rows=$(wc -l < "$work/csv-2/drift.csv")
[ "$rows" -eq 4360 ] || { echo "FAIL drift.csv has $rows lines, not 4360"; failures=$((failures + 1)); }
grep -q '"status": "failed"' "$work/csv-2/summary.json" || { echo "FAIL status"; failures=$((failures + 1)); }
for script in "$@"; do
  name=$(basename "$script" .tcl)
  for threads in 1 2; do
    mkdir -p "$work/$name-$threads"
    "$poundfe" opensees --threads $threads "$script" "$work/$name-$threads" > /dev/null 2>&1 ||
      { echo "FAIL $name, --threads $threads: exit $?"; failures=$((failures + 1)); }
  done
  n=0
  for f in "$work/$name-1"/*; do
    cmp -s "$f" "$work/$name-2/$(basename "$f")" ||
      { echo "FAIL $name: $(basename "$f") differs"; failures=$((failures + 1)); }
    n=$((n + 1))
  done
  [ $n -gt 0 ] || { echo "FAIL $name: no recorder file"; failures=$((failures + 1)); }
  echo "$name: $n files the same"
done
[ $failures -eq 0 ] && echo "writer thread: PASS" || { echo "writer thread: $failures failures"; exit 1; }
