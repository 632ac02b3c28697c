#!/usr/bin/env bash
# Time integration/Linear solver = petsc-cg-boomeramg and trilinos-cg-ml
# (CG with algebraic multigrid, assembly/iterative_solver.h) give UMFPACK's
# trajectory: every numeric column of every CSV output within TOLERANCE
# (1e-8) of that column's peak (same_trajectory.py; energy.csv at the scale
# of its largest term), on a frame pair with hinges and Hertz-damp gaps and
# a shear pair with Bouc-Wen storeys and Jankowski gaps (both with the
# tangent refactorised, so the matrix changes under a kept preconditioner),
# the small city block and the shipped two-building example. All runs use
# Newton residual tolerance = NEWTON (1e-11, as nonlinear_solvers.sh), so CG
# stops at 0.1 x 1e-11 of ||b||. Also: every Nonlinear solver with BoomerAMG
# on the frame pair; the preconditioner is reused (builds < solves, and
# fewer than with Preconditioner reuse = false); on 2 ranks (MPIRUN) every
# rank runs the whole analysis and rank 0 writes the 1-rank trajectory; a CG
# that cannot converge (Linear maximum iterations = 1) stops the run with
# exit 2 naming the step, the results so far kept.
#   amg_solvers.sh POUNDFE TESTS_CLI_DIR INPUT_DIR [MPIRUN [TOLERANCE [NEWTON]]]
set -eu
poundfe=$1 here=$2 input=$3 mpirun=${4:-} tolerance=${5:-1e-8} newton=${6:-1e-11}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$here/helpers.sh" # fail, with
# FILE with "set NAME = VALUE" in a Time integration/Iterative solver subsection
iterative() { sed "/^subsection Time integration/a\\  subsection Iterative solver\\n    set $2\\n  end" "$1"; }
value() { grep -o "\"$2\": [0-9.e+-]*" "$1" | head -1 | cut -d' ' -f2; }
counts() {
  local s=$1/summary.json
  echo "iterations/step $(value "$s" mean_iterations_per_step | cut -c1-5)" \
       "solves $(value "$s" linear_solves)" \
       "CG its/solve $(value "$s" mean_linear_iterations_per_solve | cut -c1-5)" \
       "max $(value "$s" max_linear_iterations_per_solve)" \
       "builds $(value "$s" preconditioner_builds)"
}
same() { # REFERENCE_DIR CANDIDATE_DIR LABEL
  grep -q '"status": "completed"' "$2/summary.json" || fail "$3: not completed"
  for csv in "$1"/*.csv; do
    scale=""
    [ "$(basename "$csv")" = energy.csv ] && scale=--common-scale
    /usr/bin/python3 "$here/same_trajectory.py" $scale "$tolerance" "$csv" "$2/$(basename "$csv")" \
      > "$work/diff" || fail "$3: $(basename "$csv"): $(cat "$work/diff")"
  done
}
reused() { # DIR LABEL: at least one build, fewer builds than solves
  local b s
  b=$(value "$1/summary.json" preconditioner_builds) s=$(value "$1/summary.json" linear_solves)
  [ -n "$b" ] && [ "$b" -ge 1 ] && [ "$b" -lt "$s" ] || fail "$2: $b builds for $s solves"
}
# model | End time replacing the file's (empty: keep it) | settings
cases="$here/newton-frame-pair.prm||Tangent update = refactorize
$here/newton-shear-pair.prm||Tangent update = refactorize
$here/city-block-small.prm|0.3|Tangent update = refactorize; Nonlinear solver = krylov-newton
$input/two-buildings.prm||End time = 1"
while IFS='|' read -r model end settings; do
  name=$(basename "$model" .prm)
  sed -e "/^ *set Linear solver *=/d" -e "${end:+s/^\( *set End time *=\).*/\1 $end/}" "$model" \
    > "$work/$name.base.prm"
  with "$work/$name.base.prm" "Newton residual tolerance = $newton; $settings" > "$work/$name.prm"
  with "$work/$name.prm" "Linear solver = umfpack" > "$work/$name.umfpack.prm"
  "$poundfe" run "$work/$name.umfpack.prm" --output "$work/$name/umfpack" > /dev/null ||
    fail "$name umfpack: exit $?"
  for solver in petsc-cg-boomeramg trilinos-cg-ml; do
    out="$work/$name/$solver"
    with "$work/$name.prm" "Linear solver = $solver" > "$work/$name.$solver.prm"
    "$poundfe" run "$work/$name.$solver.prm" --output "$out" > /dev/null || fail "$name $solver: exit $?"
    grep -q "\"linear_solver\": \"$solver\"" "$out/summary.json" || fail "$name $solver: another solver ran"
    same "$work/$name/umfpack" "$out" "$name $solver"
    reused "$out" "$name $solver"
    echo "ok   $name ($settings) $solver = umfpack: $(counts "$out")"
  done
done <<< "$cases"

frame=$work/newton-frame-pair.petsc-cg-boomeramg.prm
for method in modified-newton krylov-newton bfgs auto; do
  with "$frame" "Nonlinear solver = $method" > "$work/frame.$method.prm"
  "$poundfe" run "$work/frame.$method.prm" --output "$work/frame/$method" > /dev/null ||
    fail "frame $method: exit $?"
  same "$work/newton-frame-pair/umfpack" "$work/frame/$method" "frame boomeramg $method"
  echo "ok   frame pair, boomeramg with $method = umfpack newton: $(counts "$work/frame/$method")"
done

iterative "$frame" "Preconditioner reuse = false" > "$work/frame.rebuild.prm"
"$poundfe" run "$work/frame.rebuild.prm" --output "$work/frame/rebuild" > /dev/null || fail "no reuse: exit $?"
same "$work/newton-frame-pair/umfpack" "$work/frame/rebuild" "frame boomeramg without reuse"
kept=$(value "$work/newton-frame-pair/petsc-cg-boomeramg/summary.json" preconditioner_builds)
rebuilt=$(value "$work/frame/rebuild/summary.json" preconditioner_builds)
[ "$rebuilt" -gt "$kept" ] || fail "Preconditioner reuse = false: $rebuilt builds, with reuse $kept"
echo "ok   Preconditioner reuse = false: $rebuilt builds against $kept with reuse"

if [ -n "$mpirun" ]; then
  $mpirun -np 2 "$poundfe" run "$frame" --output "$work/frame/ranks2" > /dev/null || fail "2 ranks: exit $?"
  same "$work/newton-frame-pair/petsc-cg-boomeramg" "$work/frame/ranks2" "2 ranks"
  echo "ok   2 ranks: the 1-rank trajectory"
fi

with "$frame" "Maximum step cuts = 1" > "$work/frame.cuts.prm"
iterative "$work/frame.cuts.prm" "Linear maximum iterations = 1" > "$work/frame.fail.prm"
status=0
"$poundfe" run "$work/frame.fail.prm" --output "$work/frame/fail" > /dev/null 2> "$work/err" || status=$?
[ "$status" -eq 2 ] || fail "non-converging CG: exit $status ($(cat "$work/err"))"
grep -q "the step from t = .*did not converge in 1 iterations" "$work/err" ||
  fail "non-converging CG: message $(cat "$work/err")"
grep -q '"status": "failed"' "$work/frame/fail/summary.json" || fail "non-converging CG: status"
[ -s "$work/frame/fail/drift.csv" ] || fail "non-converging CG: results so far not kept"
echo "ok   non-converging CG: exit 2, $(head -c 200 "$work/err")"
