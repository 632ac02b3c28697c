#!/usr/bin/env bash
# Links between buildings and bumpers in the gap through the command line
# (doc/verification.md, "Links and bumpers"; theory §1.14, §4.9):
#  1. a bumper of zero thickness reproduces the bare contact: the pair of
#     input/shear-pair-pounding.prm with and without it gives the same
#     impacts, energies and floor displacements to 1e-8;
#  2. the example input/linked-shear-pair.prm: the energy balance closes to
#     1e-8 with dampers and a bumper, the links dissipate energy (links_J > 0,
#     their sum over summary.json's links equals links_J to 1e-12), every
#     impact says what it touched and the bumper object counts them;
#  3. Maxwell and elastic-plastic links: energy balance 1e-8 as well.
# Bad input (alpha, floors, negative c/k, bumpers): tests/cli/bad/link-*.prm,
# bumper-*.prm in cli/bad-input.
set -eu
poundfe=$1 input=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/helpers.sh" # fail, same_csv


# 1. zero-thickness bumper = bare contact
cp "$input/shear-pair-pounding.prm" "$work/bare.prm"
{ cat "$input/shear-pair-pounding.prm"
  printf 'subsection Bumpers\n  set Law = hertz\n  set Thickness = 0\n  set Stiffness = 1e9\nend\n'
} > "$work/zero.prm"
"$poundfe" run "$work/bare.prm" --output "$work/bare" > /dev/null
"$poundfe" run "$work/zero.prm" --output "$work/zero" > /dev/null
[ "$(wc -l < "$work/bare/impacts.csv")" -gt 1 ] || fail "the bare pair does not pound"
cut -d, -f1-11 "$work/zero/impacts.csv" > "$work/zero-impacts.csv"
same_csv "$work/bare/impacts.csv" "$work/zero-impacts.csv" 1e-8 || fail "zero-thickness bumper: impacts"
for f in energy.csv floor_displacement.csv; do
  cut -d, -f1-10 "$work/bare/$f" > "$work/a.csv"
  cut -d, -f1-10 "$work/zero/$f" > "$work/b.csv"
  same_csv "$work/a.csv" "$work/b.csv" 1e-8 || fail "zero-thickness bumper: $f"
done
echo "ok   a bumper of zero thickness is the bare contact"

# 2. the example
"$poundfe" run "$input/linked-shear-pair.prm" --output "$work/linked" > /dev/null
python3 - "$work/linked" <<'PY' || fail "linked example"
import csv, json, sys
d = sys.argv[1]
s = json.load(open(d + "/summary.json"))
e = s["energy"]
error = e["max_relative_balance_error"]
links = s["links"]
total = sum(l["dissipated_energy_J"] for l in links)
print(f"energy balance {error:.3g}, links {e['links_J']:.6g} J of input {e['input_J']:.6g} J")
assert error <= 1e-8, "energy balance"
assert e["links_J"] > 0, "no energy in links"
assert abs(total - e["links_J"]) <= 1e-12 * e["links_J"], "links' energies do not add up"
assert len(links) == 2 and {l["kind"] for l in links} == {"viscous", "kelvin-voigt"}
rows = list(csv.DictReader(open(d + "/impacts.csv")))
touched = [r["touched"] for r in rows]
assert rows and set(touched) <= {"bumper", "structure", "bumper+structure"}, touched
b = s["bumper"]
assert b["impacts_on_bumper_only"] + b["impacts_reaching_structure"] == len(rows)
assert b["impacts_on_bumper_only"] == touched.count("bumper")
print(f"{len(rows)} impacts: {touched.count('bumper')} on the bumper only, "
      f"{len(rows) - touched.count('bumper')} reaching the structure")
PY
echo "ok   the linked example: balance, links' energy, impacts say what they touched"

# 3. Maxwell and elastic-plastic links
sed -e 's/set Viscous dampers .*/set Maxwell links = shear3 2 0 shear2 2 0 2e4 500/' \
    -e 's/set Kelvin-Voigt links .*/set Elastic-plastic links = shear3 1 0 shear2 1 0 2e4 100 0.05/' \
    "$input/linked-shear-pair.prm" > "$work/other.prm"
"$poundfe" run "$work/other.prm" --output "$work/other" > /dev/null
python3 - "$work/other/summary.json" <<'PY' || fail "Maxwell and elastic-plastic links"
import json, sys
s = json.load(open(sys.argv[1]))
e = s["energy"]
print(f"energy balance {e['max_relative_balance_error']:.3g}, links {e['links_J']:.6g} J, "
      f"peak link forces {[round(l['peak_force_N']) for l in s['links']]} N")
assert e["max_relative_balance_error"] <= 1e-8 and e["links_J"] > 0
assert {l["kind"] for l in s["links"]} == {"maxwell", "elastic-plastic"}
PY
echo "ok   Maxwell and elastic-plastic links close the energy balance"
