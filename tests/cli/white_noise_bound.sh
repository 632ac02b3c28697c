#!/bin/bash
# The white-noise intensity bound does not move with the time step: 3 standard
# deviations of the noise below 25 Hz, sqrt(2 S0 x 2 pi 25), at most 10 g, so
# S0 <= 3.401 m^2/s^3 (D = pi S0 <= 10.69) at any time step or sample
# interval. Realistic intensities run at a tiny step: the thesis's SD
# oscillator with D = 0.6 (input/sd-oscillator-noise.prm) and subset-drift's
# S0 = 0.01 m^2/s^3 held over a 1e-5 s step (a bound on the held samples'
# deviation, sqrt(2 pi S0 / dt), refused both). D = 10.6 runs and D = 10.8
# is refused, at a step of 0.05 s and of 1e-5 s alike, with the expected PGA
# 3 sqrt(2 (10.8 / pi) 2 pi 25) / 9.80665 = 10.0534 g in its message.
# Usage: white_noise_bound.sh POUNDFE INPUT_DIR
set -u
poundfe=$1
input=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0

# run NAME EXPECTED_EXIT FILE SETTINGS...
run() {
  local name=$1 expected=$2 file=$3
  shift 3
  local sets=()
  for s in "$@"; do sets+=(--set "$s"); done
  "$poundfe" run "$file" "${sets[@]}" --set "Output/Directory=$work/$name" \
    --set Output/Plots=false --set "Output/VTU interval=0" > "$work/$name.log" 2>&1
  local status=$?
  if [ "$status" -ne "$expected" ]; then
    echo "FAIL $name: exit $status, expected $expected"
    tail -2 "$work/$name.log"
    failed=1
  else
    echo "ok   $name: exit $status"
  fi
}

sd=$input/sd-oscillator-noise.prm
for dt in 0.05 1e-5; do
  steps="Time integration/Time step=$dt"
  run "sd-d0.6-dt$dt" 0 "$sd" "Ground motion/Stochastic/D=0.6" \
    "Ground motion/Stochastic/Duration=0.1" "$steps"
  run "sd-d10.6-dt$dt" 0 "$sd" "Ground motion/Stochastic/D=10.6" \
    "Ground motion/Stochastic/Duration=0.1" "$steps"
  run "sd-d10.8-dt$dt" 1 "$sd" "Ground motion/Stochastic/D=10.8" \
    "Ground motion/Stochastic/Duration=0.1" "$steps"
done
grep -q "'Ground motion/Stochastic/D': gives an expected peak ground acceleration of 10.0533" \
  "$work/sd-d10.8-dt1e-5.log" || { echo "FAIL: D = 10.8 message"; cat "$work/sd-d10.8-dt1e-5.log"; failed=1; }
run subset-drift-s0-dt1e-5 0 "$input/subset-drift.prm" "Ground motion/Stochastic/Sample interval=0" \
  "Ground motion/Stochastic/Duration=0.02" "Time integration/Time step=1e-5"
exit $failed
