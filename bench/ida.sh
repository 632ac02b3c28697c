#!/usr/bin/env bash
# IDA throughput on 1 and 2 ranks (Release build, from the repository root):
#   bash bench/ida.sh [RECORDS] [RUNS_PER_RECORD]
# Generates RECORDS Kanai-Tajimi records of input/ida-pounding-pair.prm as an
# AT2 suite (ground-motion --write-at2), then runs `poundfe ida` on it on one
# rank and under mpirun -np 2 into fresh directories, and prints the runs per
# second of each (summary.json: runs_now / wall_time_s, the rounds alone).
set -eu
n=${1:-20}
runs=${2:-10}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 POUNDFE_PROGRESS=0
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
build/poundfe ground-motion input/ida-pounding-pair.prm --realizations "$n" --write-at2 \
  --output "$work/suite" --set Output/Plots=false > /dev/null
options=(--set "IDA/Suite=$work/suite/records/suite.csv" --set "IDA/Runs per record=$runs"
         --set Output/Plots=false)
rate() {
  python3 -c "import json, sys; s = json.load(open(sys.argv[1])); print(s['runs_now'], s['runs_now'] / s['wall_time_s'])" "$1"
}
build/poundfe ida input/ida-pounding-pair.prm --output "$work/one" "${options[@]}" > /dev/null
mpirun -np 2 build/poundfe ida input/ida-pounding-pair.prm --output "$work/two" "${options[@]}" > /dev/null
read -r runs1 r1 < <(rate "$work/one/summary.json")
read -r runs2 r2 < <(rate "$work/two/summary.json")
cmp -s "$work/one/ida.csv" "$work/two/ida.csv" || echo "warning: ida.csv differs between 1 and 2 ranks"
echo "1 rank: $runs1 runs, $r1 runs/s"
echo "2 ranks: $runs2 runs, $r2 runs/s"
awk -v a="$r1" -v b="$r2" 'BEGIN { printf "speed-up on 2 ranks: %.2f\n", b / a }'
