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
# on_one_and_two NAME PATTERN COMMAND ARG... : poundfe COMMAND --threads N
# ARG... for N = 1 and 2, an ARG that is OUT replaced by $work/NAME1 or
# $work/NAME2; then each file of NAME1 matching PATTERN compared with
# NAME2's ($compared counts them).
on_one_and_two() {
  local name=$1 pattern=$2 command=$3 n f arg
  shift 3
  for n in 1 2; do
    local args=()
    for arg in "$@"; do
      if [ "$arg" = OUT ]; then args+=("$work/$name$n"); else args+=("$arg"); fi
    done
    if ! "$poundfe" "$command" --threads "$n" "${args[@]}" > "$work/$name$n.log" 2>&1; then
      echo "FAIL: $command --threads $n:"; tail -3 "$work/$name$n.log"; exit 1
    fi
  done
  compared=0
  for f in "$work/${name}1"/$pattern; do
    compared=$((compared + 1))
    cmp -s "$f" "$work/${name}2/$(basename "$f")" ||
      { echo "FAIL: $command $(basename "$f") differs between --threads 1 and 2"; status=1; }
  done
}
on_one_and_two t '*.csv' run "$prm" --output OUT --set "Time integration/End time=3"
files=$compared
impacts=$(grep -o '[0-9]* impacts' "$work/t2.log" | cut -d' ' -f1)
if [ "$files" -lt 8 ] || [ "${impacts:-0}" -lt 1 ]; then
  echo "FAIL: $files CSV files, ${impacts:-0} impacts: the run did not pound"; status=1
fi
sed 's/analyze 4000 0.005/analyze 400 0.005/' "$pair_tcl" > "$work/pair.tcl"
awk 'BEGIN { for (i = 0; i <= 400; i++) { t = i * 0.005
  print 3.5 * sin(2 * 3.141592653589793 * t / 0.9) * (t < 1 ? t : 1) } }' > "$work/record.txt"
mkdir -p "$work/s1" "$work/s2"
on_one_and_two s '*.out' opensees "$work/pair.tcl" OUT "$work/record.txt"
script_files=$compared
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
