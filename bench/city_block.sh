#!/usr/bin/env bash
# The distributed solve of input/city-block.prm (issue 12 item 5) on 1 and 2
# ranks (Release build, from the repository root): set-up, steps/s, where the
# stepping time goes and the peak resident memory per rank (getrusage, what
# /usr/bin/time -v reports), from poundfe-bench --distributed; then one
# rank with the default solver under Krylov-Newton against full Newton
# (steps/s and how far apart, per output file). About 15 minutes on 2 cores.
#   bash bench/city_block.sh [FILE]
set -eu
file=${1:-input/city-block.prm}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# one thread per rank: no BLAS threads competing with the ranks for the cores
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
for ranks in 1 2; do
  mpirun -np $ranks build/poundfe-bench --distributed "$file"
done
# One rank, as one would run it there: the default direct solver (Eigen's
# simplicial L D L^T; its solves take a few ms against MUMPS's ~27 ms, whose
# per-call overhead dominates on these narrow frames) under Krylov-Newton,
# against full Newton; both at Newton residual tolerance 1e-11 (at the
# default 1e-8 the methods stop at different points: 1.1e-5 of a floor
# acceleration's peak apart, 5e-8 of a peak drift's, measured at stop 30).
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for method in newton krylov-newton; do
  sed -e '/set Linear solver *= petsc-mumps/d' \
      -e "/^subsection Time integration/a\\  set Nonlinear solver = $method\n  set Newton residual tolerance = 1e-11" \
      "$file" > "$work/$method.prm"
  build/poundfe run "$work/$method.prm" --output "$work/$method" > /dev/null
  printf 'one rank, eigen-ldlt, %s: %s\n' "$method" \
    "$(grep -o '"steps_per_second": [0-9.]*\|"refactorizations": [0-9]*' "$work/$method/summary.json" | tr '\n' ' ')"
done
for csv in "$work/newton"/*.csv; do
  scale=""
  [ "$(basename "$csv")" = energy.csv ] && scale=--common-scale
  d=$(/usr/bin/python3 tests/cli/same_trajectory.py $scale 1 "$csv" "$work/krylov-newton/$(basename "$csv")" |
      sed -n 's/.*largest difference \([^ ]*\) .*/\1/p')
  printf 'Krylov-Newton against full Newton, %s: within %s of a column'"'"'s peak\n' "$(basename "$csv")" "$d"
done
