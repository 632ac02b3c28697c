#!/usr/bin/env bash
# poundfe:: in OpenSees scripts (doc/user-guide.md, Running OpenSees scripts):
#  1. poundfe::energy against the script's own trapezoidal sums, and the
#     balance's residual within 1e-8 of the largest term
#     (tests/opensees/energy_balance.tcl): a linear SDOF, a two-storey stick
#     with a nodal load (Rayleigh, then modal damping, whose term closes the
#     balance), the stick yielding (Steel01, Rayleigh on the committed
#     stiffness), two sticks pounding through ElasticPPGap,
#     ViscoelasticGap, Hertzdamp, a MinMax of ImpactMaterial, the
#     ElasticPPGap as a twoNodeLink and in Series with an Elastic spring; across
#     analyze calls (tests/opensees/energy_restart.tcl): `reset` starts the
#     balance and the impact log again, and new Rayleigh factors between
#     two analyze calls keep the balance closed;
#  2. poundfe::impacts against the gap's force history (episodes, peak
#     force, impulse) and its CSV file, one row an episode;
#  3. poundfe::stepCutting (tests/opensees/step_cutting.tcl): a pounding
#     pair whose step fails at 1.8 s under Newton (as under OpenSees 3.8)
#     completes with it on; before the failure its rows are the failed run's
#     byte for byte, after it its distance from a run at dt/16 at most twice
#     that before (the step's own discretisation error; measured 1.3 times);
#  4. an unknown poundfe:: command or option, a query of an observer the
#     script has not turned on, an empty file name, poundfe::locateEvents
#     with a number of halvings out of 1 to 12 or not a number: one line
#     with the file and line, exit 1; poundfe::locateEvents query gives the
#     halvings (4 by default, 0 off and after wipe). poundfe::locateEvents's
#     numbers: opensees_locate.sh.
#   opensees_poundfe.sh POUNDFE CORPUS_DIR PYTHON3
set -u
poundfe=$1 corpus=$2 python=$3
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$here/helpers.sh"
for case in sdof mdof modal steel01 ElasticPPGap ViscoelasticGap Hertzdamp MinMax TwoNodeLink \
    Series; do
  mkdir -p "$work/$case"
  "$poundfe" opensees "$corpus/energy_balance.tcl" "$case" "$work/$case" > "$work/$case/log" 2>&1 \
    || { cat "$work/$case/log"; fail "energy_balance $case"; }
done
for case in reset rayleigh; do
  "$poundfe" opensees "$corpus/energy_restart.tcl" "$case" > "$work/restart-$case.log" 2>&1 \
    || { cat "$work/restart-$case.log"; fail "energy_restart $case"; }
done
# the CSV: its header and one row per episode the script counted
log=$work/ElasticPPGap/log csv=$work/ElasticPPGap/impacts.csv
n=$(sed -n 's/^energy_balance ElasticPPGap: \([0-9]*\) impacts$/\1/p' "$log")
[ -n "$n" ] && [ "$n" -gt 0 ] || { cat "$log"; fail "no impacts counted"; }
head -1 "$csv" | grep -qxF "element,start_time,end_time,peak_force,impulse,max_penetration,max_penetration_time" \
  || fail "impacts.csv's header"
[ "$(tail -n +2 "$csv" | wc -l)" = "$n" ] || fail "impacts.csv: not $n rows"
[ -z "$(tail -n +2 "$csv" | cut -d, -f1 | grep -vx 3)" ] || fail "impacts.csv: an element other than 3"
# step cutting: off fails as OpenSees does, on completes and agrees
mkdir -p "$work/cut"
for mode in off on fine; do
  "$poundfe" opensees "$corpus/step_cutting.tcl" "$work/cut" $mode > "$work/cut/$mode.log" 2>&1
done
grep -qxF "step_cutting off: status -3 time 1.798000" "$work/cut/off.log" \
  || { cat "$work/cut/off.log"; fail "step cutting off: not the failure at 1.8 s"; }
for mode in on fine; do
  grep -qxF "step_cutting $mode: status 0 time 4.000000" "$work/cut/$mode.log" \
    || { cat "$work/cut/$mode.log"; fail "step cutting $mode: did not complete"; }
done
n_off=$(wc -l < "$work/cut/cut_off.out")
[ "$n_off" -gt 100 ] && head -n "$n_off" "$work/cut/cut_on.out" | cmp -s - "$work/cut/cut_off.out" \
  || fail "step cutting on: rows before the failure differ from the run without it"
"$python" - "$work/cut" <<'PY' || fail "step cutting on: off the fine run"
import sys
def rows(name):
    with open(f"{sys.argv[1]}/cut_{name}.out") as f:
        return {round(float(w[0]), 9): [float(x) for x in w[1:]] for w in map(str.split, f) if w}
on, fine = rows("on"), rows("fine")
before = after = 0.0
for t, u in on.items():
    if t in fine and abs(t / 0.002 - round(t / 0.002)) < 1e-6:
        e = max(abs(a - b) for a, b in zip(u, fine[t]))
        if t < 1.7985:
            before = max(before, e)
        else:
            after = max(after, e)
print(f"step cutting: distance from dt/16 before the failure {before:.3e}, after {after:.3e}")
sys.exit(0 if 0 < before and after <= 2 * before else 1)
PY
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
echo "poundfe::energy on; poundfe::energy -file e.out" | bad energy-option \
  "2: poundfe::energy: unknown option '-file' (poundfe::energy takes none, or on or off)" || exit 1
echo "poundfe::impacts on; poundfe::impacts -csv i.csv" | bad impacts-option \
  "2: poundfe::impacts: unknown option '-csv' (poundfe::impacts takes -file F, or on or off)" || exit 1
echo "poundfe::impacts on; poundfe::impacts -file {}" | bad impacts-empty-file \
  "2: poundfe::impacts: an empty file name after -file" || exit 1
echo "poundfe::energy on off" | bad energy-on-off \
  "2: poundfe::energy: unknown word 'off' after on" || exit 1
echo "poundfe::energy" | bad energy-off \
  "2: poundfe::energy: it is off: 'poundfe::energy on' before the analysis turns it on" || exit 1
printf 'poundfe::impacts on\nwipe\npoundfe::impacts\n' | bad impacts-wiped \
  "4: poundfe::impacts: it is off: 'poundfe::impacts on' before the analysis turns it on" || exit 1
echo "poundfe::stepCutting on 0" | bad cuts-zero \
  "2: poundfe::stepCutting: the most halvings must be 1 to 30, got 0" || exit 1
echo "poundfe::stepCutting sometimes" | bad cuts-word \
  "2: poundfe::stepCutting: 'sometimes' where on or off is due" || exit 1
echo "poundfe::frobnicate" | bad unknown-command \
  '2: invalid command name "poundfe::frobnicate"' || exit 1
echo "poundfe::locateEvents on -1" | bad locate-negative \
  "2: poundfe::locateEvents: the most halvings must be 1 to 12, got -1" || exit 1
echo "poundfe::locateEvents on 99" | bad locate-large \
  "2: poundfe::locateEvents: the most halvings must be 1 to 12, got 99" || exit 1
echo "poundfe::locateEvents on x" | bad locate-word \
  "2: poundfe::locateEvents: expected an integer for the most halvings, got 'x'" || exit 1
echo "poundfe::locateEvents sometimes" | bad locate-state \
  "2: poundfe::locateEvents: 'sometimes' where on, off or query is due" || exit 1
echo "poundfe::locateEvents off 3" | bad locate-extra \
  "2: poundfe::locateEvents: unknown word '3' after off" || exit 1
echo "poundfe::locateEvents" | bad locate-nothing \
  "2: poundfe::locateEvents: missing on, off or query" || exit 1
# query: R, 4 by default, 0 off
printf 'puts [poundfe::locateEvents query]\npoundfe::locateEvents on\nputs [poundfe::locateEvents query]\npoundfe::locateEvents on 9\nputs [poundfe::locateEvents query]\nwipe\nputs [poundfe::locateEvents query]\n' \
  > "$work/query.tcl"
[ "$("$poundfe" opensees "$work/query.tcl" | tr '\n' ' ')" = "0 4 9 0 " ] || fail "locateEvents query"
echo "ok"
