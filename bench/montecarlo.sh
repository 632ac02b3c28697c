#!/usr/bin/env bash
# Monte Carlo throughput on 1 and 2 ranks (Release build, from the repository
# root): bash bench/montecarlo.sh [FILE] [N]
set -eu
file=${1:-input/montecarlo-pounding.prm}
n=${2:-40}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
one=$(build/poundfe-bench --montecarlo "$file" "$n" | grep '^montecarlo')
two=$(mpirun -np 2 build/poundfe-bench --montecarlo "$file" "$n" | grep '^montecarlo')
echo "$one"
echo "$two"
r1=$(echo "$one" | sed 's/.*: \([0-9.]*\) realizations\/s/\1/')
r2=$(echo "$two" | sed 's/.*: \([0-9.]*\) realizations\/s/\1/')
awk -v a="$r1" -v b="$r2" 'BEGIN { printf "speed-up on 2 ranks: %.2f\n", b / a }'
