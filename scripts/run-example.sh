#!/usr/bin/env bash
# Run the default example: two adjacent frames (3 and 2 storeys) under a
# generated Kanai-Tajimi ground motion. Sets up first if needed.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/poundfe ] || scripts/setup.sh
input=input/two-buildings.prm
out=results/two-buildings
build/poundfe modal "$input" --output "$out/modal"
build/poundfe run "$input" --output "$out"
cat <<TXT

Results of $input are in $out/:
  summary.json               model size, modes, peak drift and floor acceleration per storey,
                             hinge peaks, impacts per gap, energy balance, Newton statistics
  impacts.csv                the impact log: one row per impact
  drift.csv, floor_acceleration.csv, floor_displacement.csv, ground_motion.csv
  hinges.csv, energy.csv, contact_force.csv
  drift_profile.png, acceleration_profile.png, roof_displacement.png, ground_motion.png,
  energy.png, contact_force.png, hysteresis_<hinge>.png
  solution.pvd               open in ParaView (Warp By Vector on 'displacement')
  modal/summary.json, modal/modes.pvd   frequencies, periods, mass ratios and mode shapes
TXT
