#!/usr/bin/env bash
# The ranks of an MPI job agree on their inputs before any collective work
# (commands/rank_agreement.h): with mpirun's MPMD form each rank is given
# its own parameter file, so that only one of them can fail or differ:
#  - montecarlo, rank 1's parameter file missing, or its tabulated force
#    file missing: exit 1 on every rank, no rank left waiting (timeout), the
#    message printed once, naming rank 1 (and the file);
#  - montecarlo, ranks given different models (an entry, a force file's
#    contents, the command itself): refused naming the rank and the entry
#    or file, once, exit 1, nothing written;
#  - run partitioned by building (MPI initialised once the input is read on
#    one process): rank 1's file missing, or a different model: the same;
#  - the same model from two directories (copies, other paths): it runs.
#   mpi_agreement.sh POUNDFE MPIRUN
set -eu
poundfe=$1 mpirun=$2
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/helpers.sh"

# two two-storey shear buildings, a second of stochastic motion, a
# tabulated force on building 1 from force.txt beside the file
model() { # directory [extra lines at the end]
  mkdir -p "$1"
  cat > "$1/mc.prm" << PRM
subsection Model
  set Number of buildings = 2
  set Separations         = 0.05
end
subsection Building 1
  set Type               = shear
  set Number of storeys  = 2
  set Floor masses       = 1000
  set Storey stiffnesses = 5e6
end
subsection Building 2
  set Type               = shear
  set Number of storeys  = 2
  set Floor masses       = 1000
  set Storey stiffnesses = 4e6
end
subsection Ground motion
  set Type = kanai-tajimi
  subsection Stochastic
    set Duration        = 1
    set Sample interval = 0.01
    set Seed            = 3
  end
end
subsection Nodal forces
  set Tabulated = 1 1 0 ux force.txt
end
subsection Time integration
  set Time step = 0.01
end
subsection Monte Carlo
  set Realizations = 4
end
subsection Output
  set VTU interval    = 0
  set Number of modes = 0
  set Plots           = false
end
${2:-}
PRM
  printf '0 0\n0.5 1000\n1 0\n' > "$1/force.txt"
}

# refused DESCRIPTION TEXT MPIRUN-ARGUMENTS...: exit 1 within the timeout,
# one message containing TEXT, nothing written in $work/out
refused() {
  local what=$1 text=$2
  shift 2
  rm -rf "$work/out"
  local status=0
  timeout -k 5 60 "$mpirun" "$@" > "$work/log" 2>&1 || status=$?
  [ "$status" -ne 124 ] && [ "$status" -ne 137 ] || fail "$what: the ranks waited (killed after 60 s)"
  [ "$status" -eq 1 ] || fail "$what: exit status $status: $(head -c 600 "$work/log")"
  [ "$(grep -c '^poundfe: error: ' "$work/log")" -eq 1 ] ||
    fail "$what: not one message: $(head -c 600 "$work/log")"
  grep -qF -- "$text" "$work/log" || fail "$what: no '$text' in: $(head -c 600 "$work/log")"
  [ ! -e "$work/out" ] || fail "$what: wrote $work/out"
  echo "ok   $what: exit 1, $(grep '^poundfe: error: ' "$work/log" | sed "s|$work/||g" | head -c 300)"
}

model "$work/a"
model "$work/copy"
model "$work/no-force" && rm "$work/no-force/force.txt"
model "$work/edited" && printf '0 0\n0.5 2000\n1 0\n' > "$work/edited/force.txt"
model "$work/stiffer" && sed -i 's/Storey stiffnesses = 4e6/Storey stiffnesses = 4.5e6/' "$work/stiffer/mc.prm"
mc() { echo -np 1 "$poundfe" montecarlo "$1" --output "$work/out"; }

refused "montecarlo, rank 1's parameter file missing" \
  "poundfe: error: rank 1: $work/none.prm: cannot open the parameter file (no such file)" \
  $(mc "$work/a/mc.prm") : $(mc "$work/none.prm")
refused "montecarlo, rank 1's force file missing" \
  "rank 1's differs from rank 0's in the contents of force.txt ('Nodal forces/Tabulated') (rank 1 cannot read it: cannot open the file (no such file))" \
  $(mc "$work/a/mc.prm") : $(mc "$work/no-force/mc.prm")
refused "montecarlo, rank 1's force file edited" \
  "rank 1's differs from rank 0's in the contents of force.txt ('Nodal forces/Tabulated')" \
  $(mc "$work/a/mc.prm") : $(mc "$work/edited/mc.prm")
refused "montecarlo, rank 1 given another stiffness" \
  "rank 1's differs from rank 0's in 'Building 2/Storey stiffnesses'" \
  $(mc "$work/a/mc.prm") : $(mc "$work/stiffer/mc.prm")
refused "montecarlo on rank 0, subset on rank 1" "rank 1's differs from rank 0's in the command" \
  $(mc "$work/a/mc.prm") : -np 1 "$poundfe" subset "$work/a/mc.prm" --output "$work/out"

# the same model from another directory, with its own copy of force.txt
timeout -k 5 60 "$mpirun" $(mc "$work/a/mc.prm") : $(mc "$work/copy/mc.prm") > "$work/log" 2>&1 ||
  fail "montecarlo, the same model from two directories: $(head -c 600 "$work/log")"
[ "$(rows "$work/out/realizations.csv" | wc -l)" -eq 4 ] || fail "montecarlo, copies: not 4 realizations"
echo "ok   montecarlo, the same model and force file from two directories: runs, 4 realizations"

# run partitioned by building: MPI is initialised only once the input says so
part="set Partition = buildings"
model "$work/part" && sed -i "/^subsection Time integration/a\\  $part" "$work/part/mc.prm"
model "$work/part-stiffer" && sed -i -e "/^subsection Time integration/a\\  $part" \
  -e 's/Storey stiffnesses = 4e6/Storey stiffnesses = 4.5e6/' "$work/part-stiffer/mc.prm"
run() { echo -np 1 "$poundfe" run "$1" --output "$work/out"; }
refused "run partitioned, rank 1's parameter file missing" \
  "poundfe: error: rank 1: $work/none.prm: cannot open the parameter file (no such file)" \
  $(run "$work/part/mc.prm") : $(run "$work/none.prm")
refused "run partitioned, rank 1 given another stiffness" \
  "rank 1's differs from rank 0's in 'Building 2/Storey stiffnesses'" \
  $(run "$work/part/mc.prm") : $(run "$work/part-stiffer/mc.prm")
