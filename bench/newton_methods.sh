#!/usr/bin/env bash
# Nonlinear solver = newton, modified-newton, krylov-newton (and bfgs, auto)
# on the city block (issue 23 item 1; Release build, from the repository
# root): `poundfe run` over the first END seconds (default 0.25 s = 50 steps
# of 5 ms), one rank, petsc-mumps as in the input. Prints per method the
# steps/s of the run (summary.json: wall time of the stepping, outputs
# included), factorisations and Newton iterations per step (sub-steps
# included), and how far every output column is from full Newton's
# (same_trajectory.py, relative to each column's peak).
#   bash bench/newton_methods.sh [FILE [END [METHODS...]]]
set -eu
file=${1:-input/city-block.prm} end=${2:-0.25}
shift $(($# > 2 ? 2 : $#))
methods=${*:-newton modified-newton krylov-newton}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
value() { grep -o "\"$2\": [0-9.e+-]*" "$1" | head -1 | cut -d' ' -f2; }
echo "load: $(cut -d' ' -f1-3 /proc/loadavg)"
for method in $methods; do
  sed -e "s/^\( *set End time *=\).*/\1 $end/" \
      -e "/^subsection Time integration/a\\  set Nonlinear solver = $method" "$file" > "$work/$method.prm"
  mpirun -np 1 build/poundfe run "$work/$method.prm" --output "$work/$method" > /dev/null
  s="$work/$method/summary.json"
  steps=$(value "$s" steps) substeps=$(value "$s" steps_including_substeps)
  awk -v m="$method" -v w="$(value "$s" wall_time_s)" -v n="$steps" -v k="$substeps" \
      -v f="$(value "$s" refactorizations)" -v i="$(value "$s" mean_iterations_per_step)" \
      'BEGIN { printf "%-16s %4d steps (%4d with sub-steps) %7.1f s %6.3f steps/s  %6d factorisations (%5.2f per step)  %5.2f iterations per (sub-)step\n", m, n, k, w, n / w, f, f / n, i }'
  if [ "$method" != newton ] && [ -d "$work/newton" ]; then
    worst=0
    for csv in "$work/newton"/*.csv; do
      scale=""
      [ "$(basename "$csv")" = energy.csv ] && scale=--common-scale
      d=$(/usr/bin/python3 tests/cli/same_trajectory.py $scale 1 "$csv" "$work/$method/$(basename "$csv")" |
          sed -n 's/.*largest difference \([^ ]*\) .*/\1/p')
      worst=$(awk -v a="$worst" -v b="$d" 'BEGIN { print (b > a ? b : a) }')
    done
    echo "                 every output column within $worst of its peak from newton's"
  fi
done
