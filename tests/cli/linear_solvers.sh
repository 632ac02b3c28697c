#!/usr/bin/env bash
# `run` with the PETSc and Trilinos solvers, which need MPI initialised
# (poundfe initialises it only when the input selects them): completes and
# gives the peak drifts of eigen-ldlt.
set -eu
poundfe=$1 input=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL $*"; exit 1; }
peaks() { grep -o '"peak_drift_ratio": [^,}]*' "$1" | cut -d' ' -f2; }
for solver in eigen-ldlt petsc trilinos; do
  sed "/^subsection Time integration/a\\  set Linear solver = $solver" "$input" > "$work/$solver.prm"
  "$poundfe" run "$work/$solver.prm" --output "$work/$solver" > /dev/null || fail "$solver: exit status $?"
  grep -q '"status": "completed"' "$work/$solver/summary.json" || fail "$solver: not completed"
  grep -q "\"linear_solver\": \"$solver\"" "$work/$solver/summary.json" || fail "$solver: another solver ran"
  paste <(peaks "$work/eigen-ldlt/summary.json") <(peaks "$work/$solver/summary.json") |
    awk -v s="$solver" '{ d = $1 - $2; if (d < 0) d = -d; if (d > 1e-9 * ($1 < 0 ? -$1 : $1)) { print "FAIL " s ": peak drift " $2 " instead of " $1; exit 1 } }'
  echo "ok   run with $solver"
done
