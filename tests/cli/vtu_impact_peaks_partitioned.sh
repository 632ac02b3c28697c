#!/usr/bin/env bash
# Output/VTU impact peaks in a run partitioned by building (Time
# integration/Partition = buildings) writes the frames of the whole model's
# run: the small city block (3 buildings, gaps between ranks) with a 0.25 s
# VTU interval, on one process without the partition and on 2 ranks with
# it: the same frame times in solution.pvd (exactly: the same step times
# through the same shortest text), frames off the interval among them (the
# impact peaks), each frame's arrays within the partitioned run's
# tolerance; and Field format = xdmf written by the 2 ranks together: the
# same frames as their VTU series (tests/cli/xdmf.py --compare).
#   vtu_impact_peaks_partitioned.sh POUNDFE MPIRUN INPUT
set -eu
poundfe=$1 mpirun=$2 input=$3
here=$(dirname "$0")
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL $*"; exit 1; }
# the solver settings and tolerance of tests/cli/partitioned_run.sh: only
# the order of sums differs between the runs (3e-12 of a peak measured)
tolerance=1e-8
solver="set Linear solver = umfpack\n  set Tangent update = refactorize\n  set Nonlinear solver = krylov-newton\n  set Newton residual tolerance = 1e-11"
sed -e "s/set Linear solver = petsc-mumps/$solver/" \
    -e "s/set VTU interval    = 0/set VTU interval = 0.25\n  set VTU impact peaks = true/" \
    "$input" > "$work/whole.prm"
sed -e "/^subsection Time integration/a\\  set Partition = buildings" "$work/whole.prm" > "$work/part.prm"
"$poundfe" run "$work/whole.prm" --output "$work/whole" > /dev/null
"$mpirun" -np 2 "$poundfe" run "$work/part.prm" --output "$work/part" > "$work/part.log"
grep -q "VTU interval only" "$work/part.log" && fail "the partitioned run still says it writes the regular frames only"
times() { grep -o 'timestep="[^"]*"' "$1/solution.pvd" | cut -d'"' -f2; }
diff <(times "$work/whole") <(times "$work/part") > "$work/diff.txt" ||
  { head "$work/diff.txt"; fail "2 ranks: other frame times than the whole model's run"; }
n=$(times "$work/whole" | wc -l)
peaks=$(times "$work/whole" | python3 -c "
import sys
print(sum(abs(t / 0.25 - round(t / 0.25)) > 1e-9 for t in map(float, sys.stdin)))")
[ "$peaks" -gt 0 ] || fail "no frame at an impact's peak: the check tests nothing"
for frame in "$work"/whole/solution/*.vtu; do
  python3 "$here/same_vtu.py" "$tolerance" "$frame" "$work/part/solution/$(basename "$frame")" \
    || fail "2 ranks: $(basename "$frame") differs"
done
echo "ok   2 ranks, Partition = buildings: the whole model's $n frames ($peaks at impact peaks)"
sed -e "s/^subsection Output/subsection Output\n  set Field format = xdmf/" "$work/part.prm" > "$work/together.prm"
mkdir "$work/fields" && ln -s "$work/part" "$work/fields/vtu"
"$mpirun" -np 2 "$poundfe" run "$work/together.prm" --output "$work/fields/xdmf" > /dev/null
python3 "$here/xdmf.py" --compare "$work/fields" solution > "$work/together.log" ||
  { cat "$work/together.log"; fail "2 ranks, HDF5 written together: not the VTU frames"; }
echo "ok   2 ranks, Field format = xdmf written together: the same $n frames"
