#!/usr/bin/env bash
# The mitigation study through the command line (doc/verification.md,
# "Mitigation study"; theory §1.17), on input/mitigation-shear-pair.prm
# (bare, dampers c = 0, 5e3, 2e4 with alpha = 0.5, bumpers of 2 and 5 mm;
# 4 realizations of a Kanai-Tajimi motion):
#  1. a damper of c = 0 is the bare pair: every realization's drifts, floor
#     accelerations, impacts and impact force equal the bare case's exactly;
#     the largest approach (free run: Newton with a zero-force element
#     against the bare pair's linear steps) to 1e-12;
#  2. mitigation.csv's statistics recomputed from realizations.csv (means,
#     P(pounding) = the fraction with an impact, the bumpers' gap D_bare + t,
#     the type-7 quantile) to 1e-12;
#  3. the damper case c = 5e3 against `poundfe run` of the file with the
#     damper written by hand in Links/Viscous dampers (realization 0:
#     drifts, floor accelerations, impacts, impact force) and against
#     `poundfe separation` of that file (the mean largest approach and the
#     gap for the target probability over the same 4 realizations), to 1e-12;
#     the bumper case t = 2 mm against `poundfe run` with a Bumpers section.
# Bad input (empty lists, negative c, alpha, a bumper thicker than the gap,
# a damper at a floor that does not exist): tests/cli/bad/mitigation-*.prm.
set -eu
poundfe=$1 input=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/helpers.sh" # fail

example="$input/mitigation-shear-pair.prm"
"$poundfe" mitigation "$example" --output "$work/study" > /dev/null 2>&1 || fail "the example"
[ -s "$work/study/mitigation.png" ] || fail "no mitigation.png"

# the same pair run directly: the damper of damper2 and the bumper of bumper1
# by hand (the numbers only: no plots, no VTU)
sed -e 's/^subsection Output/&\n  set Plots = false\n  set VTU interval = 0/' "$example" > "$work/quiet.prm"
sed -e 's/^subsection Mitigation/subsection Links\n  set Viscous dampers = shear3 2 0 shear2 2 0 5e3 0.5\nend\n&/' \
  "$work/quiet.prm" > "$work/damper.prm"
sed -e 's/^subsection Mitigation/subsection Bumpers\n  set Law = linear\n  set Thickness = 0.002\n  set Stiffness = 2e6\nend\n&/' \
  "$work/quiet.prm" > "$work/bumper.prm"
for case in damper bumper; do
  "$poundfe" run "$work/$case.prm" --output "$work/$case" > /dev/null 2>&1 || fail "run $case"
done
"$poundfe" separation "$work/damper.prm" --output "$work/separation" > /dev/null 2>&1 ||
  fail "separation"

python3 - "$work" <<'PY' || fail "mitigation study"
import csv, json, sys
w = sys.argv[1]
table = {r["case"]: r for r in csv.DictReader(open(w + "/study/mitigation.csv"))}
rows = sorted(csv.DictReader(open(w + "/study/realizations.csv")), key=lambda r: int(r["realization"]))
buildings = ["shear3", "shear2"]
cases = list(table)
assert cases == ["bare", "damper1", "damper2", "damper3", "bumper1", "bumper2"], cases
near = lambda a, b, tol=1e-12: abs(a - b) <= tol * max(abs(a), abs(b), 1e-300)

# 1. c = 0 is the bare pair
for r in rows:
    for what in ["peak_drift_ratio_shear3", "peak_drift_ratio_shear2", "peak_floor_acc_m_s2",
                 "n_impacts", "peak_impact_force_N"]:
        assert r["damper1_" + what] == r["bare_" + what], (what, r["realization"])
    assert near(float(r["damper1_largest_approach_m"]), float(r["bare_largest_approach_m"]))
assert table["bare"]["p_pounding"] != "0", "the bare pair does not pound"
print(f"c = 0 equals the bare pair on {len(rows)} realizations "
      f"(P(pounding) {table['bare']['p_pounding']})")

# 2. the statistics from realizations.csv
def quantile(x, p):  # type 7
    x = sorted(x); h = (len(x) - 1) * p; i = int(h)
    return x[i] + (h - i) * ((x[i + 1] if i + 1 < len(x) else x[i]) - x[i])
target = json.load(open(w + "/study/summary.json"))["target_probability"]
for c in cases:
    col = lambda what: [float(r[c + "_" + what]) for r in rows if r["completed"] == "1"]
    mean = lambda x: sum(x) / len(x)
    t = table[c]
    for b in buildings:
        assert near(float(t["peak_drift_ratio_" + b]), mean(col("peak_drift_ratio_" + b)))
    larger = [max(a, b) for a, b in zip(col("peak_drift_ratio_shear3"), col("peak_drift_ratio_shear2"))]
    assert near(float(t["max_drift_ratio"]), mean(larger))
    assert near(float(t["peak_floor_acc_m_s2"]), mean(col("peak_floor_acc_m_s2")))
    assert near(float(t["n_impacts"]), mean(col("n_impacts")))
    assert near(float(t["max_impact_force_N"]), max(col("peak_impact_force_N")))
    assert near(float(t["p_pounding"]), mean([n > 0 for n in col("n_impacts")]))
    assert near(float(t["required_gap_m"]), mean(col("largest_approach_m")))
    assert near(float(t["required_gap_target_m"]), quantile(col("largest_approach_m"), 1 - target))
    if t["kind"] == "bumper":
        bare = [float(r["bare_largest_approach_m"]) for r in rows if r["completed"] == "1"]
        thickness = float(t["bumper_thickness_m"])
        assert all(near(a, b + thickness) for a, b in zip(col("largest_approach_m"), bare))
print("mitigation.csv = the statistics of realizations.csv")

# 3. against poundfe run (realization 0) and poundfe separation
r0 = rows[0]
for case, directory in [("damper2", "damper"), ("bumper1", "bumper")]:
    s = json.load(open(f"{w}/{directory}/summary.json"))
    for b in s["buildings"]:
        drift = max(st["peak_drift_ratio"] for st in b["storeys"])
        assert near(drift, float(r0[f"{case}_peak_drift_ratio_{b['name']}"])), (case, b["name"])
    acc = max(st["peak_absolute_floor_acceleration_m_s2"] for b in s["buildings"] for st in b["storeys"])
    assert near(acc, float(r0[case + "_peak_floor_acc_m_s2"])), case
    impacts = sum(g["impacts"] for g in s["gaps"])
    force = max(g["peak_force_N"] for g in s["gaps"])
    assert impacts == float(r0[case + "_n_impacts"]), (case, impacts)
    assert near(force, float(r0[case + "_peak_impact_force_N"])), case
    print(f"{case} = poundfe run (realization 0): {impacts} impacts, peak force {force:.6g} N")
p = json.load(open(w + "/separation/summary.json"))["pairs"][0]
assert near(p["time_history_m"], float(table["damper2"]["required_gap_m"]))
assert near(p["pounding"]["gap_for_target_probability_m"], float(table["damper2"]["required_gap_target_m"]))
print(f"damper2's required gap = poundfe separation's: {p['time_history_m']:.6g} m")
PY
echo "ok   mitigation: c = 0 is the bare pair, the table, the direct runs"

# 4. a record (realization 0 of the motion as a text file): one run per case
"$poundfe" ground-motion "$work/quiet.prm" --output "$work/motion" > /dev/null 2>&1
tail -n +2 "$work/motion/ground_motion.csv" | tr , ' ' > "$work/record.txt"
python3 - "$work/quiet.prm" "$work" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
record = ("subsection Ground motion\n  set Type = record\n  subsection Record\n"
          "    set File  = record.txt\n    set Units = m/s^2\n  end\nend\n")
text = re.sub(r"subsection Ground motion\n.*?\n  end\nend\n", record, text, flags=re.S)
open(sys.argv[2] + "/record.prm", "w").write(text)
links = "subsection Links\n  set Viscous dampers = shear3 2 0 shear2 2 0 2e4 0.5\nend\n"
open(sys.argv[2] + "/record-damper.prm", "w").write(text.replace("subsection Mitigation", links + "subsection Mitigation"))
PY
"$poundfe" mitigation "$work/record.prm" --output "$work/record" > /dev/null 2>&1 || fail "record study"
"$poundfe" run "$work/record-damper.prm" --output "$work/record-damper" > /dev/null 2>&1 ||
  fail "record run"
python3 - "$work" <<'PY' || fail "record study"
import csv, json, sys
w = sys.argv[1]
rows = list(csv.DictReader(open(w + "/record/realizations.csv")))
assert len(rows) == 1, len(rows)
r = rows[0]
for what in ["peak_drift_ratio_shear3", "peak_drift_ratio_shear2", "peak_floor_acc_m_s2",
             "n_impacts", "peak_impact_force_N"]:
    assert r["damper1_" + what] == r["bare_" + what], what
s = json.load(open(w + "/record-damper/summary.json"))
near = lambda a, b: abs(a - b) <= 1e-12 * max(abs(a), abs(b), 1e-300)
for b in s["buildings"]:
    assert near(max(st["peak_drift_ratio"] for st in b["storeys"]),
                float(r["damper3_peak_drift_ratio_" + b["name"]])), b["name"]
print(f"record: c = 0 is the bare pair ({r['bare_n_impacts']} impacts); c = 2e4 = poundfe run")
PY
echo "ok   mitigation of a record"
