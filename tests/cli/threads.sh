#!/usr/bin/env bash
# --threads N: the element loop of a time history on N threads (deal.II's
# TBB) gives the same numbers as on one, byte for byte: the fibre pair
# benchmark (bench/fibre-pair.prm: 140 fibre members and 10 gaps, pounding
# at 8 floors) for its first 3 s after gravity, with --threads 1 and
# --threads 2, every CSV file compared with cmp (each element writes its own
# slices, the sums over elements stay in their order). A --threads that is no
# whole number in 1..256 written in digits alone (a blank, a sign or a
# leading zero included) is refused: exit 1, one line naming the option,
# nothing written; so is --threads for a command that reads no file.
#   threads.sh POUNDFE BENCH_PRM
set -u
poundfe=$1 prm=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
for n in 1 2; do
  if ! "$poundfe" run "$prm" --output "$work/t$n" --threads "$n" \
      --set "Time integration/End time=3" > "$work/t$n.log" 2>&1; then
    echo "FAIL: run --threads $n:"; tail -3 "$work/t$n.log"; exit 1
  fi
done
files=0
for f in "$work"/t1/*.csv; do
  files=$((files + 1))
  cmp -s "$f" "$work/t2/$(basename "$f")" ||
    { echo "FAIL: $(basename "$f") differs between --threads 1 and 2"; status=1; }
done
impacts=$(grep -o '[0-9]* impacts' "$work/t2.log" | cut -d' ' -f1)
if [ "$files" -lt 8 ] || [ "${impacts:-0}" -lt 1 ]; then
  echo "FAIL: $files CSV files, ${impacts:-0} impacts: the run did not pound"; status=1
fi
for bad in 0 257 two 1.5 "" " 2" "2 " +2 02; do
  out=$("$poundfe" run "$prm" --output "$work/bad" --threads "$bad" 2>&1)
  code=$?
  if [ "$code" -ne 1 ] || [ -e "$work/bad" ] || [ "$(printf '%s\n' "$out" | wc -l)" -ne 1 ] ||
     ! printf '%s' "$out" | grep -q -- '--threads'; then
    echo "FAIL: --threads '$bad': exit $code, output: $out"; status=1
  fi
done
out=$("$poundfe" template frame --threads 2 2>&1)
code=$?
if [ "$code" -ne 1 ] || ! printf '%s' "$out" | grep -q -- "--threads .*'template' reads no"; then
  echo "FAIL: template --threads 2: exit $code, output: $out"; status=1
fi
[ "$status" -eq 0 ] && echo "threads: $files files the same on 1 and 2 threads, bad values refused"
exit "$status"
