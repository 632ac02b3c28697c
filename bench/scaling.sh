#!/usr/bin/env bash
# Time and memory per step against the model size and the ranks (issue 23
# item 6; doc/benchmarks.md, "Time and memory against size and ranks"):
# rows of city-block frames (scripts/city_block.py: 40-storey 10-bay frames
# with hinges and Hertz-damp gaps) of 3, 6, 12 and 24 buildings on 1 and 2
# ranks, and 100 buildings of 80 storeys (1.94 million equations, about
# 5 GiB) on one, each set up and run for 10 steps of 5 ms by
# poundfe-bench --distributed (petsc-mumps). Release build, from the
# repository root; about 15 minutes on 2 idle cores.
#   bash bench/scaling.sh [--no-large | --largest]
# --largest runs only 100 buildings of 290 storeys (7.0 M equations, 16 GiB).
set -eu
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 # one thread per rank
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python=/usr/bin/python3
run() { # file ranks
  echo "== $(basename "$1" .prm), $2 rank(s), load $(cut -d' ' -f1 /proc/loadavg)"
  mpirun -np "$2" build/poundfe-bench --distributed "$1" |
    grep -E "equations|set-up|factors|stepping|peak resident"
}
if [ "${1:-}" = --largest ]; then # 7.0 M equations, 16 GiB, 11 minutes: the machine to itself
  $python scripts/city_block.py --buildings 100 --storeys 290 --end 0.05 > "$work/largest.prm"
  run "$work/largest.prm" 1
  exit 0
fi
for buildings in 3 6 12 24; do
  $python scripts/city_block.py --buildings $buildings --end 0.05 > "$work/row$buildings.prm"
  for ranks in 1 2; do run "$work/row$buildings.prm" $ranks; done
done
if [ "${1:-}" != --no-large ]; then
  $python scripts/city_block.py --buildings 100 --storeys 80 --end 0.05 > "$work/large.prm"
  run "$work/large.prm" 1
fi
