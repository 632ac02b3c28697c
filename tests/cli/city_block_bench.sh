#!/usr/bin/env bash
# bench/city_block.sh on a small city block: both runs (1 and 2 ranks) reach
# the end and print their figures; the serial and parallel runs report the
# same model (equations, nonlinear elements, gaps) and the same steps.
#   city_block_bench.sh INPUT   (from the repository root, build/ beside it)
set -u
export OMPI_MCA_rmaps_base_oversubscribe=1
out=$(bash bench/city_block.sh "$1" 2>&1) || { echo "$out"; echo "FAIL: exit status $?"; exit 1; }
echo "$out"
fail() { echo "FAIL $*"; exit 1; }
[ "$(grep -c 'peak resident memory' <<< "$out")" -eq 4 ] || fail "not four complete reports"
models=$(grep -o '[0-9]* equations, [0-9]* nonlinear elements, [0-9]* gaps' <<< "$out" | sort -u | wc -l)
[ "$models" -eq 1 ] || fail "the two runs report different models"
steps=$(grep 'distributed' -A4 <<< "$out" | grep -o 'stepping: [0-9]* steps ([0-9]* with sub-steps)' | sort -u | wc -l)
[ "$steps" -eq 1 ] || fail "the two runs took different steps"
# partitioned by building: the same steps as the whole model, and the same
# final displacements to the Newton tolerance's reach
steps=$(grep -E '^(serial|partitioned)' -A2 <<< "$out" | grep -o 'stepping: [0-9]* steps ([0-9]* with sub-steps)' | sort -u | wc -l)
[ "$steps" -eq 1 ] || fail "the partitioned run took other steps than the whole model's"
d=$(sed -n 's/.*final displacements within \([^ ]*\) of the peak.*/\1/p' <<< "$out")
[ -n "$d" ] || fail "no comparison of the partitioned run"
/usr/bin/python3 -c "import sys; sys.exit(0 if float('$d') <= 1e-8 else 1)" || fail "partitioned run $d of the peak away"
# poundfe run partitioned (every output) against one process
d=$(sed -n "s/.*poundfe run partitioned on 2 ranks against one process: every CSV within \([^ ]*\) of.*/\1/p" <<< "$out")
[ -n "$d" ] || fail "no comparison of poundfe run partitioned"
/usr/bin/python3 -c "import sys; sys.exit(0 if float('$d') <= 1e-8 else 1)" || fail "poundfe run partitioned $d of a peak away"
grep -q '^rank 0: peak RSS [0-9]* KiB$' <<< "$out" && grep -q '^rank 1: peak RSS [0-9]* KiB$' <<< "$out" ||
  fail "not two ranks' memory"
echo "ok: the city-block benchmark on 1 and 2 ranks, distributed and partitioned, and poundfe run partitioned"
