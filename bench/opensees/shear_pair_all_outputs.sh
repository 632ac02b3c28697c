#!/usr/bin/env bash
# The shear pairs (bench/shear-pair-linear.prm, bench/shear-pair-jankowski.prm)
# in poundfe and in OpenSees 3.8 side by side, every output at every step:
# poundfe `run` with its default outputs (CSV, Output interval = the time
# step, plus summary.json), OpenSees the script of `poundfe export-opensees`
# with recorders on every quantity at every step (floor displacement,
# velocity and absolute acceleration, storey and gap forces and deformations;
# a storey's drift is its deformation over its height, and OpenSees's Drift
# recorder needs a second coordinate the 1D script has not). Each run's CPU time (user + system, /usr/bin/time), ROUNDS
# rounds alternating which program goes first, and the same runs with End
# time = one step for the start-up, so that (full - start-up) / steps is the
# CPU time of a step with its outputs. OPENBLAS_NUM_THREADS=1 for OpenSees
# (bench/opensees/speed.py says why).
#   bash bench/opensees/shear_pair_all_outputs.sh POUNDFE OPENSEES WORK_DIR [ROUNDS] [MODEL...]
# MODEL: linear, jankowski (default both). From the repository root.
# With CALLGRIND=1: instructions instead of CPU times (valgrind --tool=callgrind,
# one run each, whole process; the start-up runs likewise).
# With POUNDFE_THREADS=N: poundfe runs with --threads N (from 2, its CSV tables
# are formatted and written on a thread of their own; CPU times and
# instructions count both threads).
set -eu
poundfe=$1 opensees=$2 work=$3 rounds=${4:-3}
shift $(( $# < 4 ? $# : 4 ))
models=${*:-linear jankowski}
mkdir -p "$work"
export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1

# the exported script with a recorder on every quantity before its analysis
opensees_script() { # MODEL DIR END
  local prm=bench/shear-pair-$1.prm dir=$2
  "$poundfe" export-opensees "$prm" --output "$dir" --set "Ground motion/Stochastic/Duration=$3" > /dev/null
  local floors gaps storeys
  floors=$(sed -n 's/^recorder Node .* -node \(.*\) -dof 1 disp$/\1/p' "$dir/model.tcl")
  gaps=$(sed -n 's/^recorder Element .* -ele \(.*\) force$/\1/p' "$dir/model.tcl")
  storeys=$(sed -n 's/^element zeroLength \([0-9]*\) [0-9]* [0-9]* -mat [0-9]* -dir 1$/\1/p' "$dir/model.tcl" |
            awk -v g=" $gaps " 'index(g, " " $1 " ") == 0' | tail -n 5 | tr '\n' ' ')
  awk -v floors="$floors" -v gaps="$gaps" -v storeys="$storeys" '
    /^constraints / && !done {
      print "recorder Node -file [file join $out floor_vel.out] -time -precision 16 -node " floors " -dof 1 vel"
      print "recorder Node -file [file join $out floor_acc.out] -time -precision 16 -timeSeries 1 -node " floors " -dof 1 accel"
      print "recorder Element -file [file join $out storey_force.out] -time -precision 16 -ele " storeys "force"
      print "recorder Element -file [file join $out storey_deformation.out] -time -precision 16 -ele " storeys "deformation"
      print "recorder Element -file [file join $out gap_deformation.out] -time -precision 16 -ele " gaps " deformation"
      done = 1
    }
    { print }' "$dir/model.tcl" > "$dir/all.tcl"
}

cpu() { # COMMAND...: user + system seconds
  /usr/bin/time -f '%U %S' -o "$work/time.txt" "$@" > /dev/null 2>&1
  awk '{ print $1 + $2 }' "$work/time.txt"
}

instructions() { # COMMAND...: instructions of the whole process
  valgrind --tool=callgrind --callgrind-out-file="$work/cg.out" "$@" 2>&1 > /dev/null |
    sed -n 's/.*Collected : //p'
}

for model in $models; do
  full=$work/$model-full short=$work/$model-short
  opensees_script "$model" "$full" 20
  opensees_script "$model" "$short" 0.0005
  steps=$(sed -n 's/.*analyze \([0-9]*\) .*/\1/p' "$full/model.tcl")
  prm=bench/shear-pair-$model.prm
  run_p_full=("$poundfe" run "$prm" --output "$work/$model-poundfe" --set "Output/Plots=false")
  run_p_short=("$poundfe" run "$prm" --output "$work/$model-poundfe-short" --set "Output/Plots=false"
               --set "Time integration/End time=0.0005")
  if [ -n "${POUNDFE_THREADS:-}" ]; then
    run_p_full+=(--threads "$POUNDFE_THREADS") run_p_short+=(--threads "$POUNDFE_THREADS")
  fi
  run_o_full=("$opensees" "$full/all.tcl" "$full")
  run_o_short=("$opensees" "$short/all.tcl" "$short")
  if [ "${CALLGRIND:-0}" = 1 ]; then
    p_full=$(instructions "${run_p_full[@]}") p_short=$(instructions "${run_p_short[@]}")
    o_full=$(instructions "${run_o_full[@]}") o_short=$(instructions "${run_o_short[@]}")
    echo "$model $steps steps, instructions: poundfe $p_full (start-up $p_short)," \
         "OpenSees $o_full (start-up $o_short)"
    continue
  fi
  for round in $(seq "$rounds"); do
    if [ $((round % 2)) = 1 ]; then
      p_full=$(cpu "${run_p_full[@]}") o_full=$(cpu "${run_o_full[@]}")
      p_short=$(cpu "${run_p_short[@]}") o_short=$(cpu "${run_o_short[@]}")
    else
      o_full=$(cpu "${run_o_full[@]}") p_full=$(cpu "${run_p_full[@]}")
      o_short=$(cpu "${run_o_short[@]}") p_short=$(cpu "${run_p_short[@]}")
    fi
    echo "$model round $round, $steps steps, CPU s: poundfe $p_full (start-up $p_short)," \
         "OpenSees $o_full (start-up $o_short), load $(cut -d' ' -f1 /proc/loadavg)"
  done
done
