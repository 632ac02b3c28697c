#!/usr/bin/env bash
# A 44-record IDA of a 5-storey and a 3-storey Bouc-Wen shear building that
# pound (input/ida-pounding-pair.prm with the storeys set), 20 runs per
# record, on 1 and 2 ranks (Release build, from the repository root):
#   bash bench/ida44.sh [RECORDS] [RUNS_PER_RECORD] [REPEATS]
# Generates RECORDS Kanai-Tajimi records as an AT2 suite, then runs
# `mpirun -np 1` and `mpirun -np 2` alternately REPEATS times each, into fresh
# directories, and prints the best of each: the runs per second of the
# runs (summary.json: runs_now / wall_time_s) and the whole command's wall
# time (set-up and output included), the speed-up, and the load average
# before and after. ida.csv must be the same on 1 and 2 ranks.
#   COMMAND=msa: the same suite and model through `poundfe msa`, every record
# at RUNS_PER_RECORD stripes of Sa(T1) (0.05, 0.10, ... g; no cloud): the
# same number of runs per record, each dealt to the free rank as ida's;
# msa.csv must be the same on 1 and 2 ranks.
#   POUNDFE=path: that binary (default build/poundfe), e.g. an earlier
# build kept aside, to compare two builds under the same load.
#   Each rank runs under setsid (SETSID=0: not): with the kernel's autogroup
# scheduling (/proc/sys/kernel/sched_autogroup_enabled = 1) the CPU is
# shared between sessions, not processes, so on a machine that other
# sessions load, the ranks of one session share one session's time and two
# ranks cannot run faster than one; a session per rank gives each rank the
# share a process of its own would have, as on a machine of its own.
#   The machine's own ceiling: each repeat also runs two independent
# one-rank processes at once, each on half of the suite (no dealer, no
# messages), and prints their combined runs per second against one rank's.
# Two processes on two cores do not always run twice as fast as one (shared
# caches, memory bandwidth, clock); the dealer's speed-up is judged against
# this ceiling.
set -eu
poundfe=${POUNDFE:-build/poundfe}
n=${1:-44}
runs=${2:-20}
repeats=${3:-3}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 POUNDFE_PROGRESS=0
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pair=(--set "Building 1/Number of storeys=5" --set "Building 2/Number of storeys=3"
      --set Output/Plots=false)
"$poundfe" ground-motion input/ida-pounding-pair.prm --realizations "$n" --write-at2 \
  --output "$work/suite" "${pair[@]}" > /dev/null
command=${COMMAND:-ida}
options=("${pair[@]}" --set "IDA/Suite=$work/suite/records/suite.csv")
if [ "$command" = msa ]; then
  stripes=$(python3 -c "print(', '.join('%.2f' % (0.05 * (k + 1)) for k in range($runs)))")
  options+=(--set "MSA/Intensities=$stripes" --set "MSA/Cloud=false")
else
  options+=(--set "IDA/Runs per record=$runs")
fi
suite=$work/suite/records/suite.csv
n_header=$(grep -c '^#\|^name,' "$suite")
n_rows=$(($(wc -l < "$suite") - n_header))
{ head -n "$n_header" "$suite"; tail -n +"$((n_header + 1))" "$suite" | head -n $((n_rows / 2)); } > "$work/suite/records/half1.csv"
{ head -n "$n_header" "$suite"; tail -n +"$((n_header + 1 + n_rows / 2))" "$suite"; } > "$work/suite/records/half2.csv"
echo "load average before: $(uptime | sed 's/.*load average: //')"
best() { sort -g | tail -1; }
isolate=setsid
[ "${SETSID:-1}" = 0 ] && isolate=
echo "autogroup scheduling: $(cat /proc/sys/kernel/sched_autogroup_enabled 2> /dev/null || echo unknown); ranks under: ${isolate:-none}"
for i in $(seq "$repeats"); do
  for np in 1 2; do
    start=$(date +%s.%N)
    mpirun -np "$np" $isolate "$poundfe" "$command" input/ida-pounding-pair.prm --output "$work/np$np-$i" \
      "${options[@]}" > /dev/null
    end=$(date +%s.%N)
    python3 -c "import json, sys; s = json.load(open(sys.argv[1])); print(s['runs_now'], s['runs_now'] / s['wall_time_s'], float(sys.argv[3]) - float(sys.argv[2]))" \
      "$work/np$np-$i/summary.json" "$start" "$end" >> "$work/rates$np"
  done
  for half in 1 2; do
    $isolate "$poundfe" "$command" input/ida-pounding-pair.prm --output "$work/half$half-$i" \
      "${options[@]}" --set "IDA/Suite=$work/suite/records/half$half.csv" > /dev/null &
  done
  wait
  python3 -c "import json, sys; s = [json.load(open(f)) for f in sys.argv[1:]]; print(sum(x['runs_now'] for x in s) / max(x['wall_time_s'] for x in s))" \
    "$work/half1-$i/summary.json" "$work/half2-$i/summary.json" >> "$work/rates_halves"
done
cmp -s "$work/np1-1/$command.csv" "$work/np2-1/$command.csv" ||
  echo "warning: $command.csv differs between 1 and 2 ranks"
echo "load average after: $(uptime | sed 's/.*load average: //')"
runs_done=$(head -1 "$work/rates1" | cut -d' ' -f1)
r1=$(cut -d' ' -f2 "$work/rates1" | best)
r2=$(cut -d' ' -f2 "$work/rates2" | best)
w1=$(cut -d' ' -f3 "$work/rates1" | sort -g | head -1)
w2=$(cut -d' ' -f3 "$work/rates2" | sort -g | head -1)
echo "$command: $n records x $runs runs per record: $runs_done runs"
echo "all: $(tr '\n' ';' < "$work/rates1") | $(tr '\n' ';' < "$work/rates2")"
printf '1 rank:  %.1f runs/s, %.1f s in all\n' "$r1" "$w1"
printf '2 ranks: %.1f runs/s, %.1f s in all\n' "$r2" "$w2"
awk -v a="$r1" -v b="$r2" 'BEGIN { printf "speed-up on 2 ranks: %.2f\n", b / a }'
rh=$(best < "$work/rates_halves")
awk -v a="$r1" -v h="$rh" -v b="$r2" 'BEGIN { printf "two independent 1-rank processes on halves: %.1f runs/s, %.2f x one rank (the ceiling); 2 ranks reach %.0f %% of it\n", h, h / a, 100 * b / h }'
