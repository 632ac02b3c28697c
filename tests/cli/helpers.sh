# Shell helpers of the command-line tests (montecarlo.sh, interrupt.sh,
# links.sh, soil.sh, ...); source after setting $work, a scratch directory.
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
# Every numeric cell of two CSV files with the same header agrees to $3
# relative to its column's largest finite magnitude; text cells are equal. A
# NaN in either file fails (it would compare as nothing), an infinity must
# be the same infinity in both.
same_csv() {
  python3 - "$1" "$2" "$3" <<'PY'
import csv, math, sys
a, b = (list(csv.reader(open(p))) for p in sys.argv[1:3])
tolerance = float(sys.argv[3])
if a[0] != b[0] or len(a) != len(b):
    sys.exit(f"different columns or rows: {sys.argv[1]} {sys.argv[2]}")
worst = 0.0
for j in range(len(a[0])):
    try:
        x = [float(r[j]) if r[j] else 0.0 for r in a[1:]]
        y = [float(r[j]) if r[j] else 0.0 for r in b[1:]]
    except ValueError:
        if [r[j] for r in a[1:]] != [r[j] for r in b[1:]]:
            sys.exit(f"column {a[0][j]} differs")
        continue
    if any(math.isnan(v) for v in x + y):
        sys.exit(f"column {a[0][j]}: NaN")
    if any((math.isinf(u) or math.isinf(v)) and u != v for u, v in zip(x, y)):
        sys.exit(f"column {a[0][j]}: an infinity differs")
    scale = max([abs(v) for v in x if math.isfinite(v)] + [1e-300])
    worst = max([worst] + [abs(u - v) / scale for u, v in zip(x, y) if math.isfinite(u)])
print(f"largest relative difference {worst:.3g}")
sys.exit(0 if worst <= tolerance else 1)
PY
}
# FILE with "set NAME = VALUE" lines ("NAME = VALUE; ...") added to its
# Time integration section
with() {
  local lines
  lines=$(echo "$2" | tr ';' '\n' | sed 's/^ *//; /^$/d; s/^/  set /' | sed ':a;N;$!ba;s/\n/\\n/g')
  sed "/^subsection Time integration/a\\$lines" "$1"
}
