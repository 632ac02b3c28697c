#!/usr/bin/env bash
# Every Time integration/Nonlinear solver (integration/newton_acceleration.h)
# gives the trajectory of full Newton: every numeric column of every CSV
# output within TOLERANCE (1e-8) of that column's largest value
# (same_trajectory.py; energy.csv at the scale of its largest term), on
# models made for this test (a shear pair with Bouc-Wen storeys and stiff
# Jankowski gaps, a frame pair with hinges and Hertz-damp gaps), the small
# city block and shipped examples, with the tangent refactorised (where the
# methods differ in cost), hybrid and Woodbury; full Newton with a line
# search too. Prints each run's iterations and factorisations.
# All runs, full Newton's too, use Newton residual tolerance = NEWTON
# (1e-11): at the default 1e-8 a linearly converging method stops nearer the
# tolerance than Newton's quadratic last iteration, and full Newton itself
# is 4e-8 of a column's peak from its own trajectory at 1e-11
# (doc/verification.md). auto alone is compared at TOLERANCE_AUTO (1e-7):
# it switches between methods by clock times, so which steps stop just
# under the residual tolerance (linear convergence) changes with the load;
# measured 1.2e-9 to 1.09e-8 of a column's peak on city-block-small (the
# last under load); 1e-7 still catches a wrong step or row (O(1)).
#   nonlinear_solvers.sh POUNDFE TESTS_CLI_DIR INPUT_DIR [TOLERANCE [NEWTON]]
set -eu
poundfe=$1 here=$2 input=$3 tolerance=${4:-1e-8} newton=${5:-1e-11}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$here/helpers.sh" # fail, with
counts() {
  for key in steps_including_substeps mean_iterations_per_step refactorizations; do
    printf '%s %s  ' "$key" "$(grep -o "\"$key\": [0-9.e+-]*" "$1" | head -1 | cut -d' ' -f2 | cut -c1-6)"
  done
}
# model | its settings
cases="$here/newton-shear-pair.prm|Tangent update = refactorize
$here/newton-frame-pair.prm|Tangent update = hybrid; Woodbury columns = 4
$here/city-block-small.prm|Tangent update = refactorize
$input/two-buildings.prm|End time = 2
$input/shear-pair-pounding.prm|End time = 2
$input/bouc-wen-sdof.prm|"
while IFS='|' read -r model settings; do
  name=$(basename "$model" .prm)
  with "$model" "Newton residual tolerance = $newton; $settings" > "$work/$name.prm"
  "$poundfe" run "$work/$name.prm" --output "$work/$name/newton" > /dev/null || fail "$name newton: exit $?"
  echo "     $name ($settings) newton: $(counts "$work/$name/newton/summary.json")"
  for variant in modified-newton krylov-newton bfgs auto line-search; do
    if [ $variant = line-search ]; then
      with "$work/$name.prm" "Line search = true" > "$work/$name.$variant.prm"
    else
      with "$work/$name.prm" "Nonlinear solver = $variant" > "$work/$name.$variant.prm"
    fi
    out="$work/$name/$variant"
    "$poundfe" run "$work/$name.$variant.prm" --output "$out" > /dev/null ||
      fail "$name $variant: exit $?"
    grep -q '"status": "completed"' "$out/summary.json" || fail "$name $variant: not completed"
    for csv in "$work/$name/newton"/*.csv; do
      scale=""
      [ "$(basename "$csv")" = energy.csv ] && scale=--common-scale
      allowed=$tolerance
      [ $variant = auto ] && allowed=1e-7
      /usr/bin/python3 "$here/same_trajectory.py" $scale "$allowed" "$csv" "$out/$(basename "$csv")" \
        > /dev/null || fail "$name $variant: $(basename "$csv")"
    done
    echo "ok   $name $variant: $(counts "$out/summary.json")"
  done
done <<< "$cases"
