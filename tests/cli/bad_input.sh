#!/usr/bin/env bash
# Every bad-input class: exit status 1, one message naming the file and what
# was wrong (the '# expect:' line of each file), and no output directory.
# A missing parameter file, and numerical failures (exit 2), as well.
# A file's '# command:' line names the command to run it with (run by default).
set -u
poundfe=$1
dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
check() { # file expected_status expected_text [more expected texts]
  local file=$1 status=$2 out="$work/out" command text
  shift 2
  command=$(sed -n 's/^# command: //p' "$file" 2> /dev/null)
  rm -rf "$out"
  "$poundfe" "${command:-run}" "$file" --output "$out" > "$work/stdout" 2> "$work/stderr"
  local got=$?
  local message
  message=$(cat "$work/stderr")
  if [ "$got" -ne "$status" ]; then
    echo "FAIL $file: exit $got, expected $status: $message"; failures=$((failures + 1)); return
  fi
  for text in "$@"; do
    if ! grep -qF -- "$text" "$work/stderr"; then
      echo "FAIL $file: message lacks '$text': $message"; failures=$((failures + 1)); return
    fi
  done
  if [ "$(wc -l < "$work/stderr")" -ne 1 ]; then
    echo "FAIL $file: expected one line of message: $message"; failures=$((failures + 1)); return
  fi
  if [ "$status" -eq 1 ] && [ -e "$out" ]; then
    echo "FAIL $file: output written despite bad input"; failures=$((failures + 1)); return
  fi
  echo "ok   $(basename "$file"): $message"
}
n=0
for file in "$dir"/*.prm; do
  expected=$(sed -n '1s/^# expect: //p' "$file")
  # One run: the message names the file and says what was wrong (a run of
  # poundfe costs ~0.4 s of start-up alone, so each file is run once).
  check "$file" 1 "$expected" "$(basename "$file")"
  n=$((n + 1))
done
check "$dir/does-not-exist.prm" 1 "cannot open the parameter file"
check "$dir/../mechanism.prm" 2 "singular"
check "$dir/../newton-failure.prm" 2 "failed even at dt"
for f in summary.json hinges.csv energy.csv drift.csv; do
  [ -s "$work/out/$f" ] || { echo "FAIL newton-failure: results so far not kept ($f)"; failures=$((failures + 1)); }
done
grep -q '"status": "failed"' "$work/out/summary.json" || { echo "FAIL newton-failure: status"; failures=$((failures + 1)); }
# forces whose squares overflow: a failure naming the quantity, not exit 0 with zeros
check "$dir/../overflowing-forces.prm" 2 "failed even at dt" "from t = 0 s" "is not finite (inf)"
[ -s "$work/out/summary.json" ] || { echo "FAIL overflowing-forces: results so far not kept"; failures=$((failures + 1)); }
check "$dir/../reliability-form-failure.prm" 2 "its gradient is zero at the start"
grep -q '"status": "failed"' "$work/out/summary.json" || { echo "FAIL reliability-form-failure: status"; failures=$((failures + 1)); }
echo "$n bad-input files, $failures failures"
[ "$failures" -eq 0 ]
