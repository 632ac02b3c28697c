#!/usr/bin/env bash
# ida on two ranks stopped while its runs are dealt:
#  - SIGINT to rank 0 only (it stops dealing and tells the worker), and
#    SIGINT to rank 1 only (the worker stops on its own and tells rank 0):
#    exit status 130, summary.json "interrupted", no temporary file, every
#    run journaled once;
#  - the same command on two ranks then runs only the rest and ends with the
#    ida.csv of an uninterrupted run on one rank.
set -eu
poundfe=$1 mpirun=$2 example=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export POUNDFE_PROGRESS=0
work=$(mktemp -d)
trap 'pkill -9 -f "$work" 2> /dev/null || true; rm -rf "$work"' EXIT
. "$(dirname "$0")/helpers.sh"
# without job control, a script's background jobs ignore SIGINT
set -m

short=(--set "Ground motion/Stochastic/Duration=6" --set "IDA/Runs per record=10"
       --set "IDA/Tolerance=0.1" --set "Output/Plots=false")
"$poundfe" ground-motion "$example" --realizations 8 --write-at2 --output "$work/gen" \
  "${short[@]}" > /dev/null
options=("${short[@]}" --set "IDA/Suite=$work/gen/records/suite.csv")
"$poundfe" ida "$example" --output "$work/reference" "${options[@]}" > /dev/null

# pid of MPI rank $2 of the run writing to $1
rank_pid() {
  local p
  for p in $(pgrep -f -- "--output $1 "); do
    if [ "$(tr '\0' '\n' < "/proc/$p/environ" 2> /dev/null | sed -n 's/^OMPI_COMM_WORLD_RANK=//p')" = "$2" ]; then
      echo "$p"
      return
    fi
  done
  fail "no rank $2 writing to $1"
}
# name rank: a two-rank ida stopped by SIGINT to that rank once 6 runs are in
ida_case() {
  local d=$work/$1 status=0
  "$mpirun" -np 2 "$poundfe" ida "$example" --output "$d" "${options[@]}" > "$d.log" 2>&1 &
  local job=$!
  wait_for_rows "$d/journal/realizations.csv" 6
  kill -INT "$(rank_pid "$d" "$2")"
  wait "$job" 2> /dev/null || status=$?
  [ "$status" -eq 130 ] || fail "$1: exit status $status instead of 130: $(cat "$d.log")"
  grep -q '"status": "interrupted"' "$d/summary.json" ||
    fail "$1: not interrupted (the test came too late?): $(grep '"status"' "$d/summary.json")"
  [ -z "$(find "$d" -name '*.tmp')" ] || fail "$1: temporary files left"
  [ -z "$(rows "$d/journal/realizations.csv" | cut -d, -f1 | uniq -d)" ] || fail "$1: a run journaled twice"
  local done_before=$(($(wc -l < "$d/journal/realizations.csv") - 1))
  "$mpirun" -np 2 "$poundfe" ida "$example" --output "$d" "${options[@]}" > "$d.resumed.log" 2>&1 ||
    fail "$1: resumed: $(cat "$d.resumed.log")"
  grep -q '"status": "completed"' "$d/summary.json" || fail "$1: the resumed run did not complete"
  cmp -s "$work/reference/ida.csv" "$d/ida.csv" || fail "$1: ida.csv differs from an uninterrupted run"
  echo "ok   ida -np 2, SIGINT to rank $2: stopped after $done_before runs (exit status 130), resumed on 2 ranks as uninterrupted"
}
ida_case sigint-rank-0 0
ida_case sigint-rank-1 1
