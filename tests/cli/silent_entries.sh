#!/usr/bin/env bash
# Nothing silent (doc/verification.md, "Entries without effect"): an entry
# that has no effect in the model it is in is refused (exit 1, one line naming
# file, line and entry, nothing written) or, where the run still makes sense,
# reported as a warning on the terminal and in summary.json:
#   refused: an entry tagged for another building Type, dimension or member
#     model ([frame], [3D], [frame, fibre] ...), written in a .prm file, a
#     JSON file or by --set: a 3D entry in a planar model, Column E on a
#     shear building;
#   warned: a contact law that makes no gap element (3D slabs that face
#     nothing), a contact-law entry the law does not use, Model/Separations
#     with one building or beside a Plan/Position for every building it
#     would place; an entry another entry's value leaves without effect
#     (model/entry_scope.h: warn_entries_without_effect): Storey stiffnesses
#     beside typed Resisting planes of a 3D shear building, Bouc-Wen entries
#     of a building with no hinge or hysteretic storey, Hinges entries
#     without Locations, a Damping entry of another Damping/Type, a
#     Foundation entry with Type = none.
#   silent_entries.sh POUNDFE
set -u
poundfe=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
. "$here/expect.sh"

# warned TEXT: after an expect 0, TEXT in stderr as a warning and in summary.json
warned() {
  grep -F "poundfe: warning: " stderr | grep -qF -- "$1" || { fail "no warning '$1' on the terminal"; return; }
  grep -qF -- "$1" out/summary.json || { fail "summary.json lacks '$1'"; return; }
  echo "ok   warned: $(grep -F -- "$1" stderr | head -1 | head -c 200)"
}

short() { # the 3D buildings below run 0.05 s of the default ground motion
  printf 'subsection Time integration\n  set Time step = 0.01\n  set End time = 0.05\nend\n'
}
plan_pair() { # two 3D shear buildings; $1: Model entries, $2 and $3: their Plan entries, $4: Contact
  printf 'subsection Model\n  set Number of buildings = 2\n  set Dimension = 3\n%s\nend\n' "$1"
  for b in 1 2; do
    printf 'subsection Building %s\n  set Type = shear\n  set Number of storeys = 2\n' "$b"
    printf '  set Floor masses = 1000\n  set Storey stiffnesses = 5e6\n'
    printf '  subsection Plan\n    set Plan dimensions = 6, 6\n%s\n  end\nend\n' "$([ "$b" = 1 ] && echo "$2" || echo "$3")"
  done
  printf 'subsection Contact\n%s\nend\n' "$4"
  printf 'subsection Output\n  set Plots = false\n  set Number of modes = 2\nend\n'
  short
}

# refused: a 3D entry in a planar model names its file, line and entry
shear '  set Number of bays y = 2' > planar.prm
expect 1 "planar.prm:6: parameter 'Building 1/Number of bays y': has no effect on a 2D shear building: it is a [3D frame] entry (Type = frame, Model/Dimension = 3); remove it, or set Type = frame and set Model/Dimension = 3" run planar.prm --output out
shear '  set Vertical floor mass = none' > planar-mass.prm
expect 1 "planar-mass.prm:6: parameter 'Building 1/Vertical floor mass': has no effect on a 2D shear building" run planar-mass.prm --output out
# refused: an entry of another Type (its help's tag) on a 3D shear building
# (model/entry_scope.h; unit/model walks every tagged entry)
for entry in 'Column E = 3e10' 'Diaphragm = none' 'Vertical floor mass = none'; do
  { printf 'subsection Model\n  set Dimension = 3\nend\n'
    shear "$(printf '  subsection Plan\n    set Plan dimensions = 6, 6\n  end\n  set %s' "$entry")"; } > other-type.prm
  expect 1 "other-type.prm:12: parameter 'Building 1/${entry%% =*}': has no effect on a 3D shear building: it is a [" run other-type.prm --output out
done
# ... only with the fibre members it is for
{ printf 'subsection Building 1\n  set Type = frame\n  set Member element = displacement\nend\n'
  printf 'subsection Output\n  set Plots = false\nend\n'; } > hinges-frame.prm
expect 1 "hinges-frame.prm:3: parameter 'Building 1/Member element': has no effect on a 2D frame building with Member model = elastic-hinges" run hinges-frame.prm --output out
# ... a key of a JSON file (no line) and an override alike
printf '{ "Building 1": { "Type": "shear", "Number of storeys": "2", "Floor masses": "1000",\n  "Storey stiffnesses": "5e6", "Column E": "3e10" } }\n' > shear.json
expect 1 "shear.json: parameter 'Building 1/Column E': has no effect on a 2D shear building" run shear.json --output out
shear '' > plain.prm
expect 1 "plain.prm: parameter 'Building 1/Plan/Rotation': has no effect on a 2D shear building" run plain.prm --output out --set "Building 1/Plan/Rotation=30"
# ... and the same entries run where they apply: a default never counts
expect 0 "results in out" run plain.prm --output out
# warned: Separations when every building after the first has a Position
plan_pair '  set Separations = 0.05' '    set Position = 0, 0' '    set Position = 6.1, 0' '  set Law = linear' > placed.prm
expect 0 "results in out" run placed.prm --output out
warned "placed.prm:4: parameter 'Model/Separations': has no effect: every building after the first has Plan/Position" 
# ... but with the second building placed by it, the run goes on
plan_pair '  set Separations = 0.05' '    set Position = 0, 0' '' '  set Law = linear' > separated.prm
expect 0 "results in out" run separated.prm --output out
grep -q "warning" stderr && fail "separated.prm warns: $(cat stderr)"

# warned: a contact law with no facing slabs (the second building 20 m east and north)
plan_pair '' '    set Position = 0, 0' '    set Position = 20, 20' '  set Law = linear' > apart.prm
expect 0 "results in out" run apart.prm --output out
warned "apart.prm:27: parameter 'Contact/Law': has no effect: no gap element was made"
# warned: restitution and damping entries of an undamped law, a given damping's restitution
plan_pair '  set Separations = 0.05' '' '' "$(printf '  set Law = linear\n  set Coefficient of restitution = 0.5')" > elastic.prm
expect 0 "results in out" run elastic.prm --output out
warned "parameter 'Contact/Coefficient of restitution': has no effect: Contact/Law = linear has no damping"
plan_pair '  set Separations = 0.05' '' '' "$(printf '  set Law = kelvin-voigt\n  set Damping from = given\n  set Damping = 0.1\n  set Coefficient of restitution = 0.5')" > given.prm
expect 0 "results in out" run given.prm --output out
warned "parameter 'Contact/Coefficient of restitution': has no effect: Damping from = given uses Damping"
# warned: Separations with one building
{ printf 'subsection Model\n  set Separations = 0.05\nend\n'; shear; } > alone.prm
expect 0 "results in out" run alone.prm --output out
warned "alone.prm:2: parameter 'Model/Separations': has no effect: the model has one building"
# warned: entries another entry's value leaves without effect, each with its
# file, line and entry; the same entries where they act warn nothing
planes='    set Resisting planes = 3 0 90 2.5e6; -3 0 90 2.5e6; 0 3 0 2.5e6; 0 -3 0 2.5e6'
{ printf 'subsection Model\n  set Dimension = 3\nend\n'
  shear "$(printf '  subsection Plan\n    set Plan dimensions = 6, 6\n%s\n  end' "$planes")"; short; } > planes.prm
expect 0 "results in out" run planes.prm --output out
warned "planes.prm:8: parameter 'Building 1/Storey stiffnesses': has no effect: Plan/Resisting planes are typed"
{ printf 'subsection Model\n  set Dimension = 3\nend\n'
  shear "$(printf '  subsection Plan\n    set Plan dimensions = 6, 6\n  end')"; short; } > perimeter.prm
expect 0 "results in out" run perimeter.prm --output out
grep -q "has no effect" stderr && fail "perimeter.prm warns: $(cat stderr)"
{ printf 'subsection Building 1\n  set Type = frame\n  subsection Bouc-Wen\n    set alpha = 0.1\n  end\n'
  printf '  subsection Hinges\n    set Yield moment = 1e5\n  end\nend\n'
  printf 'subsection Output\n  set Plots = false\nend\n'; short; } > elastic-frame.prm
expect 0 "results in out" run elastic-frame.prm --output out
warned "elastic-frame.prm:4: parameter 'Building 1/Bouc-Wen/alpha': has no effect: the building has no hinge (Hinges/Locations is empty)"
warned "elastic-frame.prm:7: parameter 'Building 1/Hinges/Yield moment': has no effect: the building has no hinge"
sed 's/    set Yield moment = 1e5/    set Locations = column bases\n    set Yield moment = 1e5/' elastic-frame.prm > hinged-frame.prm
expect 0 "results in out" run hinged-frame.prm --output out
grep -q "has no effect" stderr && fail "hinged-frame.prm warns: $(cat stderr)"
{ shear "$(printf '  subsection Bouc-Wen\n    set n = 2\n  end')"; short; } > elastic-shear.prm
expect 0 "results in out" run elastic-shear.prm --output out
warned "elastic-shear.prm:7: parameter 'Building 1/Bouc-Wen/n': has no effect: the building has no hysteretic storey"
{ shear "$(printf '  subsection Damping\n    set Type = modal\n    set Modal ratios = 0.05\n    set a1 = 0.002\n  end')"; short; } > modal.prm
expect 0 "results in out" run modal.prm --output out
warned "modal.prm:9: parameter 'Building 1/Damping/a1': has no effect: Damping/Type = modal does not use it (Type = coefficients does)"
{ shear "$(printf '  subsection Foundation\n    set Shear-wave velocity = 200\n  end')"; short; } > fixed.prm
expect 0 "results in out" run fixed.prm --output out
warned "fixed.prm:7: parameter 'Building 1/Foundation/Shear-wave velocity': has no effect: Foundation/Type = none: a fixed base"
report "entries without effect"
