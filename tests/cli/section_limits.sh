#!/usr/bin/env bash
# The limit states of fibre members (Section limits; doc/theory.md §13.5) in
# the run of input/fibre-frame-pounding.prm:
#   - summary.json's section_limit_states: one entry per fibre member, four
#     integration points each, yield curvatures within a factor 2 of
#     Priestley et al.'s 2.1 eps_y / h, ratios >= 0, a first time exactly
#     when a ratio reached 1 (within the run), each member's damage state
#     its worst limit reached, each storey's (buildings[].storey_damage_states
#     and drift_profile.csv's damage_state) its worst member's;
#   - the section states recorder (sections.csv) of a column, every step:
#     N < 0 at t = 0 (gravity), its largest curvature at most the summary's
#     peak (which also sees the substeps) and near it;
#   - bad input (expect.sh): limits of the wrong sign, zero or a word, and a
#     recorder of no fibre member: exit 1 naming the entry, nothing written.
#   section_limits.sh POUNDFE EXAMPLE
set -u
poundfe=$1 example=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
. "$(dirname "$0")/expect.sh" 2> /dev/null || . "$OLDPWD/$(dirname "$0")/expect.sh"

"$poundfe" run "$example" --output run --set "Output/Plots=false" \
  --set "Output/Recorders/Record=section states of A_C1.1 every 0" > /dev/null ||
  fail "example run: exit $?"
python3 - run <<'PY' || fail "summary.json's section limit states"
import csv, json, math, sys
d = sys.argv[1]
s = json.load(open(d + "/summary.json"))
members = s["section_limit_states"]
assert len(members) == 21, len(members)  # 4 storeys x 3 members + 3 x 3
order = ["none", "yield", "spalling", "crushing", "fracture"]
limit_of = {"bar_yield": "yield", "spalling": "spalling", "crushing": "crushing",
            "bar_fracture": "fracture"}
duration = s["ground_motion"]["duration_s"]
worst = {}
for m in members:
    h = 0.4 if "_C" in m["member"] else 0.5
    for k in ("yield_curvature_positive_1_m", "yield_curvature_negative_1_m"):
        assert len(m[k]) == 4, (m["member"], k)
        for ky in m[k]:
            estimate = 2.1 * 450e6 / 200e9 / h
            assert 0.5 * estimate < ky < 2 * estimate, (m["member"], k, ky, estimate)
    assert all(mu >= 0 for mu in m["curvature_ductility"]), m["member"]
    assert all(e <= 0 for e in m["peak_concrete_strain"]), m["member"]
    state = "none"
    for name, limit in m["limits"].items():
        r, t = limit["ratio"], limit["first_time_s"]
        assert r is not None and r >= 0, (m["member"], name, r)
        assert (t is not None) == (r >= 1 - 1e-12), (m["member"], name, r, t)
        assert t is None or 0 <= t <= duration, (m["member"], name, t)
        if t is not None and order.index(limit_of[name]) > order.index(state):
            state = limit_of[name]
    assert m["damage_state"] == state, (m["member"], m["damage_state"], state)
    key = (m["building"], m["storey"])
    worst[key] = max(worst.get(key, "none"), state, key=order.index)
    spalling = m["limits"]["spalling"]
    assert spalling["strain"] == -0.004, spalling
    assert m["limits"]["bar_yield"]["strain"] == 450e6 / 200e9, m["limits"]["bar_yield"]
assert any(m["limits"]["bar_yield"]["ratio"] > 0.1 for m in members), "no demand at all"
rows = list(csv.DictReader(open(d + "/drift_profile.csv")))
for b in s["buildings"]:
    states = b["storey_damage_states"]
    assert states == [worst[(b["name"], i + 1)] for i in range(len(states))], (b["name"], states)
    assert [r["damage_state"] for r in rows if r["building"] == b["name"]] == states
# the recorder of A_C1.1 against the summary's peaks
sec = list(csv.DictReader(open(d + "/sections.csv")))
a = next(m for m in members if m["member"] == "A_C1.1")
assert float(sec[0]["A_C1.1_ip1_N_N"]) < 0, sec[0]["A_C1.1_ip1_N_N"]
for i in range(4):
    kappa = max(float(r["A_C1.1_ip%d_kappa_1_m" % (i + 1)]) for r in sec)
    peak = a["peak_curvature_positive_1_m"][i]
    assert kappa <= peak + 1e-12 and kappa >= 0.5 * peak, (i, kappa, peak)
    steel = max(float(r["A_C1.1_ip%d_steel_strain_max" % (i + 1)]) for r in sec)
    assert steel <= a["peak_steel_strain_max"][i] + 1e-12, (i, steel)
print("ok: section limit states of %d members; storeys %s" %
      (len(members), [b["storey_damage_states"] for b in s["buildings"]]))
PY

expect 1 "Section limits/Spalling strain" run "$example" --output out \
  --set "Section limits/Spalling strain=0.004"
expect 1 "Section limits/Crushing strain" run "$example" --output out \
  --set "Section limits/Crushing strain=0"
expect 1 "Section limits/Bar yield strain" run "$example" --output out \
  --set "Section limits/Bar yield strain=-0.002"
expect 1 "Section limits/Bar fracture strain" run "$example" --output out \
  --set "Section limits/Bar fracture strain=large"
expect 1 "Output/Recorders/Record" run "$example" --output out \
  --set "Output/Recorders/Record=section states of A_C9.1"

[ "$failures" -eq 0 ] || { echo "$failures of $n failed"; exit 1; }
echo "ok: section limit states, $n refusals"
