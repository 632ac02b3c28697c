#!/usr/bin/env bash
# Stopping montecarlo, subset and fragility with SIGINT or SIGTERM while they run:
#  - montecarlo on two ranks: SIGINT to rank 0 only (it stops the other),
#    SIGTERM to both ranks (as a batch system sends it), SIGINT to mpirun
#    (Open MPI sends the ranks SIGTERM after 1 s, SIGKILL 1 s later), and
#    SIGINT to a single process: the run stops after the realizations under
#    way with exit status 128 + signal (mpirun's own status when mpirun was
#    signalled), summary.json "interrupted" and no temporary file; the same
#    command then ends with the realizations and summary of an uninterrupted run;
#  - subset: exit status 130, "interrupted", no estimate;
#  - fragility: the same, the levels done, and resumed as uninterrupted.
set -eu
poundfe=$1 mpirun=$2 input=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
trap 'pkill -9 -f "$work" 2> /dev/null || true; rm -rf "$work"' EXIT
. "$(dirname "$0")/helpers.sh"
# without job control, a script's background jobs ignore SIGINT
set -m

# 100 realizations of 3 s of motion (~0.05 s each); fragility: 2 x 30
sed 's/set Realizations   = 8/set Realizations   = 100/; s/set Duration    = 8/set Duration    = 3/
     s/set Rise end    = 2/set Rise end    = 0.5/; s/set Plateau end = 5/set Plateau end = 2/
     s/set Realizations per level = 4/set Realizations per level = 30/
     s/set Samples per level = 20/set Samples per level = 40/' "$input" > "$work/short.prm"
"$poundfe" montecarlo "$work/short.prm" --output "$work/reference" > /dev/null
"$poundfe" fragility "$work/short.prm" --output "$work/fragility-reference" > /dev/null
"$poundfe" subset "$work/short.prm" --output "$work/subset-reference" > /dev/null

# pid of MPI rank $2 of the run writing to $1
rank_pid() {
  local p
  for p in $(pgrep -f -- "--output $1\$"); do
    if [ "$(tr '\0' '\n' < "/proc/$p/environ" 2> /dev/null | sed -n 's/^OMPI_COMM_WORLD_RANK=//p')" = "$2" ]; then
      echo "$p"
      return
    fi
  done
  fail "no rank $2 writing to $1"
}
# directory expected-status status: stopped early, cleanly
check_interrupted() {
  [ "$3" -eq "$2" ] || fail "$1: exit status $3 instead of $2: $(cat "$1.log")"
  [ -f "$1/summary.json" ] || fail "$1: no summary.json: $(cat "$1.log")"
  grep -q '"status": "interrupted"' "$1/summary.json" ||
    fail "$1: not interrupted (the test came too late?): $(grep '"status"' "$1/summary.json")"
  [ -z "$(find "$1" -name '*.tmp')" ] || fail "$1: temporary files left: $(find "$1" -name '*.tmp')"
}
# directory [mpirun -np 2]: started again, the run ends as the reference
check_resumed() {
  local d=$1
  shift
  "$@" "$poundfe" montecarlo "$work/short.prm" --output "$d" > "$d.resumed.log"
  grep -q "resuming: " "$d.resumed.log" || fail "$d: did not resume: $(cat "$d.resumed.log")"
  [ -z "$(rows "$d/realizations.csv" | cut -d, -f1 | uniq -d)" ] || fail "$d: duplicated realizations"
  diff <(rows "$work/reference/realizations.csv") <(rows "$d/realizations.csv") > /dev/null ||
    fail "$d: the realizations differ from an uninterrupted run"
  same_summary "$work/reference/summary.json" "$d/summary.json" "$d: summary differs from an uninterrupted run"
}
# name signal-target expected-status: a two-rank montecarlo run stopped once 4 rows are in
montecarlo_case() {
  local d=$work/$1 status=0
  "$mpirun" -np 2 "$poundfe" montecarlo "$work/short.prm" --output "$d" > "$d.log" 2>&1 &
  local job=$!
  wait_for_rows "$d/realizations.csv" 4
  case $2 in
    rank-0) kill -INT "$(rank_pid "$d" 0)" ;;
    ranks) kill -TERM "$(rank_pid "$d" 0)" "$(rank_pid "$d" 1)" ;;
    mpirun) kill -INT "$job" ;;
  esac
  wait "$job" 2> /dev/null || status=$?
  check_interrupted "$d" "$3" "$status"
  echo "$(($(wc -l < "$d/realizations.csv") - 1))"
}

n=$(montecarlo_case sigint-rank-0 rank-0 130)
check_resumed "$work/sigint-rank-0" "$mpirun" -np 2
echo "ok   montecarlo -np 2, SIGINT to rank 0: stopped at $n of 100 (exit status 130), resumed on 2 ranks as uninterrupted"
n=$(montecarlo_case sigterm-ranks ranks 143)
check_resumed "$work/sigterm-ranks"
echo "ok   montecarlo -np 2, SIGTERM to both ranks: stopped at $n of 100 (exit status 143), resumed on 1 rank as uninterrupted"
n=$(montecarlo_case sigint-mpirun mpirun 1)
check_resumed "$work/sigint-mpirun" "$mpirun" -np 2
echo "ok   montecarlo -np 2, SIGINT to mpirun: stopped at $n of 100, resumed as uninterrupted"

d=$work/single status=0
"$poundfe" montecarlo "$work/short.prm" --output "$d" > "$d.log" 2>&1 &
job=$!
wait_for_rows "$d/realizations.csv" 4
kill -INT "$job"
wait "$job" 2> /dev/null || status=$?
check_interrupted "$d" 130 "$status"
grep -q "Monte Carlo interrupted after" "$d.log" || fail "single: no message: $(cat "$d.log")"
echo "ok   montecarlo, one process, SIGINT: exit status 130, interrupted"

d=$work/subset status=0
"$poundfe" subset "$work/short.prm" --output "$d" > "$d.log" 2>&1 &
job=$!
# the output directory appears after the set-up, when the handlers are in place
for _ in $(seq 1 1500); do [ -d "$d" ] && break; sleep 0.02; done
sleep 2.5 # into level 1 usually (level 0: 40 runs of ~0.05 s)
kill -INT "$job"
wait "$job" 2> /dev/null || status=$?
check_interrupted "$d" 130 "$status"
grep -q '"failure_probability"' "$d/summary.json" && fail "subset: an estimate though interrupted"
[ -f "$d/subset_levels.csv" ] || fail "subset: no subset_levels.csv"
echo "ok   subset, SIGINT: exit status 130, interrupted after $(($(wc -l < "$d/subset_levels.csv") - 1)) levels"
# resumed on two ranks from the journal of the runs done: the estimate and
# every level of the uninterrupted one-rank run, to the last digit
[ "$(($(wc -l < "$d/subset_runs.csv") - 2))" -gt 0 ] || fail "subset: no runs in subset_runs.csv"
"$mpirun" -np 2 "$poundfe" subset "$work/short.prm" --output "$d" > "$d.resumed.log" 2>&1 ||
  fail "subset: the resumed run failed: $(cat "$d.resumed.log")"
grep -q "resuming: " "$d.resumed.log" || fail "subset: did not resume: $(cat "$d.resumed.log")"
diff "$work/subset-reference/subset_levels.csv" "$d/subset_levels.csv" > /dev/null ||
  fail "subset: resumed levels differ from uninterrupted"
for key in failure_probability coefficient_of_variation coefficient_of_variation_upper_bound; do
  [ "$(grep "\"$key\"" "$d/summary.json")" = "$(grep "\"$key\"" "$work/subset-reference/summary.json")" ] ||
    fail "subset: resumed $key differs from uninterrupted"
done
resumed=$(sed -n 's/.*"resumed_model_runs": \([0-9]*\).*/\1/p' "$d/summary.json")
[ "${resumed:-0}" -gt 0 ] || fail "subset: no resumed model runs in summary.json"
[ -z "$(find "$d" -name 'subset_runs.rank*')" ] || fail "subset: rank journals left after the end"
echo "ok   subset resumed on 2 ranks ($resumed model runs from the journal): the levels and estimate of an uninterrupted run"

d=$work/fragility status=0
"$poundfe" fragility "$work/short.prm" --output "$d" > "$d.log" 2>&1 &
job=$!
wait_for_rows "$d/pga_0.3g/realizations.csv" 3
kill -INT "$job"
wait "$job" 2> /dev/null || status=$?
check_interrupted "$d" 130 "$status"
grep -q '"completed_levels": 1' "$d/summary.json" || fail "fragility: not one level done"
[ "$(wc -l < "$d/fragility_points.csv")" -eq 2 ] || fail "fragility: not the points of one level"
"$poundfe" fragility "$work/short.prm" --output "$d" > "$d.resumed.log"
same_summary "$work/fragility-reference/summary.json" "$d/summary.json" "fragility: resumed differs from uninterrupted"
diff "$work/fragility-reference/fragility_points.csv" "$d/fragility_points.csv" > /dev/null ||
  fail "fragility: resumed points differ from uninterrupted"
echo "ok   fragility, SIGINT in the second level: exit status 130, one level done, resumed as uninterrupted"

# run: a long free vibration after the motion, stopped with SIGINT after a
# second: the loop stops at the end of a step, every file is complete and
# the time series end at the summary's end time.
d=$work/run status=0
sed 's/^subsection Time integration/subsection Time integration\n  set End time = 2000/
     s/set VTU interval *= .*/set VTU interval = 0/; s/set Output interval *= .*/set Output interval = 0.1/' \
  "$input" > "$work/long.prm"
grep -q "End time = 2000" "$work/long.prm" || fail "run: could not make the long input"
"$poundfe" run "$work/long.prm" --output "$d" > "$d.log" 2>&1 &
job=$!
for _ in $(seq 1 1500); do [ -d "$d" ] && break; sleep 0.02; done
sleep 1
kill -INT "$job"
wait "$job" 2> /dev/null || status=$?
check_interrupted "$d" 130 "$status"
end=$(sed -n 's/.*"end_time_s": \([0-9.e+-]*\).*/\1/p' "$d/summary.json")
last=$(tail -n 1 "$d/drift.csv" | cut -d, -f1)
awk -v e="$end" 'BEGIN { exit !(e > 0 && e < 2000) }' || fail "run: end time $end"
# the last row is at the last output time before the end
awk -v e="$end" -v l="$last" 'BEGIN { exit !(l <= e && e - l < 0.1 + 1e-9) }' || fail "run: last row at $last, end $end"
grep -q "interrupted at t = " "$d.log" || fail "run: no message: $(cat "$d.log")"
echo "ok   run, SIGINT: exit status 130, interrupted at t = $end s, files complete"
