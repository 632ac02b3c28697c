#!/usr/bin/env bash
# Entries that name a building (Contact/Barriers, Nodal forces, Springs,
# Friction: 'building floor ...', Subset simulation/Building) take its
# number or its Name (issue 14 item 15): the same two-building model written
# with numbers and with names gives byte-identical results, and so does the
# subset example with its building named; a name no building has is refused with the
# names that exist; a name two buildings share is refused as ambiguous.
set -eu
poundfe=$1 input=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
fail() { echo "FAIL $*"; exit 1; }
cat > numbers.prm <<'PRM'
subsection Model
  set Number of buildings = 2
  set Separations         = 0.01
end
subsection Building 1
  set Name               = west
  set Type               = shear
  set Number of storeys  = 2
  set Floor masses       = 1000
  set Storey stiffnesses = 4e6
end
subsection Building 2
  set Name               = east
  set Type               = shear
  set Number of storeys  = 3
  set Floor masses       = 1000
  set Storey stiffnesses = 6e6
end
subsection Ground motion
  set Type = none
end
subsection Contact
  set Law      = linear
  set Barriers = 1 2 left 0.004; 2 3 right 0.006
end
subsection Springs
  set Cubic springs = 2 1 0 1e5 1e9
end
subsection Nodal forces
  set Harmonic = 1 2 0 ux 2e4 12; 2 3 0 ux 1e4 20 0.5
end
subsection Time integration
  set Time step = 0.005
  set End time  = 2
end
PRM
sed -e 's/Barriers = 1 2 left 0.004; 2 3 right/Barriers = west 2 left 0.004; east 3 right/' \
    -e 's/Cubic springs = 2 1 0/Cubic springs = east 1 0/' \
    -e 's/Harmonic = 1 2 0 ux 2e4 12; 2 3 0/Harmonic = west 2 0 ux 2e4 12; east 3 0/' \
    numbers.prm > names.prm
[ "$(diff numbers.prm names.prm | grep -c '^>')" -eq 3 ] || fail "the names were not all put in"
"$poundfe" run numbers.prm --output out-numbers > /dev/null || fail "numbers: exit $?"
"$poundfe" run names.prm --output out-names > /dev/null || fail "names: exit $?"
n=0
for f in out-numbers/*.csv; do
  cmp -s "$f" "out-names/$(basename "$f")" || fail "$(basename "$f") differs between numbers and names"
  n=$((n + 1))
done
[ "$(wc -l < out-numbers/impacts.csv)" -gt 1 ] || fail "no impact: the barriers are not exercised"
echo "ok   numbers and names: $n CSV files identical, $(($(wc -l < out-numbers/impacts.csv) - 1)) impacts"
refused() { # file expected
  set +e
  message=$("$poundfe" run "$1" --output out-bad 2>&1 > /dev/null); status=$?
  set -e
  [ $status -eq 1 ] || fail "$1 exited $status: $message"
  [ ! -e out-bad ] || fail "$1: output written"
  echo "$message" | grep -qF -- "$2" || fail "$1: message lacks '$2': $message"
  echo "ok   $1: $message"
}
sed 's/Barriers = west 2/Barriers = north 2/' names.prm > unknown-barrier.prm
refused unknown-barrier.prm "unknown-barrier.prm:24: parameter 'Contact/Barriers': 'north 2 left 0.004': building must be 1..2 or a Name ('west', 'east'), got 'north'"
sed 's/Harmonic = west 2/Harmonic = West 2/' names.prm > unknown-force.prm
refused unknown-force.prm "parameter 'Nodal forces/Harmonic': 'West 2 0 ux 2e4 12': building must be 1..2 or a Name ('west', 'east'), got 'West'"
sed 's/set Name               = east/set Name               = west/' names.prm > shared-name.prm
refused shared-name.prm "buildings 1 and 2 are both named 'west'; give the building's number"
sed 's/Barriers = west 2/Barriers = 3 2/' names.prm > number-too-large.prm
refused number-too-large.prm "building must be 1..2 or a Name ('west', 'east'), got '3'"

# Subset simulation/Building: input/subset-drift.prm names its building S1
sed 's/set Building                = 1/set Building                = S1/' "$input/subset-drift.prm" > subset-name.prm
grep -q 'Building  *= S1' subset-name.prm || fail "the subset building was not named"
"$poundfe" subset "$input/subset-drift.prm" --output subset-number > /dev/null || fail "subset by number: exit $?"
"$poundfe" subset subset-name.prm --output subset-name > /dev/null || fail "subset by name: exit $?"
cmp -s subset-number/subset_levels.csv subset-name/subset_levels.csv ||
  fail "subset_levels.csv differs between the building's number and its Name"
echo "ok   Subset simulation/Building = S1: subset_levels.csv identical to Building = 1"
sed 's/set Building                = 1/set Building                = S2/' "$input/subset-drift.prm" > subset-unknown.prm
refused subset-unknown.prm "parameter 'Subset simulation/Building': 'S2': building must be 1..1 or a Name ('S1'), got 'S2'"
