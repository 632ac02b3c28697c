#!/usr/bin/env bash
# Start-up: the executable links only the C and C++ runtimes and answers a
# lone --version without loading deal.II (nor MPI, PETSc, Trilinos: the
# ~200 libraries whose relocations cost 0.4-0.6 s of CPU, doc/benchmarks.md
# "Start-up"); every other command line runs the program module
# poundfe-program.so beside it, whose --version says the same line, but
# `poundfe opensees SCRIPT`, which runs in poundfe-opensees.so without
# deal.II; without the module the executable says so in one line and exits 1. Not under mpirun,
# a small modal, an empty opensees script and --help start no MPI.
# Argument: the poundfe executable of the build tree.
set -u
poundfe=$(realpath "$1")
source_dir=$(realpath "$(dirname "${BASH_SOURCE[0]}")/../..")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail() { echo "FAIL $*"; exit 1; }

# 1. What the executable links: the runtimes, nothing of deal.II's.
needed=$(readelf -d "$poundfe" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p' | sort | tr '\n' ' ')
for library in $needed; do
  case $library in
    libc.so.* | libm.so.* | libstdc++.so.* | libgcc_s.so.* | libdl.so.*) ;;
    *) fail "poundfe links $library (all: $needed)" ;;
  esac
done
echo "ok   poundfe links only $needed"

# 2. A lone --version loads no other library (the loader's own log).
LD_DEBUG=files LD_DEBUG_OUTPUT="$work/loader" "$poundfe" --version > version || fail "--version exited $?"
loaded=$(cat "$work"/loader.* | grep -c 'file=.*\[0\];  needed by\|file=.*\[0\];  dynamically loaded by')
grep -q 'file=libdeal\|poundfe-program' "$work"/loader.* && fail "--version loaded deal.II or the program"
grep -Eq '^poundfe \(git [^)]+\), deal\.II [0-9]+\.[0-9]+\.[0-9]+, contact models: penalty(, nonsmooth, Siconos Numerics)?$' version || fail "--version said: $(cat version)"
echo "ok   --version: $(cat version), $loaded libraries loaded"

# 3. --version among other words goes to the program, which says the same.
"$poundfe" modal --version > program-version || fail "modal --version exited $?"
cmp -s version program-version || fail "the program's version line differs: $(cat program-version)"
"$poundfe" --version --nonsense 2> stderr && fail "--version --nonsense was accepted"
grep -q "unknown option '--nonsense'" stderr || fail "--version --nonsense: $(cat stderr)"
echo "ok   the program module answers --version alike and checks the other words"

# 3b. `poundfe opensees SCRIPT` runs in the interpreter's module, which
# needs none of deal.II, MPI, PETSc or Trilinos and loads no other module;
# `opensees` without a script, or with an option first, is the program's.
needed=$(readelf -d "$(dirname "$poundfe")/poundfe-opensees.so" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p' | tr '\n' ' ')
case " $needed" in
  *" libdeal"* | *" libmpi"* | *" libpetsc"* | *" libtrilinos"*) fail "poundfe-opensees.so links $needed" ;;
esac
: > empty.tcl
LD_DEBUG=files LD_DEBUG_OUTPUT="$work/lean" "$poundfe" opensees empty.tcl > lean-stdout ||
  fail "opensees on an empty script exited $?: $(cat lean-stdout)"
grep -q 'file=.*poundfe-opensees.so' "$work"/lean.* || fail "opensees did not load poundfe-opensees.so"
grep -q 'file=libdeal\|poundfe-program\|file=libmpi' "$work"/lean.* &&
  fail "opensees on a script loaded deal.II, MPI or the program"
lean_loaded=$(cat "$work"/lean.* | grep -c 'file=.*\[0\];  needed by\|file=.*\[0\];  dynamically loaded by')
"$poundfe" opensees 2> stderr && fail "opensees without a script was accepted"
grep -q "'opensees' needs a script" stderr && grep -q '^usage' stderr ||
  fail "opensees without a script: $(cat stderr)"
echo "ok   opensees SCRIPT loads poundfe-opensees.so and $lean_loaded libraries, no deal.II; without a script the program refuses it"

# 4. Without the module beside it (nor installed relative to it).
mkdir alone && cp "$poundfe" alone/
alone/poundfe --version | cmp -s - version || fail "--version needs the module"
alone/poundfe modal x.prm > stdout 2> stderr && fail "ran without its module"
[ "$(wc -l < stderr)" -eq 1 ] && grep -q "poundfe: error: cannot load the program" stderr ||
  fail "without the module: $(cat stderr)"
alone/poundfe opensees empty.tcl > stdout 2> stderr && fail "opensees ran without its module"
[ "$(wc -l < stderr)" -eq 1 ] && grep -q "poundfe: error: cannot load the program: poundfe-opensees.so" stderr ||
  fail "opensees without its module: $(cat stderr)"
echo "ok   without the modules: $(cat stderr)"

# 5. Not under mpirun, a command whose row and input do not need MPI starts
# neither MPI nor PETSc (MPI_InitFinalize: the dominant cost after the loader's).
# The probe: PETSC_OPTIONS=-version makes PETSc's initialisation print its
# version line; a command of the mpi column shows that it can (it initialises
# MPI before reading its file, which does not exist here).
if ! ldd "$(dirname "$poundfe")/poundfe-program.so" | grep -q libpetsc; then
  echo "ok   (deal.II without PETSc: no probe of MPI's start)"
  exit 0
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
PETSC_OPTIONS=-version "$poundfe" montecarlo absent.prm > mpi-probe 2>&1
grep -q 'Petsc Release Version' mpi-probe || fail "the probe does not see MPI_InitFinalize: $(cat mpi-probe)"
PETSC_OPTIONS=-version "$poundfe" modal "$source_dir/input/three-storey-shear.prm" --output modal \
  > modal-stdout 2>&1 || fail "modal exited $?: $(cat modal-stdout)"
PETSC_OPTIONS=-version "$poundfe" opensees empty.tcl > opensees-stdout 2>&1 ||
  fail "opensees on an empty script exited $?: $(cat opensees-stdout)"
PETSC_OPTIONS=-version "$poundfe" --help > help-stdout 2>&1 || fail "--help exited $?"
for run in modal-stdout opensees-stdout help-stdout; do
  grep -q 'Petsc Release Version' $run && fail "${run%-stdout} initialised MPI and PETSc"
done
echo "ok   modal, an empty opensees script and --help start no MPI (montecarlo does)"
