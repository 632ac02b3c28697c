#!/usr/bin/env bash
# The distributed solve of input/city-block.prm (issue 12 item 5) on 1 and 2
# ranks (Release build, from the repository root): set-up, steps/s, where the
# stepping time goes and the peak resident memory per rank (getrusage, what
# /usr/bin/time -v reports), from poundfe-bench --distributed; then one
# rank with the default solver under Krylov-Newton against full Newton
# (steps/s and how far apart, per output file); then the model partitioned
# by building (poundfe-bench --partitioned, doc/theory.md §3.5d) on 2 ranks
# against the whole model on one process (--serial), both under
# Krylov-Newton at 1e-11 with eigen-ldlt, and how far apart their final
# displacements are; last, poundfe run with Partition = buildings and every
# output on 2 ranks against one process. About 18 minutes on 2 cores.
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
# Partitioned by building: each rank owns its buildings' equations, elements
# and factorisation; the same method and tolerance on one process first.
sed -e "/^subsection Time integration/a\\  set Nonlinear solver = krylov-newton\n  set Newton residual tolerance = 1e-11" \
    "$file" > "$work/partitioned.prm"
build/poundfe-bench --serial "$work/partitioned.prm" 0 "$work/serial-u.txt"
mpirun -np 2 build/poundfe-bench --partitioned "$work/partitioned.prm" 0 "$work/partitioned-u.txt"
/usr/bin/python3 - "$work/serial-u.txt" "$work/partitioned-u.txt" <<'PY'
import sys
a = [float(x) for x in open(sys.argv[1])]
b = [float(x) for x in open(sys.argv[2])]
assert len(a) == len(b), "the two runs report different models"
peak = max(abs(x) for x in a)
d = max(abs(x - y) for x, y in zip(a, b))
print(f"partitioned on 2 ranks against the whole model: final displacements within {d / peak:.2e} of the peak ({peak:.4g} m)")
PY
# poundfe run partitioned by building on 2 ranks, with every output of the
# input (rank 0 gathers u, v and a after each accepted state and replays the
# elements: theory §3.5d), against the one-process Krylov-Newton run above:
# steps/s, each rank's peak RSS, and how far apart their files are.
sed -e "/^subsection Time integration/a\\  set Partition = buildings" "$work/krylov-newton.prm" > "$work/run-partitioned.prm"
/usr/bin/time -f 'one process: peak RSS %M KiB' build/poundfe run "$work/krylov-newton.prm" --output "$work/run-whole" > /dev/null
# each rank's figure goes to its own file: two ranks writing to stderr at once
# can interleave their lines
mpirun -np 2 bash -c '/usr/bin/time -o "$0.$OMPI_COMM_WORLD_RANK" -f "rank $OMPI_COMM_WORLD_RANK: peak RSS %M KiB" "$@"' \
  "$work/rss" build/poundfe run "$work/run-partitioned.prm" --output "$work/run-partitioned" > /dev/null
cat "$work/rss.0" "$work/rss.1"
for run in run-whole run-partitioned; do
  printf 'poundfe run, %s: %s\n' "$run" "$(grep -o '"steps_per_second": [0-9.]*' "$work/$run/summary.json")"
done
worst=0
for csv in "$work/run-whole"/*.csv; do
  scale=""
  [ "$(basename "$csv")" = energy.csv ] && scale=--common-scale
  d=$(/usr/bin/python3 tests/cli/same_trajectory.py $scale 1 "$csv" "$work/run-partitioned/$(basename "$csv")" |
      sed -n 's/.*largest difference \([^ ]*\) .*/\1/p')
  worst=$(/usr/bin/python3 -c "print(max($worst, $d))")
done
echo "poundfe run partitioned on 2 ranks against one process: every CSV within $worst of a column's peak"
