#!/usr/bin/env bash
# poundfe switching (issue 25 item 2): the Filippov switching analysis.
#   - a block on a belt (switching-belt.prm: m = k = N = 1, mu_s = 0.4,
#     mu_k = 0.2, v0 = 0.1, starting stuck): the closed form's
#     4 s of stick, 2 pi - 2 atan 2 s of slip, each switch to 1e-6 s (the
#     events are located to 1e-12 s, the slip integrated at relative
#     tolerance 1e-10: measured ~1e-10 s);
#   - the thesis's spillway (input/thesis/fig-3.7.prm): g1 (the gap) crossed
#     12 times and g2 (the rate in contact) 6 times in [0, 3] s, as the
#     thesis's §3.3.4 counts, each hit's time within 2e-4 s of Table 3.1;
#   - a start on the gap at rest: grazing (a = b = 0);
#   - every row of every log: its class agrees with the signs of its
#     normal components a, b (crossing a b > 0, attracting sliding a > 0 > b,
#     sliding exit with a or b = 0 to 1e-6 of max |a|, |b| (the located
#     exit's residual), grazing to 1e-8);
# then bad input: a model with a hysteretic storey: exit 1, no output.
set -eu
poundfe=$1 cli=$2 thesis=$3
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$here/helpers.sh"

"$poundfe" switching "$cli/switching-belt.prm" --output "$work/belt" > /dev/null
"$poundfe" switching "$thesis/fig-3.7.prm" --output "$work/spillway" > /dev/null
sed -e 's/^\( *set Harmonic *=\).*/\1/' "$thesis/fig-3.7.prm" |
  sed -e '/^subsection Time integration/i subsection Initial conditions\n  set State = 0.005, 0\nend\n' \
  > "$work/grazing.prm"
"$poundfe" switching "$work/grazing.prm" --output "$work/grazing" > /dev/null

python3 - "$work" <<'PY' || fail "switching"
import csv, json, math, sys
work = sys.argv[1]
def log(name):
    return list(csv.DictReader(open(f"{work}/{name}/switching.csv")))
def check_classes(rows):
    for r in rows:
        a, b, c = float(r["normal_minus"]), float(r["normal_plus"]), r["class"]
        scale = max(abs(a), abs(b))
        if c == "crossing":
            assert a * b > 0, r
        elif c == "attracting-sliding":
            assert a > 0 > b, r
        elif c == "repulsive-sliding":
            assert a < 0 < b, r
        elif c == "grazing":
            assert min(abs(a), abs(b)) <= 1e-8 * scale, r
        elif c == "sliding-exit":
            assert min(abs(a), abs(b)) <= 1e-6 * scale, r
        else:
            raise AssertionError(r)
# the belt: stick [0, 4], slip 2 pi - 2 atan 2, stick 4 s, ...
belt = log("belt")
check_classes(belt)
slip = 2 * math.pi - 2 * math.atan(2)
expected = [(0, "attracting-sliding"), (4, "sliding-exit"), (4 + slip, "attracting-sliding"),
            (8 + slip, "sliding-exit"), (8 + 2 * slip, "attracting-sliding")]
got = [(float(r["time_s"]), r["class"]) for r in belt]
assert [c for _, c in got] == [c for _, c in expected], got
worst = max(abs(t - e) for (t, _), (e, _) in zip(got, expected))
print(f"belt: {len(got)} hits, stick intervals within {worst:.2g} s of the closed form")
assert worst <= 1e-6, worst
summary = json.load(open(f"{work}/belt/summary.json"))
intervals = [(s["entry_s"], s["exit_s"]) for s in summary["sliding_intervals"]]
assert len(intervals) == 3 and abs(intervals[1][1] - intervals[1][0] - 4) <= 1e-6, intervals
# the spillway: 12 crossings of g1, 6 of g2, at Table 3.1's times
spill = log("spillway")
check_classes(spill)
counts = {s["name"]: s for s in json.load(open(f"{work}/spillway/summary.json"))["surfaces"]}
gap = [s for n, s in counts.items() if n.endswith(" gap")][0]
rate = [s for n, s in counts.items() if n.endswith(" rate")][0]
assert gap["hits"] == gap.get("crossing", 0) == 12, gap
assert rate["hits"] == rate.get("crossing", 0) == 6, rate
table = [0.4006, 0.4071, 0.4172, 0.8384, 0.8446, 0.8543, 1.2818, 1.2880, 1.2977,
         1.7307, 1.7368, 1.7467, 2.1798, 2.1860, 2.1958, 2.6286, 2.6348, 2.6446]
times = [float(r["time_s"]) for r in spill]
worst = max(abs(t - e) for t, e in zip(times, table))
print(f"spillway: g1 {gap['hits']}, g2 {rate['hits']} hits; against Table 3.1 within {worst:.2g} s")
assert len(times) == 18 and worst <= 2e-4, (times, worst)
# a start on the gap at rest: a grazing
graze = log("grazing")
check_classes(graze)
assert [r["class"] for r in graze] == ["grazing"], graze
PY

# a model with hysteretic storeys: refused, naming the model
set +e
"$poundfe" switching "$cli/newton-shear-pair.prm" --output "$work/hysteretic" > /dev/null 2> "$work/hysteretic.err"
status=$?
set -e
[ "$status" = 1 ] || fail "hysteretic: exit $status, not 1"
grep -q "newton-shear-pair.prm:[0-9]*: parameter 'Model/Number of buildings'.*hysteretic storey" "$work/hysteretic.err" ||
  fail "hysteretic: $(cat "$work/hysteretic.err")"
[ ! -e "$work/hysteretic" ] || fail "hysteretic: wrote $work/hysteretic"
echo "switching: ok"
