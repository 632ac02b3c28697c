#!/usr/bin/env bash
# The step-rate check: runs `poundfe-bench --step-rate` on the models of
# bench/step-rate.txt (outputs off, and every default CSV output at every
# step) and prints, per model and case, the figure recorded there, today's,
# and the change in per cent, with the load average before and after (a
# figure taken under load says little: doc/benchmarks.md, "Step rate check").
# A tool, not a test: timings depend on the machine and on what else runs.
#   bash bench/check-step-rate.sh [-r REPEATS] [-b BENCH] [-t PERCENT] [MODEL...]
# -r  runs per figure, the best kept (default 5)
# -b  the benchmark binary (default build/poundfe-bench)
# -t  exit 1 when a figure fell by more than PERCENT below the recorded one
#     (default: never; the table is printed either way)
# A model's line may carry four more figures, from the alternating runs
# named on the table's "# baseline:" line: off and csv of this code, then of
# the baseline build. Each row then also gives the first over the second,
# "recorded alternately: N.NNx baseline": a ratio of those recorded runs,
# at the load that line states, never of today's run (which runs one build).
# Run from the repository root, on a Release build.
set -eu
repeats=5 bench=build/poundfe-bench threshold=
while getopts r:b:t: option; do
  case $option in
    r) repeats=$OPTARG ;;
    b) bench=$OPTARG ;;
    t) threshold=$OPTARG ;;
    *) sed -n '2,18p' "$0" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
table=bench/step-rate.txt
[ -r "$table" ] || { echo "check-step-rate: no $table (run from the repository root)" >&2; exit 2; }
[ -x "$bench" ] || { echo "check-step-rate: no $bench (build the poundfe-bench target)" >&2; exit 2; }
before=$(cut -d' ' -f1-3 /proc/loadavg)
today=$("$bench" --step-rate "$repeats" "$@")
after=$(cut -d' ' -f1-3 /proc/loadavg)
sed -n 's/^# recorded: /recorded: /p; s/^# baseline: /baseline: /p' "$table"
echo "today: $(git rev-parse --short HEAD 2>/dev/null || echo '?'), $(date -u '+%Y-%m-%d %H:%M UTC'), load average $before before, $after after"
# today's lines are "step-rate MODEL CASE STEPS/S"; the table's
# "MODEL INPUT OFF CSV [ALT_OFF ALT_CSV BASELINE_OFF BASELINE_CSV]"
echo "$today" | awk -v threshold="$threshold" '
  NR == FNR {
    if ($0 !~ /^#/ && NF >= 4) {
      recorded[$1, "off"] = $3; recorded[$1, "csv"] = $4
      if (NF >= 8) {
        alternate[$1, "off"] = $5; alternate[$1, "csv"] = $6
        baseline[$1, "off"] = $7;  baseline[$1, "csv"] = $8
      }
    }
    next
  }
  $1 == "step-rate" {
    was = recorded[$2, $3]
    if (was > 0) {
      change = 100 * ($4 - was) / was
      printf "%-22s %-4s recorded %9.0f  today %9.0f  %+6.1f %%", $2, $3, was, $4, change
      if (baseline[$2, $3] > 0)
        printf "  recorded alternately: %.2fx baseline", alternate[$2, $3] / baseline[$2, $3]
      printf "\n"
      if (threshold != "" && change < -threshold) fell = 1
    } else
      printf "%-22s %-4s recorded         -  today %9.0f\n", $2, $3, $4
  }
  END { exit fell }' "$table" -
