#!/usr/bin/env bash
# Monte Carlo, Subset Simulation and fragility from the command line:
#  - one rank and two (mpirun -np 2) give the same realizations and numbers;
#  - a run killed (SIGKILL, every process) while it runs and started again
#    completes without losing or duplicating a realization, to the same numbers;
#  - Subset Simulation and fragility on two ranks equal one rank;
#  - ground-motion --realizations writes the samples and the ensemble PSD;
#  - command-specific bad input: exit 1, one message, nothing written;
#  - a directory's realizations.csv or subset journal of another seed or
#    model (or without the record of its input) is refused, not resumed.
set -eu
poundfe=$1 mpirun=$2 input=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
trap 'pkill -9 -f "$work" 2> /dev/null || true; rm -rf "$work"' EXIT
. "$(dirname "$0")/helpers.sh"

"$poundfe" montecarlo "$input" --output "$work/one" > /dev/null
"$mpirun" -np 2 "$poundfe" montecarlo "$input" --output "$work/two" > /dev/null
n=$(rows "$work/one/realizations.csv" | wc -l)
[ "$n" -eq 8 ] || fail "montecarlo: $n realizations instead of 8"
diff <(rows "$work/one/realizations.csv") <(rows "$work/two/realizations.csv") > /dev/null ||
  fail "montecarlo: the realizations differ between 1 and 2 ranks"
same_summary "$work/one/summary.json" "$work/two/summary.json" "montecarlo: summary differs between 1 and 2 ranks"
for f in pdf_max_drift_ratio.csv cdf_max_drift_ratio.csv pdf_peak_contact_force.csv cdf_min_clearance.csv; do
  [ -s "$work/one/$f" ] || fail "montecarlo: no $f"
done
grep -q '"pounding"' "$work/one/summary.json" || fail "montecarlo: no pounding probability"
echo "ok   montecarlo: -np 2 gives the realizations and summary of one rank"

# Kill every process of a two-rank run of 20 realizations once two are in,
# then resume; compare with an uninterrupted one-rank run.
sed 's/set Realizations   = 8/set Realizations   = 20/' "$input" > "$work/twenty.prm"
"$poundfe" montecarlo "$work/twenty.prm" --output "$work/twenty" > /dev/null
"$mpirun" -np 2 "$poundfe" montecarlo "$work/twenty.prm" --output "$work/killed" > "$work/killed.log" 2>&1 &
wait_for_rows "$work/killed/realizations.csv" 2
pkill -9 -f "$work/killed" || true
{ wait; } 2> /dev/null || true
before=$(($(wc -l < "$work/killed/realizations.csv") - 1))
[ -e "$work/killed/summary.json" ] && fail "resume: the kill came after the end (test too slow to kill)"
# as if the kill had cut a row in the middle: the resumed run must drop it
printf '19,2026,1,0.0123' >> "$work/killed/realizations.csv"
"$poundfe" montecarlo "$work/twenty.prm" --output "$work/killed" > "$work/resumed.log"
grep -q "resuming: $before of 20" "$work/resumed.log" || fail "resume: did not resume from $before rows: $(cat "$work/resumed.log")"
[ -z "$(rows "$work/killed/realizations.csv" | cut -d, -f1 | uniq -d)" ] || fail "resume: duplicated realizations"
[ "$(rows "$work/killed/realizations.csv" | wc -l)" -eq 20 ] || fail "resume: not 20 realizations"
diff <(rows "$work/twenty/realizations.csv") <(rows "$work/killed/realizations.csv") > /dev/null ||
  fail "resume: the realizations differ from an uninterrupted run"
same_summary "$work/twenty/summary.json" "$work/killed/summary.json" "resume: summary differs from an uninterrupted run"
echo "ok   montecarlo: killed after $before of 20 realizations, resumed to the same results"

"$poundfe" subset "$input" --output "$work/subset-one" > /dev/null
"$mpirun" -np 2 "$poundfe" subset "$input" --output "$work/subset-two" > /dev/null
same_summary "$work/subset-one/summary.json" "$work/subset-two/summary.json" "subset: differs between 1 and 2 ranks"
grep -q '"failure_probability"' "$work/subset-one/summary.json" || fail "subset: no estimate"
echo "ok   subset: -np 2 gives the estimate of one rank"

"$poundfe" fragility "$input" --output "$work/fragility-one" > /dev/null
"$mpirun" -np 2 "$poundfe" fragility "$input" --output "$work/fragility-two" > /dev/null
same_summary "$work/fragility-one/summary.json" "$work/fragility-two/summary.json" "fragility: differs between 1 and 2 ranks"
diff "$work/fragility-one/fragility_points.csv" "$work/fragility-two/fragility_points.csv" > /dev/null ||
  fail "fragility: counts differ between 1 and 2 ranks"
[ -s "$work/fragility-one/fragility_curves.csv" ] || fail "fragility: no curves"
echo "ok   fragility: -np 2 gives the curves of one rank"

"$poundfe" ground-motion "$input" --realizations 4 --output "$work/gm" > /dev/null
[ "$(head -1 "$work/gm/ground_motion_samples.csv" | tr ',' '\n' | wc -l)" -eq 5 ] || fail "ground-motion: not 4 sample columns"
[ "$(wc -l < "$work/gm/ensemble_psd.csv")" -gt 50 ] || fail "ground-motion: short ensemble PSD"
echo "ok   ground-motion --realizations"

# Bad input of the probabilistic commands.
expect_bad() { # expected-text command args...
  local text=$1
  shift
  rm -rf "$work/bad"
  if "$@" --output "$work/bad" > /dev/null 2> "$work/stderr"; then fail "$* succeeded"; fi
  local status=$?
  grep -qF -- "$text" "$work/stderr" || fail "$*: message lacks '$text': $(cat "$work/stderr")"
  [ "$(wc -l < "$work/stderr")" -eq 1 ] || fail "$*: not one line: $(cat "$work/stderr")"
  [ -e "$work/bad" ] && fail "$*: output written despite bad input"
  echo "ok   bad input: $(cat "$work/stderr")"
}
sed 's/set Type = kanai-tajimi/set Type = none/' "$input" > "$work/no-random.prm"
expect_bad "needs random loading" "$poundfe" montecarlo "$work/no-random.prm"
sed 's/set Type = kanai-tajimi/set Type = white-noise/; s/set Target PGA  = 0.35/set S0 = 0.01/' "$input" > "$work/white.prm"
expect_bad "scale a Kanai-Tajimi or Clough-Penzien" "$poundfe" fragility "$work/white.prm"
expect_bad "needs a whole number" "$poundfe" ground-motion "$input" --realizations 0
# a results directory of another seed is not silently mixed in
sed 's/set Seed        = 2026/set Seed        = 7/' "$input" > "$work/other-seed.prm"
if "$poundfe" montecarlo "$work/other-seed.prm" --output "$work/one" > /dev/null 2> "$work/stderr"; then
  fail "montecarlo: resumed a directory of another seed"
fi
grep -q "Stochastic/Seed': holds realizations computed with '2026'; the input now gives '7'" "$work/stderr" ||
  fail "montecarlo: other seed: $(cat "$work/stderr")"
echo "ok   bad input: $(cat "$work/stderr")"
# nor one of another model (before: resumed, its rows mixed with the new
# model's), and the table it holds stays as it was
cp "$work/one/realizations.csv" "$work/one-rows.csv"
sed 's/set Column E          = 3.0e10/set Column E          = 3.3e10/' "$input" > "$work/stiffer.prm"
if "$poundfe" montecarlo "$work/stiffer.prm" --output "$work/one" > /dev/null 2> "$work/stderr"; then
  fail "montecarlo: resumed a directory of another model"
fi
grep -q "Building 1/Column E': holds realizations computed with '3.0e10'; the input now gives '3.3e10'" "$work/stderr" ||
  fail "montecarlo: other model: $(cat "$work/stderr")"
[ "$(wc -l < "$work/stderr")" -eq 1 ] || fail "montecarlo: other model: not one line"
cmp -s "$work/one/realizations.csv" "$work/one-rows.csv" || fail "montecarlo: other model: realizations.csv changed"
echo "ok   bad input: $(cat "$work/stderr")"
# more realizations of the same model resume; a table without its record does not
sed 's/set Realizations   = 8/set Realizations   = 9/' "$input" > "$work/nine.prm"
"$poundfe" montecarlo "$work/nine.prm" --output "$work/one" > "$work/nine.log"
grep -q "resuming: 8 of 9" "$work/nine.log" || fail "montecarlo: more realizations: $(cat "$work/nine.log")"
echo "ok   montecarlo: Realizations 8 -> 9 resumes from the 8"
rm "$work/one/realizations.csv.inputs"
if "$poundfe" montecarlo "$work/nine.prm" --output "$work/one" > /dev/null 2> "$work/stderr"; then
  fail "montecarlo: resumed a table without its record"
fi
grep -q "left no record of its input (realizations.csv.inputs)" "$work/stderr" ||
  fail "montecarlo: no record: $(cat "$work/stderr")"
echo "ok   bad input: $(cat "$work/stderr")"
# the record and the table are read as any input (issue 28 class 1): a FIFO
# in their place is refused at once (before: the read waited for a writer)
for fifo in realizations.csv.inputs realizations.csv; do
  "$poundfe" montecarlo "$input" --output "$work/fifo" > /dev/null
  rm "$work/fifo/$fifo" && mkfifo "$work/fifo/$fifo"
  if timeout 60 "$poundfe" montecarlo "$input" --output "$work/fifo" > /dev/null 2> "$work/stderr"; then
    fail "montecarlo: read a FIFO as $fifo"
  fi
  grep -q "$fifo.*is a named pipe (FIFO), not a regular file" "$work/stderr" ||
    fail "montecarlo: FIFO as $fifo: $(cat "$work/stderr")"
  echo "ok   bad input: $(cat "$work/stderr")"
  rm -r "$work/fifo"
done
# the subset journal likewise
if "$poundfe" subset "$work/stiffer.prm" --output "$work/subset-one" > /dev/null 2> "$work/stderr"; then
  fail "subset: resumed the journal of another model"
fi
grep -q "subset_runs.csv.*Building 1/Column E': holds realizations computed with '3.0e10'" "$work/stderr" ||
  fail "subset: other model: $(cat "$work/stderr")"
echo "ok   bad input: $(cat "$work/stderr")"
# the journal synced in groups, every half second and at the end, not once a
# row: 200 short realizations on one rank call fdatasync at most once per
# half second of the run plus a few (the journal's record, the end); a row
# per sync would be 200. The kill-and-resume above checks the rows that a
# group leaves unsynced survive a killed process (they are written at once).
# The grouped syncs run on a thread of their own (append_file.h): of the
# journal's syncs the main thread (its id is the process's, execve's line)
# makes at most one, the last, so no realization waits on the disk.
if command -v strace > /dev/null; then
  sed -e 's/set Realizations   = 8/set Realizations   = 200/' -e 's/set Duration    = 8/set Duration    = 0.5/' \
    "$input" > "$work/many.prm"
  strace -f -qq -y -e trace=fdatasync,execve -o "$work/syncs" "$poundfe" montecarlo "$work/many.prm" \
    --output "$work/many" --set Output/Plots=false > /dev/null || fail "montecarlo of 200 realizations"
  syncs=$(grep -c fdatasync "$work/syncs" || true)
  main=$(awk '/execve/ { print $1; exit }' "$work/syncs")
  journal_syncs=$(grep -c 'fdatasync([0-9]*<[^>]*realizations.csv>' "$work/syncs" || true)
  main_syncs=$(grep 'fdatasync([0-9]*<[^>]*realizations.csv>' "$work/syncs" | awk -v m="$main" '$1 == m' | wc -l)
  # at least the end's sync; a group's comes only after half a second of
  # rows, which a fast machine may not take (then the check below is met
  # whichever thread syncs, but with a sync per group on the main thread,
  # as before, any run of two syncs or more fails it)
  [ "$journal_syncs" -ge 1 ] || fail "journal: never synced (the end's sync at least)"
  [ "$main_syncs" -le 1 ] || fail "journal: $main_syncs of its $journal_syncs syncs on the main thread (at most the last)"
  rows=$(($(wc -l < "$work/many/realizations.csv") - 1))
  bound=$(python3 -c "import json; print(int(2 * json.load(open('$work/many/summary.json'))['wall_time_s']) + 5)")
  [ "$rows" -eq 200 ] || fail "journal: $rows rows of 200"
  [ "$syncs" -le "$bound" ] || fail "journal: $syncs syncs for $rows rows (at most $bound)"
  echo "ok   montecarlo journal: $rows rows, $syncs syncs (at most $bound), $main_syncs of the journal's $journal_syncs on the main thread"
else
  echo "skip the journal's syncs: no strace"
fi
