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
# The same for `poundfe opensees --threads N`: the benchmark's OpenSees
# script (140 forceBeamColumn members, 10 zeroLength gaps) for 2 s of a
# sine record strong enough to pound, every recorder file compared.
#   threads.sh POUNDFE BENCH_PRM PAIR_TCL
set -u
poundfe=$1 prm=$2 pair_tcl=$3
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
sed 's/analyze 4000 0.005/analyze 400 0.005/' "$pair_tcl" > "$work/pair.tcl"
awk 'BEGIN { for (i = 0; i <= 400; i++) { t = i * 0.005
  print 3.5 * sin(2 * 3.141592653589793 * t / 0.9) * (t < 1 ? t : 1) } }' > "$work/record.txt"
for n in 1 2; do
  mkdir -p "$work/s$n"
  if ! "$poundfe" opensees --threads "$n" "$work/pair.tcl" "$work/s$n" "$work/record.txt" \
      > "$work/s$n.log" 2>&1; then
    echo "FAIL: opensees --threads $n:"; tail -3 "$work/s$n.log"; exit 1
  fi
done
script_files=0
for f in "$work"/s1/*.out; do
  script_files=$((script_files + 1))
  cmp -s "$f" "$work/s2/$(basename "$f")" ||
    { echo "FAIL: opensees $(basename "$f") differs between --threads 1 and 2"; status=1; }
done
contacts=$(awk '{ for (i = 2; i <= NF; i++) if ($i != 0) { n++; break } } END { print n + 0 }' \
  "$work/s1/gap_force.out")
if [ "$script_files" -ne 6 ] || [ "$contacts" -lt 1 ]; then
  echo "FAIL: opensees: $script_files recorder files, $contacts steps in contact"; status=1
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
[ "$status" -eq 0 ] && echo "threads: $files files of run and $script_files of opensees" \
  "($contacts steps in contact) the same on 1 and 2 threads, bad values refused"
exit "$status"
