#!/usr/bin/env bash
# The energy balance of fibre frames pounding after gravity, with the
# members' self-weight distributed along them (Member self-weight =
# distributed): the examples input/fibre-frame-pounding.prm (2D) and
# input/fibre-frame-3d.prm (3D), each force-based (as written) and
# displacement-based (Member element = displacement), run until after their
# first impacts. In each run
#   - the frames pound (impacts > 0);
#   - the balance closes to 1e-8 of the input energy at every row of
#     energy.csv (every step): |input + constant_load - (kinetic + damping +
#     strain + hysteretic + contact)| <= 1e-8 max_t input. The norm is the
#     excitation's work, not the total supplied: the held gravity loads' work
#     and the strain energy from the gravity state are both large and
#     largely cancel (the weight does work as the joints move and the
#     members store it), so a norm that counted them would make the same
#     error look smaller; and summary.json's running relative error <= 1e-8;
#   - the held loads do work (constant_load_J != 0) and the run starts from
#     rest at the gravity state (strain 0 at t = 0, initial_J 0 to 1e-9 of
#     the input).
# A member's own load's work enters both constant_load and the member's work,
# so it cancels here: the unit test energy_terms_after_gravity_by_member_model
# (hysteretic 0 on elastic sections, both formulations) is what checks it.
#   gravity_energy.sh POUNDFE EXAMPLE_2D EXAMPLE_3D
set -u
poundfe=$1 example_2d=$2 example_3d=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

# $1: the example, $2: its end time, $3: the member element, $4: its
# buildings' names
run_case() {
  local example=$1 end=$2 element=$3 name=$4
  local sets=(--set "Time integration/End time=$end"
              --set "Output/Plots=false"
              --set "Output/Recorders/Record=energy every 0")
  for b in 1 2; do
    sets+=(--set "Building $b/Member element=$element"
           --set "Building $b/Member self-weight=distributed"
           --set "Building $b/Member unit weight=25e3")
  done
  "$poundfe" run "$example" --output "$name" "${sets[@]}" > /dev/null ||
    { fail "$name: exit $?"; return; }
  python3 - "$name/summary.json" "$name/energy.csv" "$name" <<'PY' || fail "$3: balance"
import csv, json, sys
s = json.load(open(sys.argv[1]))
e = s["energy"]
rows = list(csv.DictReader(open(sys.argv[2])))
impacts = sum(g.get("impacts", 0) for g in s.get("gaps", []))
terms = ("kinetic_J", "damping_J", "strain_J", "hysteretic_J", "contact_J", "friction_J",
         "links_J")
largest_input = max(abs(float(r["input_J"])) for r in rows)
residual = max(abs(float(r["input_J"]) + float(r["constant_load_J"]) + float(r["belt_J"]) -
                   sum(float(r[t]) for t in terms)) for r in rows)
relative = residual / largest_input
start = abs(float(rows[0]["strain_J"]))
work = max(abs(float(r["constant_load_J"])) for r in rows)
print(f"{sys.argv[3]}: {len(rows)} rows, impacts {impacts}, input up to {largest_input:.6g} J, "
      f"held loads' work up to {work:.6g} J, balance residual {residual:.3g} J = "
      f"{relative:.3g} of the input, running error {e['max_relative_balance_error']:.3g}, "
      f"hysteretic {e['hysteretic_J']:.6g} J")
ok = (impacts > 0 and relative <= 1e-8 and e["max_relative_balance_error"] <= 1e-8 and
      work > 0 and e["constant_load_J"] != 0 and start <= 1e-9 * largest_input and
      abs(e["initial_J"]) <= 1e-9 * largest_input)
sys.exit(0 if ok else 1)
PY
}

for element in force displacement; do
  run_case "$example_2d" 3 "$element" "2d-$element"
  run_case "$example_3d" 2 "$element" "3d-$element"
done

if [ "$failures" -gt 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "all fibre frames' energy balances close"
