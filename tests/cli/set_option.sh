#!/usr/bin/env bash
# --set Section/Entry=value on the command line (doc/user-guide.md, "The
# command line"; commands/dispatch.h):
#  1. the overrides take effect: a run and a modal analysis with --set give
#     byte for byte the files of the same file edited the same way (the
#     summary equal but for the input's name);
#  2. applied in order: the last --set of an entry wins;
#  3. an unknown entry or section is refused with the reader's own message
#     (that of poundfe.read's overrides: tests/python/test_command_rules.py
#     compares the two), in the words the file reader has for the same entry
#     written in the file, with the closest declared names, a value out of range names the
#     entry, a malformed --set and --set for a command that reads no file
#     are refused: exit 1, one line, nothing written (tests/cli/expect.sh);
#     Only the user's own --set is named, once: not bifurcation's end time
#     or a sweep's value, which the command sets when it reads the file
#     again (input/override_origin.h);
#  4. the distributed-solver column (several ranks only, so not in Python's
#     tests): montecarlo with petsc-mumps on 2 ranks refused, one message.
#   set_option.sh POUNDFE SOURCE_DIR
set -u
poundfe=$(readlink -f "$1") source=$(readlink -f "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
. "$source/tests/cli/expect.sh"

base=$source/input/three-storey-shear.prm
# the file with the stiffness changed, plots and VTU off, 4 s long
sed -e 's/set Storey stiffnesses = 5e6/set Storey stiffnesses = 3.5e6, 4e6, 4.5e6/' \
    -e 's/set Duration   = 15/set Duration   = 4/' \
    -e 's/set VTU interval    = 0.1/set VTU interval    = 0\n  set Plots = false/' "$base" > edited.prm
cmp -s "$base" edited.prm && fail "edited.prm: the sed expressions changed nothing"
sets=(--set "Building 1/Storey stiffnesses=3.5e6, 4e6, 4.5e6"
      --set "Ground motion/Stochastic/Duration=4"
      --set "Output/VTU interval=0" --set "Output/Plots=false")

same_output() { # label directory-from-file directory-from-set
  diff -r -q -x summary.json "$2" "$3" > /dev/null ||
    { fail "$1: $(diff -r -q -x summary.json "$2" "$3")"; return; }
  python3 - "$2/summary.json" "$3/summary.json" <<'EOF' || { fail "$1: summary.json differs"; return; }
import json, sys
def kept(s):  # without the input's name, the output directory and the clock
    if isinstance(s, dict):
        return {k: kept(v) for k, v in s.items()
                if k not in ("input", "directory", "wall_time_s", "steps_per_second")}
    return [kept(v) for v in s] if isinstance(s, list) else s
a, b = (kept(json.load(open(f))) for f in sys.argv[1:])
sys.exit(a != b)
EOF
  n=$((n + 1))
  echo "ok   $1: the files of --set equal those of the edited file"
}

for command in run modal; do
  "$poundfe" $command edited.prm --output "file-$command" > /dev/null 2>&1 ||
    fail "$command edited.prm failed"
  "$poundfe" $command "$base" "${sets[@]}" --output "set-$command" > /dev/null 2>&1 ||
    fail "$command --set failed"
  same_output "$command" "file-$command" "set-$command"
done
# the overrides are not the file's values: the unedited file differs
"$poundfe" modal "$base" --output plain > /dev/null 2>&1 || fail "modal of the file failed"
cmp -s plain/summary.json set-modal/summary.json && fail "--set changed nothing in modal"

# applied in order: a first value of the same entry is overridden by the second
"$poundfe" modal "$base" --set "Building 1/Storey stiffnesses=1e9" "${sets[@]}" \
  --output twice > /dev/null 2>&1 || fail "modal with an entry set twice failed"
same_output "the last --set of an entry wins" file-modal twice

# refused as the reader refuses an override (read_parameters), nothing written
misspelt="No entry with name <Storey stiffnes> in 'Building 1' (did you mean 'Storey stiffnesses'?)"
expect 1 "parameter 'Building 1/Storey stiffnes': $misspelt" \
  modal "$base" --set "Building 1/Storey stiffnes=4e6" --output out
expect 1 "parameter 'Buildin 1/Storey stiffnesses': There is no such subsection to be entered: Buildin 1 (did you mean 'Building 1'?)" \
  modal "$base" --set "Buildin 1/Storey stiffnesses=4e6" --output out
# the same words as the file reader's for the same entry written in the file
# (the reference: that file's message, after its file:line)
sed 's/set Storey stiffnesses = 5e6/set Storey stiffnes = 4e6/' "$base" > misspelt.prm
cmp -s "$base" misspelt.prm && fail "misspelt.prm: the sed expression changed nothing"
expect 1 "misspelt.prm:" modal misspelt.prm --output out
n=$((n + 1))
from_file=$(sed 's/^.*misspelt\.prm:[0-9]*: //' stderr)
"$poundfe" modal "$base" --set "Building 1/Storey stiffnes=4e6" --output out > /dev/null 2> stderr
from_set=$(sed 's/^.*three-storey-shear\.prm: //' stderr)
[ "$from_file" = "$from_set" ] && [ "$from_file" = "parameter 'Building 1/Storey stiffnes': $misspelt" ] ||
  fail "the file says '$from_file', --set '$from_set'"
expect 1 "override value 'often' is not allowed" \
  run "$base" --set "Output/Plots=often" --output out
expect 1 "Building 1/Damping/Damping ratio" \
  run "$base" --set "Building 1/Damping/Damping ratio=-0.5" --output out
expect 1 "Time integration/Time step" run "$base" --set "Time integration/Time step=-1" --output out
expect 1 "--set needs Section/Entry=value, got 'Output/Plots'" \
  run "$base" --set "Output/Plots" --output out
expect 1 "--set needs a value" run "$base" --set
expect 1 "--set sets an entry of a parameter file, and 'template' reads none" \
  template frame --set "Output/Plots=false"

# only the user's own --set is named, never an override a command adds when
# it reads the file again: bifurcation's end time, a sweep's value. The
# --set refused during a sweep is named, after the sweep's value.
no_set() { # label: the last expect's message names no --set
  grep -qF -- "--set '" stderr && fail "$1: names a --set: $(head -c 400 stderr)"
}
set_absent() { # label TEXT: the last expect's message does not contain TEXT
  grep -qF -- "$2" stderr && fail "$1: names $2: $(head -c 400 stderr)"
}
sed -e 's/set End time  = 20/set End time = 0.04\n  set Maximum number of steps = 10/' \
  "$source/input/linear-bifurcation.prm" > short-bifurcation.prm
cmp -s "$source/input/linear-bifurcation.prm" short-bifurcation.prm &&
  fail "short-bifurcation.prm: the sed expression changed nothing"
expect 1 "parameter 'Time integration/End time': at Bifurcation value Nodal forces/Harmonic:6 = 5: needs" \
  bifurcation short-bifurcation.prm --output out
no_set "bifurcation without --set"
expect 1 "parameter 'Time integration/End time': at Bifurcation value Nodal forces/Harmonic:6 = 5: needs" \
  bifurcation "$source/input/linear-bifurcation.prm" --set "Time integration/End time=0.04" \
  --set "Time integration/Maximum number of steps=10" --output out
set_absent "bifurcation's own end time" "--set 'Time integration/End time"
sweep_of() { # parameter values: the shear building swept
  cat "$base"
  printf 'subsection Sweep\n  set Parameter = %s\n  set Values = %s\nend\n' "$1" "$2"
}
sweep_of "Model/Gravity" "9.81, 0" > sweep-gravity.prm
expect 1 "parameter 'Model/Gravity': at Sweep value Model/Gravity = 0: must be positive and finite, got 0" \
  sweep sweep-gravity.prm --set "Model/Gravity=5" --output out
no_set "a sweep's value refused"
sweep_of "Building 1/Number of storeys" "3, 4" > sweep-storeys.prm
expect 1 "parameter 'Building 1/Storey stiffnesses': at Sweep value Building 1/Number of storeys = 4: needs 1 value or 4" \
  sweep sweep-storeys.prm --set "Building 1/Storey stiffnesses=5e6, 5e6, 5e6" --output out
no_set_twice=$(grep -o -- "--set '" stderr | wc -l)
[ "$no_set_twice" -eq 1 ] || fail "a --set refused during a sweep named $no_set_twice times"

# the distributed-solver column, which only a job of several ranks can meet
# (Python runs one process): montecarlo on 2 ranks with petsc-mumps, refused
# by rank 0 alone, nothing written
if command -v mpirun > /dev/null; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
  n=$((n + 1))
  status=0
  mpirun -np 2 "$poundfe" montecarlo "$source/tests/cli/montecarlo-small.prm" \
    --set "Time integration/Linear solver=petsc-mumps" --output mumps > /dev/null 2> mumps.err || status=$?
  expected="petsc-mumps spreads one run over the MPI ranks: on more than one rank only 'run' can use it, not 'montecarlo'"
  if [ "$status" -ne 1 ] || [ "$(grep -c '^poundfe: error' mumps.err)" -ne 1 ] ||
     ! grep -qF "$expected" mumps.err || [ -e mumps ]; then
    fail "distributed solver on 2 ranks: exit $status: $(head -c 400 mumps.err)"
  else
    echo "ok   a distributed solver for montecarlo on 2 ranks: refused from its row, one message"
  fi
fi
report "--set"
