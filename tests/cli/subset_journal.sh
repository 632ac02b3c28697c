#!/usr/bin/env bash
# The journal of Subset Simulation's model runs (subset_runs.csv,
# reliability/subset_journal.h) is read on resume by the bounded reader of
# every input file (base/input_text.h). A damaged or hostile journal is bad
# input: exit 1 with one line naming the file, the line and what is wrong,
# never a crash, a hang or runs silently dropped. Only the last line cut by
# a kill (no newline) is dropped, and the run resumes.
#   subset_journal.sh POUNDFE MONTECARLO_SMALL_PRM
set -u
poundfe=$1
input=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
n=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

# 3 levels of 40 samples of 3 s of motion (as cli/interrupt)
sed 's/set Duration    = 8/set Duration    = 3/; s/set Rise end    = 2/set Rise end    = 0.5/
     s/set Plateau end = 5/set Plateau end = 2/
     s/set Samples per level = 20/set Samples per level = 40/' "$input" > short.prm
"$poundfe" subset short.prm --output out > reference.log 2>&1 || { echo "FAIL reference run: $(tail -3 reference.log)"; exit 1; }
[ -f out/subset_runs.csv ] || { echo "FAIL no subset_runs.csv after the reference run"; exit 1; }
cp out/subset_runs.csv journal.csv
cp out/subset_runs.csv.inputs record.txt # the input the journal is of (output_directory.h)
runs=$(($(wc -l < journal.csv) - 2))
[ "$runs" -gt 10 ] || { echo "FAIL only $runs runs in the journal"; exit 1; }

# journal FILE STATUS TEXT: subset resumes from FILE (as out/subset_runs.csv);
# exit STATUS, TEXT in its messages, one line on stderr when it fails
journal() {
  local file=$1 status=$2 text=$3 got=0
  n=$((n + 1))
  rm -rf out && mkdir out
  if [ -d "$file" ]; then mkdir out/subset_runs.csv; else cp "$file" out/subset_runs.csv; fi
  cp record.txt out/subset_runs.csv.inputs
  timeout -k 5 120 "$poundfe" subset short.prm --output out > stdout 2> stderr || got=$?
  if [ "$got" -ne "$status" ]; then
    fail "$file: exit $got, expected $status: $(head -c 300 stderr)"; return
  fi
  grep -qF -- "$text" stderr stdout || { fail "$file: no '$text' in: $(head -c 300 stderr stdout)"; return; }
  if [ "$status" -ne 0 ] && [ "$(wc -l < stderr)" -ne 1 ]; then
    fail "$file: expected one line: $(head -c 300 stderr)"; return
  fi
  echo "ok   $file: exit $got: $(head -c 240 stderr)$([ "$got" -eq 0 ] && grep -o 'resuming: [0-9]*' stdout)"
}

# the intact journal: every run resumed (the reference of the cases below)
journal journal.csv 0 "resuming: $runs"
# the last line cut by a kill: dropped, the rest resumed
{ cat journal.csv; printf '2,39,0.0'; } > cut.csv
journal cut.csv 0 "resuming: $runs"
# a line in the middle that is not a run: damaged, named by its line
sed '5s/.*/0,3,abc,1/' journal.csv > letters.csv
journal letters.csv 1 "subset_runs.csv:5: parameter 'Subset simulation': expected a model run 'level,sample,response,completed'"
sed '6s/^\([0-9]*,[0-9]*\),[^,]*,/\1,inf,/' journal.csv > infinite.csv
grep -q ',inf,' infinite.csv || fail "infinite.csv: no inf written"
journal infinite.csv 1 "subset_runs.csv:6: parameter 'Subset simulation': expected a model run"
sed '7s/,1$/,7/' journal.csv > completed.csv
journal completed.csv 1 "subset_runs.csv:7: parameter 'Subset simulation': expected a model run"
sed '8s/$/,1/' journal.csv > fields.csv
journal fields.csv 1 "subset_runs.csv:8: parameter 'Subset simulation': expected a model run"
sed '9s/^[0-9]*,/-1,/' journal.csv > negative.csv
journal negative.csv 1 "subset_runs.csv:9: parameter 'Subset simulation': expected a model run"
sed '2s/.*/level;sample;response;completed/' journal.csv > header.csv
journal header.csv 1 "subset_runs.csv:2: parameter 'Subset simulation': expected the header 'level,sample,response,completed'"
# hostile files: a NUL byte, a line of 2 MB, 1.1 GiB (sparse), a directory
{ head -4 journal.csv; printf '0,9,\0001,1\n'; } > nul.csv
journal nul.csv 1 "subset_runs.csv:5: parameter 'Subset simulation': a NUL byte (column 5): a binary file"
{ head -4 journal.csv; head -c 2000000 /dev/zero | tr '\0' '7'; echo; } > long.csv
journal long.csv 1 "subset_runs.csv:5: parameter 'Subset simulation': a line of 2000000 characters"
cp journal.csv huge.csv && truncate -s 1100M huge.csv
journal huge.csv 1 "more than the 1073741824 an input file may have"
mkdir directory.csv
journal directory.csv 1 "is a directory, not a Subset simulation journal"

echo "$n subset-journal cases, $failures failures"
[ "$failures" -eq 0 ]
