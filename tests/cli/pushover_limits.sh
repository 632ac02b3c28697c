#!/usr/bin/env bash
# The limit states of fibre members in a pushover, and where they are not
# followed (doc/theory.md §13.5):
#   - the pushover of input/fibre-frame-pounding.prm with an EC8 target
#     spectrum: summary.json's section_limit_states, one entry per fibre
#     member, a limit's first control displacement present exactly when its
#     ratio reached 1 and within the push; storey_damage_states at the N2
#     target displacement, at the first point of the curve that reaches it
#     (pushover.csv), each storey's state the worst limit of its members
#     (the columns below a floor, the beams of that floor) whose first
#     control displacement is at or before that point's; the same at the
#     end of the push without a target;
#   - pushover.csv's damage_state column of every storey at every step: the
#     worst limit its members reached at or before that step's displacement;
#   - the yield curvatures follow the axial force: the two columns of storey
#     1 of A (the same N at the gravity state) end the push at yield
#     curvatures more than 2 % apart (tension side against compression side);
#   - a run partitioned by building (Partition = buildings) of fibre
#     buildings: exit 1 naming Time integration/Partition, nothing written
#     (a rank sees only its own members: their limit states would be lost).
#   pushover_limits.sh POUNDFE EXAMPLE
set -u
poundfe=$1 example=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
. "$(dirname "$0")/expect.sh" 2> /dev/null || . "$OLDPWD/$(dirname "$0")/expect.sh"

cp "$example" target.prm
printf 'subsection Spectrum\n  set Target = ec8-type-1\n  set Ground type = B\n  set Design ground acceleration = 0.3\nend\n' >> target.prm
"$poundfe" pushover target.prm --output target --set "Output/Plots=false" > /dev/null ||
  fail "pushover with a target: exit $?"
"$poundfe" pushover "$example" --output end --set "Output/Plots=false" > /dev/null ||
  fail "pushover without a target: exit $?"
python3 - target end <<'PY' || fail "pushover limit states"
import csv, json, sys
order = ["none", "yield", "spalling", "crushing", "fracture"]
limit_of = {"bar_yield": "yield", "spalling": "spalling", "crushing": "crushing",
            "bar_fracture": "fracture"}
for d, at in zip(sys.argv[1:], ["target displacement", "end of the push"]):
    s = json.load(open(d + "/summary.json"))
    rows = list(csv.DictReader(open(d + "/pushover.csv")))
    u = [float(r["control_displacement_m"]) for r in rows]
    members = s["section_limit_states"]
    assert len(members) == 21, len(members)  # 4 storeys x 3 members + 3 x 3
    damage = s["storey_damage_states"]
    assert damage["at"] == at, (d, damage["at"])
    if at == "target displacement":
        target = s["capacity"]["target_displacement_m"]
        first = next(i for i, x in enumerate(u) if abs(x - u[0]) >= target)
        assert damage["point"] == first, (damage["point"], first)
    else:
        assert damage["point"] == len(u) - 1, damage["point"]
    there = u[damage["point"]]
    assert abs(damage["control_displacement_m"] - there) <= 1e-12, there
    worst = {}
    for m in members:
        reached = "none"
        for name, limit in m["limits"].items():
            r, x = limit["ratio"], limit["first_control_displacement_m"]
            assert (x is not None) == (r >= 1 - 1e-12), (m["member"], name, r, x)
            if x is not None:
                assert u[0] - 1e-12 <= x <= u[-1] + 1e-12, (m["member"], name, x)
                if x <= there + 1e-12 and order.index(limit_of[name]) > order.index(reached):
                    reached = limit_of[name]
        key = (m["building"], m["storey"])
        worst[key] = max(worst.get(key, "none"), reached, key=order.index)
    for b in damage["buildings"]:
        states = b["storeys"]
        expected = [worst[(b["building"], i + 1)] for i in range(len(states))]
        assert states == expected, (d, b["building"], states, expected)
    # pushover.csv's damage state of every storey at every step: the worst
    # limit its members reached at or before that step's displacement
    storeys = [k[len("drift "):] for k in rows[0] if k.startswith("drift ")]
    firsts = [(m["building"], m["storey"], order.index(limit_of[name]), limit["first_control_displacement_m"])
              for m in members for name, limit in m["limits"].items()
              if limit["first_control_displacement_m"] is not None]
    k = 0
    for b in damage["buildings"]:
        for i in range(len(b["storeys"])):
            column = "damage_state " + storeys[k]
            k += 1
            for r, x in zip(rows, u):
                expected = max([0] + [o for (bb, st, o, f) in firsts
                                      if bb == b["building"] and st == i + 1 and f <= x + 1e-12])
                assert float(r[column]) == expected, (d, column, x, r[column], expected)
    # the yield curvatures follow the axial force: the two columns of storey 1
    # (equal N under gravity) end the push at different ones
    ky = [next(m for m in members if m["member"] == c)["yield_curvature_positive_1_m"][0]
          for c in ("A_C1.1", "A_C1.2")]
    assert abs(ky[0] - ky[1]) > 0.02 * max(ky), ky
    print("ok: %s at %s (%.4f m): %s" % (d, at, there,
          [b["storeys"] for b in damage["buildings"]]))
PY

expect 1 "Time integration/Partition" run "$example" --output out \
  --set "Time integration/Partition=buildings"

[ "$failures" -eq 0 ] || { echo "$failures of $n failed"; exit 1; }
echo "ok: pushover limit states, $n refusals"
