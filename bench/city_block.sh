#!/usr/bin/env bash
# The distributed solve of input/city-block.prm (issue 12 item 5) on 1 and 2
# ranks (Release build, from the repository root): set-up, steps/s, where the
# stepping time goes and the peak resident memory per rank (getrusage, what
# /usr/bin/time -v reports), from poundfe-bench --distributed. About 10
# minutes on 2 cores.
#   bash bench/city_block.sh [FILE]
set -eu
file=${1:-input/city-block.prm}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# one thread per rank: no BLAS threads competing with the ranks for the cores
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
for ranks in 1 2; do
  mpirun -np $ranks build/poundfe-bench --distributed "$file"
done
