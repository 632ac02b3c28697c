#!/usr/bin/env bash
# A resumed table is tied to the contents of every file its input names
# (output/output_directory.h: resume_file): its record "<table>.inputs" holds
# a digest (size, FNV-1a) of each record, force table, mesh, ... and a rerun
# after one of them changed is refused with exit 1 and a message naming the
# file and its entry, before any realization runs, the table untouched:
#   - montecarlo after the tabulated force file was edited (and resumed
#     while it is unchanged);
#   - a record of an earlier version, without digests: refused, unverifiable;
#   - mitigation after its record was doubled (before: the old numbers);
#   - subset (its journal) after a building's Gmsh mesh was edited (its top
#     storey taller).
# Reference: the refusal itself (exit status, message, the table's bytes).
#   resume_digests.sh POUNDFE INPUT_DIR
set -eu
poundfe=$1 input=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(cd "$(dirname "$0")" && pwd)/helpers.sh"
cd "$work"

# 2 s of a 2 Hz record in g (time, acceleration), and a force history
awk 'BEGIN { for (i = 0; i <= 200; ++i) printf "%.2f %.6f\n", i / 100, 0.3 * sin(12.566 * i / 100) }' > record.txt
awk 'BEGIN { for (i = 0; i <= 20; ++i) printf "%.1f,%.1f\n", i / 10, 2000 * (i % 2) }' > force.csv
doubled() { awk '{ printf "%s %.6f\n", $1, 2 * $2 }' "$1" > "$1.new" && mv "$1.new" "$1"; }

# the mitigation example's pair, 2 s of motion, a tabulated force on the roof
sed -e '/^subsection Monte Carlo/,/^end/d' -e 's/set Duration         = 5/set Duration         = 2/' \
    -e 's/set Damper coefficients = .*/set Damper coefficients = 0, 5e3/' \
    -e 's/set Bumper thicknesses  = .*/set Bumper thicknesses  = 0.002/' \
    "$input/mitigation-shear-pair.prm" > pair.prm
grep -q "Duration         = 2" pair.prm || fail "the duration was not set"
cat >> pair.prm <<'PRM'
subsection Nodal forces
  set Tabulated = shear3 3 0 ux force.csv
end
subsection Monte Carlo
  set Realizations = 3
end
PRM

# refused DIR TEXT COMMAND...: exit 1, TEXT on stderr, DIR's table untouched
refused() {
  local directory=$1 text=$2 status=0
  shift 2
  local table=$directory/realizations.csv
  [ -f "$table" ] || table=$directory/subset_runs.csv
  cp "$table" before.csv
  "$poundfe" "$@" > stdout 2> stderr || status=$?
  [ "$status" -eq 1 ] || fail "$*: exit $status after a changed file, expected 1: $(head -c 400 stderr)"
  grep -qF -- "$text" stderr || fail "$*: no '$text' in: $(head -c 400 stderr)"
  cmp -s before.csv "$table" || fail "$*: the table was changed"
  echo "ok   $*: $(head -c 300 stderr)"
}

# montecarlo: resumed while the force table is the same, refused once edited
"$poundfe" montecarlo pair.prm --output mc > /dev/null
sed 's/set Realizations = 3/set Realizations = 4/' pair.prm > four.prm
"$poundfe" montecarlo four.prm --output mc > stdout
grep -q "resuming: 3" stdout || fail "an unchanged force table did not resume: $(cat stdout)"
grep -qF "digest of the tabulated force file 'force.csv' (Nodal forces/Tabulated) = " \
  mc/realizations.csv.inputs || fail "no digest of the force table in the record of the input"
cp force.csv force.orig
sed -i 's/^1.0,.*/1.0,9000.0/' force.csv
refused mc "the tabulated force file 'force.csv' (Nodal forces/Tabulated) changed since these realizations were computed" \
  montecarlo pair.prm --output mc
cp force.orig force.csv

# a record of an earlier version: no digest lines, nothing to check them by
grep -v '^digest of ' mc/realizations.csv.inputs > old.inputs && mv old.inputs mc/realizations.csv.inputs
refused mc "no digest of the files the input names" montecarlo pair.prm --output mc

# mitigation on the one record: the record doubled is refused, not the old numbers
sed -e '/^subsection Ground motion/,/^end/d' pair.prm > record.prm
cat >> record.prm <<'PRM'
subsection Ground motion
  set Type = record
  subsection Record
    set File = record.txt
  end
end
PRM
"$poundfe" mitigation record.prm --output mitigation > /dev/null
[ -f mitigation/realizations.csv ] || fail "mitigation wrote no realizations.csv"
cp record.txt record.orig
doubled record.txt
refused mitigation "the record file 'record.txt' (Ground motion/Record/File) changed" \
  mitigation record.prm --output mitigation
cp record.orig record.txt

# subset of a Gmsh frame: its journal refused after the mesh's top storey was raised
cp "$input/../meshes/setback.msh" setback.msh
sed -e 's|set Mesh file .*|set Mesh file = setback.msh|' -e 's/set Duration   = 20/set Duration   = 2/' \
    -e 's/set Time step = 0.002/set Time step = 0.005/' "$input/setback-frame.prm" > mesh.prm
cat >> mesh.prm <<'PRM'
subsection Subset simulation
  set Response          = peak roof displacement
  set Building          = 1
  set Threshold         = 0.05
  set Samples per level = 10
  set Maximum levels    = 2
end
PRM
"$poundfe" subset mesh.prm --output subset > /dev/null
[ -f subset/subset_runs.csv ] || fail "subset wrote no subset_runs.csv"
sed -i 's/^\(1[01] [0-9]* \)9.5 0$/\110 0/' setback.msh
grep -q '^10 0 10 0$' setback.msh || fail "the mesh was not edited"
refused subset "the mesh file 'setback.msh' (Building 1/Mesh file) changed" subset mesh.prm --output subset

echo "resume_digests: every changed file refused"
