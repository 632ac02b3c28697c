#!/usr/bin/env bash
# The comparison helpers of the command-line tests fail on what they cannot
# compare: same_csv (helpers.sh) and same_columns.py given a column of NaN,
# a single NaN, or an infinity against a number, in either file, exit
# non-zero; equal files, and files within the tolerance, pass. A NaN
# compares as nothing in Python (max() skips it), so a helper that did not
# look for it passed two files whose numbers were all NaN.
#   comparison_helpers.sh   (no arguments)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$here/helpers.sh"

printf 'time,a,b\n0,1,2\n1,3,4\n2,5,-6\n' > "$work/good.csv"
printf 'time,a,b\n0,1,2\n1,3,4\n2,5,-6.0000000001\n' > "$work/close.csv"
printf 'time,a,b\n0,1,nan\n1,3,nan\n2,5,nan\n' > "$work/nan-column.csv"
printf 'time,a,b\n0,1,2\n1,nan,4\n2,5,-6\n' > "$work/nan-cell.csv"
printf 'time,a,b\n0,1,2\n1,3,inf\n2,5,-6\n' > "$work/inf-cell.csv"

passes() { # description, command...
  local what=$1; shift
  "$@" > "$work/log" 2>&1 || { cat "$work/log"; fail "$what: failed, should pass"; }
}
fails() {
  local what=$1; shift
  if "$@" > "$work/log" 2>&1; then cat "$work/log"; fail "$what: passed, should fail"; fi
}
columns() { python3 "$here/same_columns.py" "$1" "$2" 1 1e-8; }

passes "same_csv, equal files" same_csv "$work/good.csv" "$work/good.csv" 1e-12
passes "same_csv, within 1e-8" same_csv "$work/good.csv" "$work/close.csv" 1e-8
passes "same_columns.py, equal files" columns "$work/good.csv" "$work/good.csv"
passes "same_columns.py, within 1e-8" columns "$work/good.csv" "$work/close.csv"
printf 'time,a,b\n0,-1,-2\n1,-3,-4\n2,-5,6\n' > "$work/negated.csv"
passes "same_columns.py, sign -1" python3 "$here/same_columns.py" "$work/good.csv" \
  "$work/negated.csv" -1 1e-12
for bad in nan-column nan-cell inf-cell; do
  fails "same_csv, $bad against numbers" same_csv "$work/good.csv" "$work/$bad.csv" 1e-8
  fails "same_csv, numbers against $bad" same_csv "$work/$bad.csv" "$work/good.csv" 1e-8
  fails "same_columns.py, $bad against numbers" columns "$work/good.csv" "$work/$bad.csv"
  fails "same_columns.py, numbers against $bad" columns "$work/$bad.csv" "$work/good.csv"
done
fails "same_csv, NaN against NaN" same_csv "$work/nan-column.csv" "$work/nan-column.csv" 1e-8
fails "same_columns.py, NaN against NaN" columns "$work/nan-column.csv" "$work/nan-column.csv"
grep -q "column b: NaN" <(same_csv "$work/good.csv" "$work/nan-column.csv" 1e-8 2>&1 || true) ||
  fail "same_csv: the message does not name the NaN column"
echo "ok   same_csv and same_columns.py: NaN and a differing infinity fail, equal files pass"
