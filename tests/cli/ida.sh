#!/usr/bin/env bash
# ida (incremental dynamic analysis) and its record suites:
#  - ground-motion --realizations N --write-at2 writes a suite of generated
#    records; ida runs it (the example input, shortened by --set);
#  - each record's Sa(T) in ida_records.csv equals the spectrum command's
#    PSA of the same AT2 file at T (9 digits: both print 17, the numbers are
#    the same computation on the same samples; 1e-9 relative);
#  - one rank and two (mpirun -np 2) give the same ida.csv; a second run
#    into the same directory resumes from the journal and runs nothing; a
#    journal cut to half its runs and a partial line (a killed run) is
#    resumed on two ranks: only the missing runs run, the same ida.csv;
#  - the suite reader's bad input through the binary: exit 1, one line
#    naming the suite's file, line and field, nothing written;
#  - a JSON suite of one record gives the ida.csv of the CSV suite of it;
#  - a finished run resumed after its suite file changed: exit 1, the
#    message naming the suite and IDA/Suite, the journal untouched.
poundfe=$(realpath "$1") mpirun=$2 example=$(realpath "$3")
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
# shellcheck source=/dev/null
. "$here/expect.sh"
die() { echo "FAIL $*"; exit 1; }

short=(--set "Ground motion/Stochastic/Duration=4" --set "IDA/Runs per record=6"
       --set "IDA/Tolerance=0.2" --set "Output/Plots=false")
"$poundfe" ground-motion "$example" --realizations 3 --write-at2 --output gen "${short[@]}" > /dev/null ||
  die "ground-motion --write-at2"
[ -f gen/records/realization_2.AT2 ] && [ -f gen/records/suite.csv ] || die "no AT2 suite written"
cp "$example" ida.prm
suite=(--set "IDA/Suite=$work/gen/records/suite.csv")
"$poundfe" ida ida.prm --output one "${short[@]}" "${suite[@]}" > one.log || die "ida: $(cat one.log)"
for f in summary.json ida.csv ida_records.csv ida_fractiles.csv collapse_fragility.csv; do
  [ -f "one/$f" ] || die "ida wrote no $f"
done
grep -q '"collapse_fragility"' one/summary.json || die "no collapse fragility in summary.json"

# Sa(T) against the spectrum command on each record, at T = the IDA period
T=$(python3 -c "import json; print(json.load(open('one/summary.json'))['periods_s'][0])")
for r in 0 1 2; do
  "$poundfe" spectrum ida.prm --output "spectrum$r" --set "Ground motion/Type=record" \
    --set "Ground motion/Record/File=$work/gen/records/realization_$r.AT2" \
    --set "Spectrum/Minimum period=$T" --set "Spectrum/Maximum period=$T" \
    --set "Spectrum/Number of periods=1" --set "Output/Plots=false" > /dev/null || die "spectrum $r"
  python3 - "$r" "spectrum$r/spectrum.csv" one/ida_records.csv <<'PY' || die "Sa(T) of record $r"
import csv, sys
r, spectrum, records = int(sys.argv[1]), sys.argv[2], sys.argv[3]
psa = float(next(csv.DictReader(open(spectrum)))["psa_g_5pct"])
sa = float(list(csv.DictReader(open(records)))[r]["sa_g"])
if abs(sa - psa) > 1e-9 * psa:
    sys.exit(f"ida_records.csv Sa {sa} g, spectrum {psa} g")
print(f"record {r}: Sa {sa} g = spectrum's {psa} g")
PY
done

# two ranks: the same runs
"$mpirun" -np 2 "$poundfe" ida ida.prm --output two "${short[@]}" "${suite[@]}" > /dev/null ||
  die "ida on two ranks"
cmp one/ida.csv two/ida.csv || die "one rank and two give different ida.csv"
# resumed: nothing runs again, the same results
"$poundfe" ida ida.prm --output one "${short[@]}" "${suite[@]}" > again.log || die "resumed ida"
grep -q '"runs_now": 0' one/summary.json || die "a finished ida ran again: $(grep runs one/summary.json)"
cmp one/ida.csv two/ida.csv || die "the resumed run changed ida.csv"

# a killed run's journal (two ranks): a prefix of its runs and a partial
# line; the same command on two ranks runs only the missing runs
total=$(($(wc -l < two/journal/realizations.csv) - 1))
keep=$((total / 2))
head -n $((keep + 1)) two/journal/realizations.csv > cut.csv
printf '%s' "$(sed -n "$((keep + 2))p" two/journal/realizations.csv | cut -c1-12)" >> cut.csv
mv cut.csv two/journal/realizations.csv
"$mpirun" -np 2 "$poundfe" ida ida.prm --output two "${short[@]}" "${suite[@]}" > /dev/null ||
  die "ida resumed on two ranks"
grep -Eq "\"runs_now\": $((total - keep))([^0-9]|$)" two/summary.json ||
  die "resumed from $keep of $total runs: $(grep runs_now two/summary.json), expected $((total - keep))"
cmp one/ida.csv two/ida.csv || die "the run resumed on two ranks changed ida.csv"

# bad suites: file, line, field
at2=$work/gen/records/realization_0.AT2
printf 'NGA\nx\nACCELERATION IN G\nNPTS= 3, DT= 0.02 SEC\n0.1 0.2 0.1\n' > short.AT2
bad() { # bad NAME CONTENTS TEXT: a suite NAME with CONTENTS refused with TEXT
  printf '%b' "$2" > "$1"
  expect 1 "$3" ida ida.prm "${short[@]}" --set "IDA/Suite=$work/$1" --output out
}
bad missing.csv "name,file\na,$at2\nb,nowhere.AT2\n" "missing.csv:3: parameter 'file': record '$work/nowhere.AT2'"
bad scale.csv "file,scale\n$at2,0\n" "scale.csv:2: parameter 'scale': the scale factor of 'realization_0' must be positive"
bad negative.csv "file,scale\n$at2,-2\n" "negative.csv:2: parameter 'scale': the scale factor of 'realization_0' must be positive, got -2"
bad twice.csv "name,file\nx,$at2\nx,$at2\n" "twice.csv:3: parameter 'name': the name 'x' is given twice (also on line 2)"
bad pair.csv "file,file2\n$at2,$work/short.AT2\n" "pair.csv:2: parameter 'file2': the components of a pair must share their time step and length"
bad column.csv "file,depth\n$at2,3\n" "column.csv:1: parameter 'depth': not a column of a record suite"
bad nofile.csv "name,scale\na,1\n" "nofile.csv:1: parameter 'file': the header row has no 'file' column"
bad number.csv "file,scale\n$at2,two\n" "number.csv:2: parameter 'scale': expected a number, got 'two'"
bad fields.csv "file,scale\n$at2\n" "fields.csv:2: expected 2 fields as in the header, found 1"
bad empty.csv "file\n" "the suite lists no record"
bad json.json '{"records": [{"files": ["a", "b", "c"]}]}' "parameter 'records[0].files': expected one or two record files"
bad suite.txt "file\n$at2\n" "a record suite is a .csv or .json file or a folder"
mkdir -p emptyfolder
expect 1 "the folder holds no .AT2 file" ida ida.prm "${short[@]}" --set "IDA/Suite=$work/emptyfolder" --output out
bad pair2d.csv "file,file2\n$at2,$at2\n" "the suite's records are horizontal pairs: they need a 3D model"
expect 1 "--write-at2 writes the realizations of --realizations N" ground-motion ida.prm --write-at2 --output out
expect 1 "--write-at2 belongs to ground-motion" run ida.prm --write-at2 --output out
# a folder of AT2 files is a suite too
expect 0 "collapse fragility" ida ida.prm "${short[@]}" --set "IDA/Suite=$work/gen/records" --output folder
rm -rf folder out
# a journal resumed after its suite changed: refused naming the suite and
# its entry, the journal untouched (one record, two runs up to 0.2)
printf 'file\n%s\n' "$at2" > resumed.csv
cheap=(ida ida.prm "${short[@]}" --set "IDA/Suite=$work/resumed.csv" --set "IDA/Upper intensity=0.2"
       --output resumed)
"$poundfe" "${cheap[@]}" > /dev/null || die "ida of one record"
cp resumed/journal/realizations.csv journal.before
# the same record in a JSON suite: the same runs
printf '{"records": [{"files": ["%s"], "scale": 1}]}\n' "$at2" > one.json
"$poundfe" ida ida.prm "${short[@]}" --set "IDA/Suite=$work/one.json" --set "IDA/Upper intensity=0.2" \
  --output json > /dev/null || die "ida of a JSON suite"
cmp resumed/ida.csv json/ida.csv || die "a JSON suite and a CSV suite of one record differ"
printf 'file,scale\n%s,2\n' "$at2" > resumed.csv
n=$((n + 1))
if "$poundfe" "${cheap[@]}" > resumed.log 2>&1; then
  fail "resumed with a changed suite: not refused"
elif [ $? -ne 1 ] || ! grep -q "the record suite '$work/resumed.csv' (IDA/Suite) changed since" resumed.log; then
  fail "resumed with a changed suite: $(cat resumed.log)"
elif ! cmp -s journal.before resumed/journal/realizations.csv; then
  fail "resumed with a changed suite: the journal changed"
else
  echo "ok   resumed with a changed suite: $(head -c 200 resumed.log)"
fi
report "ida"
