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
[ "$(grep -c 'peak resident memory' <<< "$out")" -eq 2 ] || fail "not two complete reports"
models=$(grep -o '[0-9]* equations, [0-9]* nonlinear elements, [0-9]* gaps' <<< "$out" | sort -u | wc -l)
[ "$models" -eq 1 ] || fail "the two runs report different models"
steps=$(grep -o 'stepping: [0-9]* steps ([0-9]* with sub-steps)' <<< "$out" | sort -u | wc -l)
[ "$steps" -eq 1 ] || fail "the two runs took different steps"
echo "ok: the city-block benchmark on 1 and 2 ranks"
