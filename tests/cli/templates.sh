#!/usr/bin/env bash
# `poundfe template KIND` (issue 14 item 15): each starting file is the
# repository's input/templates/KIND.prm byte for byte and runs as written
# (the mesh one after making its mesh from the .geo in its comments, with
# gmsh; the stochastic one also through montecarlo with 3 realizations);
# an unknown or missing kind is refused with the list of kinds.
set -eu
poundfe=$1 templates=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
fail() { echo "FAIL $*"; exit 1; }
for file in "$templates"/*.prm; do
  kind=$(basename "$file" .prm)
  "$poundfe" template "$kind" > "$kind.prm" || fail "$kind: exit $?"
  cmp -s "$kind.prm" "$file" || fail "$kind: not the text of $file"
  if [ "$kind" = mesh ]; then
    sed -n '/^# BEGIN frame.geo/,/^# END frame.geo/p' mesh.prm | sed '1d;$d; s/^# //' > frame.geo
    gmsh -1 -format msh22 frame.geo -o frame.msh > /dev/null || fail "mesh: gmsh"
  fi
  "$poundfe" run "$kind.prm" --output "out-$kind" > /dev/null || fail "$kind: run exited $?"
  grep -q '"status": "completed"' "out-$kind/summary.json" || fail "$kind: not completed"
  echo "ok   $kind"
done
sed 's/set Realizations = 100 /set Realizations = 3   /' stochastic.prm > stochastic-3.prm
grep -q 'Realizations = 3 ' stochastic-3.prm || fail "stochastic: no Realizations entry to shorten"
"$poundfe" montecarlo stochastic-3.prm --output out-mc > /dev/null || fail "stochastic: montecarlo exited $?"
grep -q '"status": "completed"' out-mc/summary.json || fail "stochastic: montecarlo not completed"
echo "ok   stochastic (montecarlo, 3 realizations)"
for bad in "template" "template nosuchkind" "template frame extra"; do
  set +e
  message=$("$poundfe" $bad 2>&1 > /dev/null); status=$?
  set -e
  [ $status -eq 1 ] || fail "'$bad' exited $status"
  echo "$message" | grep -q "one of: frame, frame3d, mesh, pounding, shear, shear3d, stochastic" || fail "'$bad': $message"
done
echo "ok   bad kinds refused"
