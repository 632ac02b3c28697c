#!/usr/bin/env bash
# Hostile input, round two (issue 28), the remaining classes, through the
# real binary (tests/cli/expect.sh):
#   class 3: SIGTERM in every phase of ground-motion --realizations (while
#            generating, and after its sample CSV: the PSD phase ran on for
#            minutes); outputs larger than the free disk refused before
#            anything is written (the size guard);
#   class 4: absurd inputs (design ground acceleration, scale factor, E,
#            maximum period, gap, all 1e308) are refused naming the
#            parameter or fail with exit 2 naming the quantity: never exit 0
#            with NaN or inf in a result;
#   class 6: every command that writes, run into a directory holding an
#            earlier command's files, leaves none of them beside its own;
#   class 7: a gnuplot that fails: status "completed with warnings" with the
#            missing figures listed, no .gp/.log helper left;
#   class 8: a value twice in Sweep/Values and Bifurcation/Values;
#   class 9: an absurd stiffness is named as such, not as a damping problem.
#   hostile_input_28_faults.sh POUNDFE INPUT_DIR CLI_DIR
set -u
poundfe=$(readlink -f "$1") inputs=$(readlink -f "$2") cli=$(readlink -f "$3")
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
. "$here/expect.sh"
plots_off() { sed 's/^\(subsection Output\)$/\1\n  set Plots = false/' "$1"; }

# --- class 3: SIGTERM in each phase of ground-motion --realizations --------
# stop_in_phase NAME WAIT LIMIT COMMAND...: starts COMMAND into out-NAME,
# waits for WAIT (a file of out-NAME to appear, or a number of seconds),
# sends SIGTERM; it must exit with 143 within LIMIT s, summary.json
# "interrupted", no *.tmp.
stop_in_phase() {
  local name=$1 wait=$2 limit=$3 d=out-$1 status=0
  shift 3
  n=$((n + 1))
  "$poundfe" "$@" --output "$d" > "$name.log" 2>&1 &
  local job=$!
  if [[ $wait =~ ^[0-9.]+$ ]]; then
    sleep "$wait"
  else
    # up to 240 s: on a loaded 2-core machine the 5,000 realizations took 77 s
    for _ in $(seq 1 4800); do [ -e "$d/$wait" ] && break; sleep 0.05; done
    [ -e "$d/$wait" ] || { fail "$name: $wait never appeared"; kill -KILL "$job"; return; }
  fi
  kill -0 "$job" 2> /dev/null || { fail "$name: finished before the signal; give it a longer input"; return; }
  kill -TERM "$job"
  local start=$SECONDS
  while kill -0 "$job" 2> /dev/null && [ $((SECONDS - start)) -lt "$limit" ]; do sleep 0.1; done
  if kill -0 "$job" 2> /dev/null; then
    kill -KILL "$job"; wait "$job" 2> /dev/null
    fail "$name: still running $limit s after SIGTERM"; return
  fi
  wait "$job" || status=$?
  [ "$status" -eq 143 ] || { fail "$name: exit status $status: $(cat "$name.log")"; return; }
  grep -q '"status": "interrupted"' "$d/summary.json" || { fail "$name: summary.json not interrupted"; return; }
  [ -z "$(find "$d" -name '*.tmp')" ] || { fail "$name: temporaries left"; return; }
  echo "ok   $name: SIGTERM after $wait, exit 143 within $((SECONDS - start)) s, summary.json interrupted"
}
plots_off "$inputs/two-buildings.prm" > motion.prm
stop_in_phase motion-generating 3 15 ground-motion motion.prm --realizations 5000
stop_in_phase motion-psd ground_motion_samples.csv 15 ground-motion motion.prm --realizations 5000

# the size guard: 2*10^6 samples x 10^5 realizations (about 4 TB of CSV)
sed 's/set Duration    = 20/set Duration    = 2000/' motion.prm > huge.prm
grep -q "Duration    = 2000" huge.prm || fail "huge.prm: no Duration changed"
n=$((n + 1))
rm -rf out
timeout 60 "$poundfe" ground-motion huge.prm --realizations 100000 --output out > huge.log 2>&1
status=$?
if [ "$status" -ne 1 ]; then
  fail "size guard: exit $status: $(head -c 300 huge.log)"
elif ! grep -q "poundfe: error: disk full: cannot write the ground-motion samples (2000001 rows of 100000 realizations) (about 4e+03 GB; .* GB free) in " huge.log; then
  fail "size guard: message: $(head -c 300 huge.log)"
elif ! grep -q '"status": "failed"' out/summary.json || [ -e out/ground_motion_samples.csv ]; then
  fail "size guard: summary.json not failed, or samples written"
else
  echo "ok   size guard: $(head -c 200 huge.log)"
fi

# --- class 4: no NaN or inf with exit status 0 -----------------------------
# finite NAME COMMAND...: exit 0 with no NaN or inf in any result (JSON's
# null, "not defined here", is allowed: output/finite_output.h), or exit 1
# naming a parameter, or exit 2 naming the quantity (one line)
finite() {
  local name=$1 status=0
  shift
  n=$((n + 1))
  rm -rf "out-$name"
  timeout 120 "$poundfe" "$@" --output "out-$name" > "$name.log" 2> "$name.err" || status=$?
  case $status in
    0) if grep -rqiE '(^|[,:[ ])[-+]?(nan|inf|infinity)(,|$|\])' "out-$name"; then
         fail "$name: exit 0 with a non-finite number: $(grep -rliE '(^|[,:[ ])[-+]?(nan|inf|infinity)(,|$|\])' "out-$name" | head -3)"
         return
       fi ;;
    1) grep -q "parameter '" "$name.err" || { fail "$name: exit 1 names no parameter: $(cat "$name.err")"; return; } ;;
    2) grep -qE "poundfe: numerical failure: the result '[^']+' .*is ([-+]inf|NaN)" "$name.err" ||
         { fail "$name: exit 2 names no quantity: $(cat "$name.err")"; return; } ;;
    *) fail "$name: exit $status: $(head -c 300 "$name.err")"; return ;;
  esac
  [ "$status" -eq 0 ] || [ "$(wc -l < "$name.err")" -eq 1 ] || { fail "$name: not one line: $(cat "$name.err")"; return; }
  echo "ok   $name: exit $status $(head -c 200 "$name.err")"
}
plots_off "$inputs/separation-spectrum.prm" | sed 's/set Design ground acceleration = 0.30/set Design ground acceleration = 1e308/' > dga.prm
grep -q "acceleration = 1e308" dga.prm || fail "dga.prm not changed"
finite design-ground-acceleration separation dga.prm
plots_off "$inputs/three-storey-shear.prm" > shear.prm
awk '/^subsection Ground motion/ {print; print "  set Scale factor = 1e308"; next} {print}' shear.prm > scale.prm
grep -q "Scale factor = 1e308" scale.prm || fail "scale.prm not changed"
finite scale-factor-run run scale.prm
finite scale-factor-ground-motion ground-motion scale.prm
finite scale-factor-spectrum spectrum scale.prm
plots_off "$inputs/three-storey-frame.prm" > frame.prm
sed 's/^\(\s*set \(Column\|Beam\) E\s*=\s*\).*/\11e308/' frame.prm > modulus.prm
grep -q "E.*= 1e308" modulus.prm || fail "modulus.prm not changed"
finite modulus-modal modal modulus.prm
finite modulus-run run modulus.prm
{ cat shear.prm; printf 'subsection Spectrum\n  set Maximum period = 1e308\nend\n'; } > period.prm
finite maximum-period spectrum period.prm
plots_off "$inputs/separation-spectrum.prm" > spectrum-route.prm
{ cat "$cli/separation-sdof-pair.prm"; printf 'subsection Separation\n  set Gap values = 0.01, 1e308\nend\n'; } > gap.prm
finite gap-values separation gap.prm

# --- class 6: a run never mixes its files with an earlier run's -------------
# After modal wrote modes.pvd into `mixed-NAME` (ground-motion its
# ground_motion.csv before modal), COMMAND must leave none of them there.
fresh() {
  local name=$1 earlier=modal mark=modes.pvd status=0
  shift
  [ "$name" = modal ] && earlier=ground-motion mark=ground_motion.csv
  n=$((n + 1))
  rm -rf "mixed-$name"
  "$poundfe" "$earlier" shear.prm --output "mixed-$name" > /dev/null 2>&1 || { fail "$name: $earlier failed"; return; }
  [ -e "mixed-$name/$mark" ] || { fail "$name: $earlier wrote no $mark"; return; }
  timeout 300 "$poundfe" "$@" --output "mixed-$name" > "mixed-$name.log" 2>&1 || status=$?
  [ "$status" -eq 0 ] || { fail "$name: exit $status: $(tail -c 300 "mixed-$name.log")"; return; }
  [ ! -e "mixed-$name/$mark" ] || { fail "$name: the earlier $earlier's $mark is still there"; return; }
  echo "ok   $name: none of $earlier's files left beside its own"
}
plots_off "$inputs/site-hazard.prm" > site-hazard.prm
cp "$inputs/memvele-catalogue-illustrative.csv" .
{ cat shear.prm; printf 'subsection Sweep\n  set Parameter = Building 1/Floor masses\n  set Values = 1000, 1200\nend\n'; } > sweep.prm
sed 's/set Values            = linspace 0.70 0.84 29/set Values = 0.7, 0.8/' "$inputs/duffing-bifurcation.prm" | plots_off /dev/stdin > bifurcation.prm
plots_off "$cli/montecarlo-small.prm" > small.prm
plots_off "$cli/stationary-linear.prm" > stationary.prm
fresh run run shear.prm
fresh modal modal shear.prm
fresh ground-motion ground-motion shear.prm
fresh spectrum spectrum shear.prm
fresh montecarlo montecarlo small.prm
fresh subset subset small.prm
fresh fragility fragility small.prm
fresh stationary-pdf stationary-pdf stationary.prm
fresh sweep sweep sweep.prm
fresh bifurcation bifurcation bifurcation.prm
fresh site-hazard site-hazard site-hazard.prm
fresh separation separation "$cli/separation-sdof-pair.prm"
fresh separation-spectrum separation spectrum-route.prm
fresh reliability reliability "$inputs/thesis-cantilever-reliability.prm"
# the same command twice: separation by spectrum, then by time history
n=$((n + 1))
"$poundfe" separation spectrum-route.prm --output twice > /dev/null 2>&1
[ -e twice/spectrum_modes.csv ] || fail "separation by spectrum wrote no spectrum_modes.csv"
"$poundfe" separation "$cli/separation-sdof-pair.prm" --output twice > /dev/null 2>&1 || fail "separation by time history failed"
[ ! -e twice/spectrum_modes.csv ] && echo "ok   separation after separation: the spectrum route's spectrum_modes.csv gone" ||
  fail "separation after separation: spectrum_modes.csv of the earlier run left"

# --- class 7: a failed plot is not "completed" ------------------------------
mkdir -p bin
printf '#!/bin/sh\necho "line 3: cannot open font" >&2\nexit 1\n' > bin/gnuplot
chmod 755 bin/gnuplot
n=$((n + 1))
rm -rf plots
PATH=$work/bin:$PATH "$poundfe" spectrum "$inputs/three-storey-shear.prm" --output plots > plots.log 2>&1
status=$?
if [ "$status" -ne 0 ]; then
  fail "failed plot: exit $status: $(cat plots.log)"
elif ! grep -q '"status": "completed with warnings"' plots/summary.json; then
  fail "failed plot: status: $(grep status plots/summary.json)"
elif ! python3 -c 'import json,sys; s=json.load(open("plots/summary.json")); m=s["missing_figures"]; assert any(x.startswith("spectrum.png: gnuplot: line 3: cannot open font") for x in m), m' 2> plots.err; then
  fail "failed plot: missing_figures: $(cat plots.err)"
elif [ -n "$(find plots -name '.plots.*' -o -name '*.gp' -o -name '*.log')" ]; then
  fail "failed plot: helper files left: $(ls -a plots)"
else
  echo "ok   failed plot: completed with warnings, missing_figures listed, no .gp/.log left"
fi

# gnuplot stopped by a signal (Ctrl-C while the figures are drawn): the
# reason says so, not "gnuplot failed without a message"
printf '#!/bin/sh\nkill -INT $$\n' > bin/gnuplot
n=$((n + 1))
rm -rf plots
PATH=$work/bin:$PATH "$poundfe" spectrum "$inputs/three-storey-shear.prm" --output plots > plots.log 2>&1
if ! python3 -c 'import json,sys; s=json.load(open("plots/summary.json")); m=s["missing_figures"]; assert any(x == "spectrum.png: gnuplot: stopped by SIGINT while drawing (the run was interrupted)" for x in m), m' 2> plots.err; then
  fail "gnuplot stopped: missing_figures: $(cat plots.err)"
else
  echo "ok   gnuplot stopped by SIGINT: the figures' reason says so"
fi

# --- class 8: a value twice in a sweep or a bifurcation ---------------------
{ cat shear.prm; printf 'subsection Sweep\n  set Parameter = Building 1/Floor masses\n  set Values = 1000, 1200, 1000\nend\n'; } > sweep-twice.prm
expect 1 "parameter 'Sweep/Values': lists 1000 twice (values 1 and 3): give each once" sweep sweep-twice.prm --output out
sed 's/set Values            = linspace 0.70 0.84 29/set Values = linspace 0.7 0.7 3/' "$inputs/duffing-bifurcation.prm" > bifurcation-twice.prm
expect 1 "parameter 'Bifurcation/Values': lists 0.7 twice (values 1 and 2)" bifurcation bifurcation-twice.prm --output out

# --- class 9: an absurd stiffness is named, not taken for a damping problem --
sed 's/set Storey stiffnesses = .*/set Storey stiffnesses = 1e308/' shear.prm > stiff.prm
expect 1 "parameter 'Building 1': building 'shear3' has a stiffness matrix entry of inf (at most 1e150): a stiffness, modulus or section property is out of any physical range" modal stiff.prm --output out

report "issue-28 faults"
