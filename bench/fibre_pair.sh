#!/usr/bin/env bash
# The fibre pair benchmark (Release build, from the repository root): two
# 10-storey, 3-bay RC frames of force-based fibre members pounding at every
# floor, 20 s at 5e-3 s (4000 steps), every output but VTU
# (bench/fibre-pair.prm), against the same model written by hand for OpenSees
# 3.8 (bench/opensees/fibre_pair/pair.tcl). Each round runs, one after the
# other: `poundfe run fibre-pair.prm`, `poundfe opensees pair.tcl` and
# `OpenSees pair.tcl` (the record: the generated one of the first poundfe
# run, its ground_motion.csv, as a one-column file), and prints the load
# average before it and, per program, the wall time, the CPU time (user +
# system) and the steps per second of each. At the end: the median steps per
# second of each program over the rounds, poundfe's against OpenSees's, and
# the two comparisons of bench/opensees/fibre_pair/compare_pair.py on the
# last round's files (the same script in both programs: within 1e-6 of the
# peaks; poundfe run against OpenSees: the peaks per storey and gap).
#   bash bench/fibre_pair.sh [BUILD_DIR [ROUNDS]]
# OPENSEES names the OpenSees 3.8 binary (default: OpenSees on the PATH);
# POUNDFE_THREADS, if set, is passed as --threads to poundfe run and to
# poundfe opensees. About 4
# minutes a round on one free core.
set -euo pipefail
build=${1:-build}
rounds=${2:-3}
opensees=${OPENSEES:-OpenSees}
here=$(cd "$(dirname "$0")" && pwd)
python=${POUNDFE_PYTHON:-/usr/bin/python3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
steps=4000
threads=()
if [ -n "${POUNDFE_THREADS:-}" ]; then threads=(--threads "$POUNDFE_THREADS"); fi

# time_it NAME COMMAND...: run it, append "NAME wall cpu" to $work/times
time_it() {
  local name=$1
  shift
  local start end
  start=$(date +%s.%N)
  /usr/bin/time -f "%U %S" -o "$work/cpu" "$@" > "$work/$name.log" 2>&1 ||
    { echo "$name failed:"; tail -5 "$work/$name.log"; exit 1; }
  end=$(date +%s.%N)
  read -r user system < <(tail -1 "$work/cpu")
  "$python" - "$name" "$start" "$end" "$user" "$system" "$steps" >> "$work/times" <<'PY'
import sys
name, start, end, user, system, steps = sys.argv[1:]
wall, cpu = float(end) - float(start), float(user) + float(system)
print(f"{name} {wall:.2f} {cpu:.2f} {int(steps) / wall:.1f} {int(steps) / cpu:.1f}")
PY
  tail -1 "$work/times" | awk '{printf "  %-17s %8.1f s wall %8.1f s CPU %8.1f steps/s (wall) %8.1f steps/s (CPU)\n", $1, $2, $3, $4, $5}'
}

for round in $(seq 1 "$rounds"); do
  echo "round $round: load average $(cut -d' ' -f1-3 /proc/loadavg)"
  rm -rf "$work/run" "$work/poundfe-opensees" "$work/opensees"
  mkdir -p "$work/poundfe-opensees" "$work/opensees"
  time_it poundfe-run "$build/poundfe" run "$here/fibre-pair.prm" --output "$work/run" "${threads[@]}"
  tail -n +2 "$work/run/ground_motion.csv" | cut -d, -f2 > "$work/record.txt"
  time_it poundfe-opensees "$build/poundfe" opensees "${threads[@]}" "$here/opensees/fibre_pair/pair.tcl" \
    "$work/poundfe-opensees" "$work/record.txt"
  time_it OpenSees "$opensees" "$here/opensees/fibre_pair/pair.tcl" "$work/opensees" "$work/record.txt"
done
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
"$python" - "$work/times" <<'PY'
import statistics, sys
rows = [line.split() for line in open(sys.argv[1])]
wall = {n: statistics.median(float(r[3]) for r in rows if r[0] == n) for n in dict.fromkeys(r[0] for r in rows)}
cpu = {n: statistics.median(float(r[4]) for r in rows if r[0] == n) for n in wall}
for n in wall:
    print(f"median {n:17s} {wall[n]:8.1f} steps/s (wall) {cpu[n]:8.1f} steps/s (CPU)")
for n in ("poundfe-run", "poundfe-opensees"):
    print(f"{n} / OpenSees: {wall[n] / wall['OpenSees']:.2f} (wall), "
          f"{cpu[n] / cpu['OpenSees']:.2f} (CPU)")
PY
echo "the same script, OpenSees against poundfe opensees:"
"$python" "$here/opensees/fibre_pair/compare_pair.py" scripts "$work/opensees" "$work/poundfe-opensees"
echo "poundfe run against OpenSees, peaks:"
"$python" "$here/opensees/fibre_pair/compare_pair.py" run "$work/run" "$work/opensees" | grep -v '^  '
