#!/usr/bin/env bash
# Every command on a 3D model (Model/Dimension = 3; doc/verification.md,
# "Every command on a 3D model", "Critical incidence angle"):
#  1. montecarlo: the columns along y and in plan, and realization 1 is the
#     run of Realization = 1, its second component included (base shear in y,
#     torque, corner drift to 1e-12);
#  2. subset, fragility, separation, spectrum, ground-motion, modal and
#     stationary-pdf accept the 3D pair;
#  3. sweep over the incidence angle: the critical angle reported; a linear
#     eccentric building's peaks against the angle are those of the
#     superposition of the 0 and 90 degree runs (angle_superposition.py), the
#     critical angle too; the angles a and a + 180 give the same peaks;
#  4. bad pairs: one message, exit 1, nothing written.
set -eu
poundfe=$1 here=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL $*"; exit 1; }
pair=$here/3d-commands.prm
json() { # file python-expression-of-s
  python3 -c "import json,sys; s=json.load(open(sys.argv[1])); print($2)" "$1"
}
column() { # csv row(1-based data row) name
  python3 -c "
import csv,sys
rows=list(csv.DictReader(open(sys.argv[1])))
print(rows[int(sys.argv[2])-1][sys.argv[3]])" "$@"
}
close() { # a b what
  python3 -c "import sys; a,b=float(sys.argv[1]),float(sys.argv[2]); sys.exit(abs(a-b)>1e-12*max(abs(a),abs(b),1e-300))" "$1" "$2" \
    || fail "$3: $1 against $2"
}

"$poundfe" montecarlo "$pair" --output "$work/mc" > /dev/null
sed 's/    set Seed             = 5/    set Seed             = 5\n    set Realization      = 1/' "$pair" > "$work/r1.prm"
"$poundfe" run "$work/r1.prm" --output "$work/r1" > /dev/null
for b in 0:tor3 1:tor2; do
  i=${b%%:*} name=${b#*:}
  close "$(column "$work/mc/realizations.csv" 2 "${name}_peak_base_shear_y_N")" \
        "$(json "$work/r1/summary.json" "s['buildings'][$i]['plan']['peak_base_shear_y_N']")" \
        "montecarlo realization 1 is not run's Realization 1 ($name base shear y)"
  close "$(column "$work/mc/realizations.csv" 2 "${name}_peak_base_torque_N_m")" \
        "$(json "$work/r1/summary.json" "s['buildings'][$i]['plan']['peak_base_torque_N_m']")" \
        "montecarlo realization 1 is not run's Realization 1 ($name torque)"
  close "$(column "$work/mc/realizations.csv" 2 "${name}_peak_floor_rotation_rad")" \
        "$(json "$work/r1/summary.json" "max(s['buildings'][$i]['plan']['peak_floor_rotation_rad'])")" \
        "montecarlo realization 1 is not run's Realization 1 ($name rotation)"
done
head -1 "$work/mc/realizations.csv" | grep -q "tor3_storey1_peak_drift_ratio_y" || fail "no drifts along y"
echo "ok   montecarlo in 3D: realization 1 = run of Realization 1 (both components)"

for command in subset fragility separation spectrum ground-motion modal stationary-pdf; do
  "$poundfe" $command "$pair" --output "$work/$command" > "$work/$command.out" 2>&1 \
    || { tail -3 "$work/$command.out"; fail "$command refuses the 3D pair"; }
  [ ! -f "$work/$command/summary.json" ] ||
    [ "$(json "$work/$command/summary.json" "s.get('status', 'completed')")" = completed ] || fail "$command not completed"
done
head -1 "$work/fragility/pga_0.2g/realizations.csv" | grep -q "tor2_peak_base_shear_y_N" \
  || fail "fragility without the plan columns"
echo "ok   subset, fragility, separation, spectrum, ground-motion, modal, stationary-pdf in 3D"

"$poundfe" sweep "$pair" --output "$work/sweep" > "$work/sweep.out"
grep -q "critical Ground motion/Incidence angle for max_drift_ratio" "$work/sweep.out" \
  || fail "sweep reports no critical angle"
[ "$(json "$work/sweep/summary.json" "len(s['critical'])")" -gt 10 ] || fail "no critical values"

# an eccentric building under two components: linear (no yielding, no
# contact) for the superposition, with its Bouc-Wen planes for the mirror
eccentric() { # output yield(keep|drop) sweep-values
  sed -e "$([ "$2" = drop ] && echo '/Storey yield drifts/d' || echo 's/^$//')" \
      -e 's/set Plan dimensions = 12, 9/set Plan dimensions = 12, 9\n    set Mass eccentricity = 1.5, -0.8/' \
      -e 's/set Type = kanai-tajimi/set Type = kanai-tajimi\n  set Components = 2/' \
      "$here/3d-symmetric-shear.prm" > "$work/$1.prm"
  printf 'subsection Sweep\n  set Parameter = Ground motion/Incidence angle\n  set Values = %s\nend\n' \
    "$3" >> "$work/$1.prm"
}
eccentric linear drop "linspace -80 90 18"
for a in 0 90; do
  sed "s/set Components = 2/set Components = 2\n  set Incidence angle = $a/" "$work/linear.prm" > "$work/a$a.prm"
  "$poundfe" run "$work/a$a.prm" --output "$work/a$a" > /dev/null
done
"$poundfe" sweep "$work/linear.prm" --output "$work/linear" > /dev/null
for floor in 1 3; do
  python3 "$here/angle_superposition.py" "$work/linear" "$work/a0/floor_displacement.csv" \
    "$work/a90/floor_displacement.csv" "S_floor${floor}_disp_x_m" "S_floor${floor}_peak_displacement_m" 1e-9 \
    || fail "the sweep's peaks differ from the superposition"
done
echo "ok   sweep over the incidence angle = superposition of the 0 and 90 degree runs"

eccentric mirror keep "25, 205"
"$poundfe" sweep "$work/mirror.prm" --output "$work/mirror" > /dev/null
python3 - "$work/mirror/sweep.csv" <<'PY' || fail "the angles 25 and 205 degrees give different peaks"
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
worst = max(abs(float(a) - float(b)) / max(abs(float(a)), 1e-300)
            for a, b in zip(rows[1][2:-1], rows[2][2:-1]) if float(a) != 0)
print(f"25 and 205 degrees: largest relative difference of the peaks {worst:.3g}")
sys.exit(worst > 1e-10)
PY
echo "ok   the angles 25 and 205 degrees give the same peaks (mirror)"

bad() { # expected-text sed-expression
  sed -e "$2" "$pair" > "$work/bad.prm"
  set +e
  "$poundfe" run "$work/bad.prm" --output "$work/bad-out" > "$work/bad.out" 2>&1
  status=$?
  set -e
  [ $status -eq 1 ] || fail "exit $status for '$1'"
  grep -q "$1" "$work/bad.out" || { cat "$work/bad.out"; fail "no message '$1'"; }
  [ ! -e "$work/bad-out" ] || fail "'$1' wrote $work/bad-out"
}
bad "Correlation.*must be in \[-1, 1\]" 's/    set Seed             = 5/    set Seed = 5\n    set Correlation = 1.5/'
bad "Intensity ratio.*needs Ground motion/Components = 2" \
  's/    set Seed             = 5/    set Seed = 5\n    set Intensity ratio = 0.5/; s/set Components      = 2/set Components = 1/'
bad "Incidence angle.*\[-360, 360\]" 's/set Incidence angle = 30/set Incidence angle = 400/'
bad "Second file.*needs a second file" 's/set Type            = kanai-tajimi/set Type = record\n  subsection Record\n    set File = x.at2\n  end/'
echo "ok   bad pairs refused (correlation, ratio without a pair, angle, second record)"
