#!/usr/bin/env bash
# Soil coupling of two compliant foundations through the command line
# (Links/Soil coupling; doc/verification.md, "Compliant foundations";
# theory §1.16), on input/soil-shear-pair.prm shortened to 4 s of motion:
#  - k = c = 0 is the uncoupled pair exactly (impacts, floor displacements,
#    energies byte-identical);
#  - k = 2e6 N/m, c = 2e4 N s/m: the energy balance closes to 1e-8 and the
#    coupling dissipates;
#  - k = 1e12 N/m (~1e4 times the foundations' sway springs), the limit of a
#    rigid soil between them: the coupling's peak deformation is below 1e-3
#    of the peak sway.
# Bad input (a fixed base, a negative k): tests/cli/bad/foundation-coupling-*.prm.
set -eu
poundfe=$1 input=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/helpers.sh" # fail

grep -q '^subsection Contact' "$input/soil-shear-pair.prm" || fail "no Contact section to put Links before"
sed -e 's/set Duration *= .*/set Duration = 4/' -e 's/^subsection Output/&\n  set Plots = false/' \
  "$input/soil-shear-pair.prm" > "$work/soil.prm"
grep -q 'set Duration = 4' "$work/soil.prm" || fail "the example's duration was not shortened"
"$poundfe" run "$work/soil.prm" --output "$work/soil" > /dev/null
couple() { # name k c
  sed -e "s/^subsection Contact/subsection Links\n  set Soil coupling = shear3 shear2 $2 $3\nend\n&/" \
    "$work/soil.prm" > "$work/$1.prm"
  "$poundfe" run "$work/$1.prm" --output "$work/$1" > /dev/null
}
couple zero 0 0
couple coupled 2e6 2e4
couple tied 1e12 0
for f in impacts.csv floor_displacement.csv; do
  cmp -s "$work/soil/$f" "$work/zero/$f" || fail "zero soil coupling: $f differs"
done
cut -d, -f1-9 "$work/soil/energy.csv" > "$work/a.csv"
cut -d, -f1-9 "$work/zero/energy.csv" > "$work/b.csv"
cmp -s "$work/a.csv" "$work/b.csv" || fail "zero soil coupling: energy.csv differs"
python3 - "$work" <<'PY' || fail "soil coupling"
import json, sys
w = sys.argv[1]
c = json.load(open(w + "/coupled/summary.json"))
e = c["energy"]
link = [l for l in c["links"] if l["label"].startswith("soil_")][0]
print(f"coupled: energy balance {e['max_relative_balance_error']:.3g}, coupling dissipates "
      f"{link['dissipated_energy_J']:.6g} J of input {e['input_J']:.6g} J")
assert e["max_relative_balance_error"] <= 1e-8 and link["dissipated_energy_J"] > 0
t = json.load(open(w + "/tied/summary.json"))
link = [l for l in t["links"] if l["label"].startswith("soil_")][0]
sway = max(f["peak_sway_m"] for f in t["foundations"])
print(f"tied: coupling deformation {link['peak_deformation_m']:.3g} m against peak sway {sway:.3g} m")
assert link["peak_deformation_m"] <= 1e-3 * sway
assert t["energy"]["max_relative_balance_error"] <= 1e-8
PY
echo "ok   soil coupling: zero is uncoupled, balance, a stiff coupling ties the sways"
