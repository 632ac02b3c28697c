#!/usr/bin/env bash
# The pushover command and the gravity analysis through the real binary:
#   bad input (exit 1, one line naming the entry, nothing written): a control
#     building or floor that does not exist, a cyclic push without a
#     protocol, a non-positive target drift, a negative floor load;
#   a push that cannot go on (a mechanism at once: storeys with no
#     post-yield stiffness pushed beyond their strength without arc length)
#     exits 2 with the curve so far in pushover.csv and a failed summary;
#   the example input: pushover.csv, summary.json with the gravity state and
#     the capacity curve's idealisation and N2 target, and a run of the same
#     file that starts from the gravity state (summary.json "gravity").
#   pushover.sh POUNDFE SOURCE_DIR
set -u
poundfe=$(readlink -f "$1") source=$(readlink -f "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
. "$source/tests/cli/expect.sh"

# a shear building with $1 in Building 1 and $2 in the Pushover section
push() {
  shear "$1"
  printf 'subsection Ground motion\n  set Type = none\nend\n'
  printf 'subsection Pushover\n%s\nend\n' "${2:-}"
}

push '' '  set Control building = 2' > building.prm
expect 1 "Pushover/Control building" pushover building.prm --output out
push '' '  set Control floor = 4' > floor.prm
expect 1 "Pushover/Control floor" pushover floor.prm --output out
push '' '  set Type = cyclic' > protocol.prm
expect 1 "Pushover/Protocol" pushover protocol.prm --output out
push '' '  set Target drift = 0' > target.prm
expect 1 "Pushover/Target drift" pushover target.prm --output out
push '' '  set Target drift = -0.01' > negative-target.prm
expect 1 "Pushover/Target drift" pushover negative-target.prm --output out
push '  set Floor loads = 1e4, -5, 0' '' > loads.prm
expect 1 "Building 1/Floor loads" pushover loads.prm --output out
expect 1 "Building 1/Floor loads" run loads.prm --output out

# storeys that yield in the first step, which one Newton iteration cannot
# converge, with one step cut and no arc length: exit 2, the curve so far
push '  set Storey yield drifts = 0.002
  subsection Bouc-Wen
    set alpha = 0
    set n = 40
  end' '  set Target drift = 0.5
  set Number of steps = 5
  set Max step cuts = 1
  set Max iterations = 1
  set Arc length = false' > mechanism.prm
expect 2 "pushover: no equilibrium" pushover mechanism.prm --output out
[ -s out/pushover.csv ] && [ "$(wc -l < out/pushover.csv)" -ge 2 ] ||
  fail "a failed pushover keeps no curve: $(ls out 2>&1)"
grep -q '"status": "failed"' out/summary.json || fail "a failed pushover's summary: $(cat out/summary.json)"

# the example: a frame with gravity first, its pushover and its run
example=$source/input/pushover-frame.prm
n=$((n + 1))
if "$poundfe" pushover "$example" --output push > stdout 2> stderr; then
  python3 - push/summary.json push/pushover.csv <<'PY' || fail "pushover's outputs"
import csv, json, sys
s = json.load(open(sys.argv[1]))
assert s["status"].startswith("completed"), s["status"]
g = s["gravity"]
assert g["peak_displacement_m"] > 0 and all(r > 0 for r in g["base_vertical_reactions_N"]), g
c = s["capacity"]
assert 0 < c["yield_displacement_m"] < c["ultimate_displacement_m"], c
assert c["target_displacement_m"] > 0, c
rows = list(csv.DictReader(open(sys.argv[2])))
assert len(rows) > 10 and float(rows[0]["load_factor"]) == 0.0
assert float(rows[-1]["base_shear_N"]) > 0
PY
  echo "ok   pushover $example"
else
  fail "pushover $example: $(head -c 400 stderr)"
fi
n=$((n + 1))
if "$poundfe" run "$example" --output run --set "Time integration/End time=0.2" > stdout 2> stderr; then
  grep -q '"gravity"' run/summary.json || fail "run after gravity: no gravity in summary.json"
  echo "ok   run $example"
else
  fail "run $example: $(head -c 400 stderr)"
fi
report pushover
