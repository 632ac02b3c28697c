#!/usr/bin/env bash
# poundfe:: in OpenSees scripts (doc/user-guide.md, Running OpenSees scripts):
#  1. poundfe::energy against the script's own trapezoidal sums, and the
#     balance's residual within 1e-8 of the largest term
#     (tests/opensees/energy_balance.tcl): a linear SDOF, a two-storey stick
#     with a nodal load, two sticks pounding through ElasticPPGap,
#     ViscoelasticGap, Hertzdamp and a MinMax of ImpactMaterial;
#  2. poundfe::impacts against the gap's force history (episodes, peak
#     force, impulse) and its CSV file, one row an episode;
#  3. an unknown poundfe:: command or option: one line with the file and
#     line, exit 1.
#   opensees_poundfe.sh POUNDFE CORPUS_DIR
set -u
poundfe=$1 corpus=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$here/helpers.sh"
for case in sdof mdof ElasticPPGap ViscoelasticGap Hertzdamp MinMax; do
  mkdir -p "$work/$case"
  "$poundfe" opensees "$corpus/energy_balance.tcl" "$case" "$work/$case" > "$work/$case/log" 2>&1 \
    || { cat "$work/$case/log"; fail "energy_balance $case"; }
done
# the CSV: its header and one row per episode the script counted
log=$work/ElasticPPGap/log csv=$work/ElasticPPGap/impacts.csv
n=$(sed -n 's/^energy_balance ElasticPPGap: \([0-9]*\) impacts$/\1/p' "$log")
[ -n "$n" ] && [ "$n" -gt 0 ] || { cat "$log"; fail "no impacts counted"; }
head -1 "$csv" | grep -qxF "element,start_time,end_time,peak_force,impulse,max_penetration,max_penetration_time" \
  || fail "impacts.csv's header"
[ "$(tail -n +2 "$csv" | wc -l)" = "$n" ] || fail "impacts.csv: not $n rows"
[ -z "$(tail -n +2 "$csv" | cut -d, -f1 | grep -vx 3)" ] || fail "impacts.csv: an element other than 3"
# refusals, by name with the file and line
bad() {
  local dir="$work/bad-$1"
  mkdir -p "$dir"
  { echo "model basic -ndm 1 -ndf 1"; cat; } > "$dir/s.tcl"
  "$poundfe" opensees "$dir/s.tcl" > "$dir/out" 2> "$dir/err"
  local status=$?
  [ "$status" = 1 ] || fail "$1: exit status $status"
  [ "$(wc -l < "$dir/err")" = 1 ] || { cat "$dir/err"; fail "$1: not one line"; }
  grep -qxF -- "poundfe: error: $dir/s.tcl:$2" "$dir/err" || { cat "$dir/err"; fail "$1: message"; }
}
echo "poundfe::energy -file e.out" | bad energy-option \
  "2: poundfe::energy: unknown option '-file' (poundfe::energy takes none)" || exit 1
echo "poundfe::impacts -csv i.csv" | bad impacts-option \
  "2: poundfe::impacts: unknown option '-csv' (poundfe::impacts takes -file F)" || exit 1
echo "poundfe::frobnicate" | bad unknown-command \
  '2: invalid command name "poundfe::frobnicate"' || exit 1
echo "ok"
