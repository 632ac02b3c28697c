# Shell helpers of the probabilistic command-line tests (montecarlo.sh,
# interrupt.sh); source after setting $work, a scratch directory.
fail() { echo "FAIL $*"; exit 1; }
# summary.json without what depends on the number of ranks or the clock
strip() { grep -v -e wall_time -e realizations_per_second -e samples_per_second -e '"ranks"' -e realizations_run_now "$1"; }
same_summary() {
  diff <(strip "$1") <(strip "$2") > "$work/diff" || { head "$work/diff"; fail "$3"; }
}
# the data rows of realizations.csv, by realization
rows() { tail -n +2 "$1" | sort -t, -k1,1n; }
# waits (up to 30 s) until realizations.csv $1 has $2 rows
wait_for_rows() {
  for _ in $(seq 1 1500); do
    [ -f "$1" ] && [ "$(($(wc -l < "$1") - 1))" -ge "$2" ] && return 0
    sleep 0.02
  done
  fail "no $2 rows in $1 after 30 s"
}
