#!/usr/bin/env bash
# doc/thesis-reproduction.md is current: scripts/reproduce-thesis.sh --check
# reruns every table and figure of the page but the five bifurcation
# diagrams of Fig. 3.2 (four of its five minutes) and compares each line
# those runs decide (the tables with their comparisons, the figures'
# peaks, counts and estimates, the Subset estimate with its CoV bounds)
# with the committed page, to the printed digit. The run times and the
# Fig. 3.2 rows are not compared.
#   thesis_reproduction.sh POUNDFE
set -eu
poundfe=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
bash "$here/../../scripts/reproduce-thesis.sh" "$(dirname "$poundfe")" "$work/out" --check ||
  { echo "FAIL doc/thesis-reproduction.md differs from what scripts/reproduce-thesis.sh now writes"; exit 1; }
echo "ok   doc/thesis-reproduction.md: the committed lines are those the script writes"
