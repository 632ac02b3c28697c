#!/usr/bin/env bash
# Suspicious damping choices warn on the console and in summary.json, and
# the run goes on (issue 14 item 15): Rayleigh damping fitted at vertical
# modes (checked against the modal output: those modes carry no horizontal
# mass), mass-proportional damping alone, both coefficients 0, entries the
# chosen Type ignores. Sound inputs (the examples named below) warn nothing.
#   damping_warnings.sh POUNDFE VERTICAL_PRM EXAMPLE.prm...
set -eu
poundfe=$1 vertical=$2
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL $*"; exit 1; }
# run FILE NAME: exit 0, stderr in NAME.err, summary in NAME/summary.json
run() {
  "$poundfe" run "$1" --output "$work/$2" > /dev/null 2> "$work/$2.err" || fail "$2: exit $?: $(cat "$work/$2.err")"
  grep -q '"status": "completed"' "$work/$2/summary.json" || fail "$2: not completed"
}
# warned NAME TEXT: on stderr as 'poundfe: warning: ...' and in summary.json
warned() {
  grep -F "poundfe: warning: " "$work/$1.err" | grep -qF -- "$2" || fail "$1: no warning '$2': $(cat "$work/$1.err")"
  grep -qF -- "$2" "$work/$1/summary.json" || fail "$1: summary.json lacks '$2'"
  echo "ok   $1: $(grep -F -- "$2" "$work/$1.err" | head -1)"
}

# Vertical modes: the modes named are those of the modal analysis without
# horizontal mass (mass ratio (x) < 1 %), the sway mode is not named.
cp "$vertical" "$work/vertical.prm"
printf 'subsection Time integration\n  set Time step = 0.01\n  set End time = 0.1\nend\n' >> "$work/vertical.prm"
"$poundfe" modal "$vertical" --output "$work/modal" > "$work/modal.out" 2> /dev/null
for mode in 1 2; do
  awk -v m=$mode '$1 == m && $4 < 0.01 { found = 1 } END { exit !found }' "$work/modal.out" ||
    fail "mode $mode of $vertical is not free of horizontal mass: $(cat "$work/modal.out")"
done
run "$work/vertical.prm" vertical
for mode in 1 2; do warned vertical "Damping/Modes fits the damping ratio at mode $mode ("; done
[ "$(grep -c 'Damping/Modes fits' "$work/vertical.err")" -eq 2 ] || fail "vertical: warned other than modes 1 and 2"
sed 's/set Modes = 1, 2/set Modes = 1, 4/' "$work/vertical.prm" > "$work/sway.prm"
awk '$1 == 4 && $4 > 0.9 { found = 1 } END { exit !found }' "$work/modal.out" || fail "mode 4 is not the sway mode"
run "$work/sway.prm" sway
[ "$(grep -c 'Damping/Modes fits' "$work/sway.err")" -eq 1 ] || fail "sway: mode 4 warned or mode 1 not"

shear() { # damping-subsection lines
  cat <<PRM
subsection Building 1
  set Type               = shear
  set Number of storeys  = 3
  set Floor masses       = 1000
  set Storey stiffnesses = 5e6
  subsection Damping
$1
  end
end
subsection Ground motion
  set Type = none
end
subsection Output
  set Number of modes = 3
end
subsection Time integration
  set Time step = 0.01
  set End time  = 0.1
end
PRM
}
shear "    set Type = coefficients
    set a0   = 0.5" > "$work/mass-only.prm"
run "$work/mass-only.prm" mass-only
warned mass-only "a1 = 0, mass-proportional damping only"
shear "    set Type = coefficients" > "$work/zero.prm"
run "$work/zero.prm" zero
warned zero "a0 and a1 are both 0: the building has no Rayleigh damping"
shear "    set Type          = none
    set Damping ratio = 0.05" > "$work/ignored.prm"
run "$work/ignored.prm" ignored
warned ignored "ignored.prm:8: parameter 'Building 1/Damping/Damping ratio': has no effect: Damping/Type = none does not use it (Type = modes does)"
shear "    set Type = coefficients
    set a0   = 0.5
    set a1   = 0.002" > "$work/sound.prm"
for file in "$work/sound.prm" "$@"; do
  name=sound-$(basename "$file" .prm)
  run "$file" "$name"
  ! grep -q "warning" "$work/$name.err" || fail "$name: $(cat "$work/$name.err")"
  grep -q '"warnings": \[\]' "$work/$name/summary.json" || fail "$name: summary.json has warnings"
  echo "ok   $name: no warning"
done
