#!/usr/bin/env bash
# CG with algebraic multigrid against UMFPACK on the city block (issue 23
# item 2; Release build, from the repository root): `poundfe run` over the
# first END seconds (default 0.1 s = 20 steps of 5 ms), one process, with
# each "NONLINEAR/LINEAR" pair of Time integration/Nonlinear solver and
# Linear solver (default: krylov-newton with umfpack, petsc-cg-boomeramg and
# trilinos-cg-ml, and newton with petsc-cg-boomeramg). Prints per run the
# steps/s (summary.json: wall time of the stepping, outputs included), Newton
# iterations per (sub-)step, linear solves, CG iterations per solve,
# preconditioner builds, peak resident memory (/usr/bin/time -v) and how far
# every output column is from the first run's (same_trajectory.py, relative
# to each column's peak). Extra settings for the Iterative solver
# subsection: AMG="AMG strong threshold = 0.25" (one "NAME = VALUE").
#   bash bench/amg_solvers.sh [FILE [END [PAIRS...]]]
set -eu
file=${1:-input/city-block.prm} end=${2:-0.1}
shift $(($# > 2 ? 2 : $#))
pairs=${*:-krylov-newton/umfpack krylov-newton/petsc-cg-boomeramg krylov-newton/trilinos-cg-ml newton/petsc-cg-boomeramg}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
value() { grep -o "\"$2\": [0-9.e+-]*" "$1" | head -1 | cut -d' ' -f2; }
reference=""
for pair in $pairs; do
  method=${pair%/*} solver=${pair#*/} name=${pair//\//-}
  echo "load before $name: $(cut -d' ' -f1-3 /proc/loadavg)"
  sed -e "s/^\( *set End time *=\).*/\1 $end/" -e "/^ *set Linear solver *=/d" \
      -e "/^subsection Time integration/a\\  set Nonlinear solver = $method\\n  set Linear solver = $solver" \
      "$file" > "$work/$name.prm"
  [ -n "${AMG:-}" ] &&
    sed -i "/^subsection Time integration/a\\  subsection Iterative solver\\n    set $AMG\\n  end" "$work/$name.prm"
  /usr/bin/time -v build/poundfe run "$work/$name.prm" --output "$work/$name" > /dev/null 2> "$work/$name.time"
  s="$work/$name/summary.json"
  memory=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$work/$name.time")
  steps=$(value "$s" steps)
  awk -v m="$name" -v w="$(value "$s" wall_time_s)" -v n="$steps" -v i="$(value "$s" mean_iterations_per_step)" \
      -v ls="$(value "$s" linear_solves)" -v li="$(value "$s" mean_linear_iterations_per_solve)" \
      -v b="$(value "$s" preconditioner_builds)" -v f="$(value "$s" refactorizations)" -v mem="$memory" \
      'BEGIN { printf "%-34s %4d steps %7.1f s %6.3f steps/s  %5.2f Newton its/step  %s  refactorisations %s  peak RSS %.0f MiB\n", m, n, w, n / w, i, (ls == "" ? "direct" : sprintf("%d solves, %.1f CG its/solve, %d preconditioner builds", ls, li, b)), f, mem / 1024 }'
  if [ -n "$reference" ]; then
    worst=0
    for csv in "$work/$reference"/*.csv; do
      scale=""
      [ "$(basename "$csv")" = energy.csv ] && scale=--common-scale
      d=$(/usr/bin/python3 tests/cli/same_trajectory.py $scale 1 "$csv" "$work/$name/$(basename "$csv")" |
          sed -n 's/.*largest difference \([^ ]*\) .*/\1/p')
      worst=$(awk -v a="$worst" -v b="$d" 'BEGIN { print (b > a ? b : a) }')
    done
    echo "                                   every output column within $worst of its peak from $reference's"
  else
    reference=$name
  fi
done
