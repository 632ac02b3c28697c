#!/usr/bin/env bash
# Time integration/Method = dopri (issue 25 item 3) on the thesis's spillway
# against its abutment (input/thesis/table-3.1.prm, Table 3.1):
#   - the 18 switching times (enters g1 = 0, deepest g2 = 0, leaves) at
#     Relative tolerance 1e-10 against a converged reference, the same
#     method at 1e-13: within 2e-5 s (the issue's requirement; measured
#     ~2e-10 s), and against the printed table at its 2e-4 s, 2e-4 m/s
#     (thesis_tables.py's comparison);
#   - the reference's first impact against an independent one, Newmark at
#     dt = 2e-6 s with event refinement to 0.45 s: within 1e-7 s (Newmark's
#     error is second order: 3.5e-5 s at 1e-4 s gives ~1.4e-8 s at 2e-6 s);
#   - the energy balance of the run: max relative error <= 1e-6;
# then bad input: a tolerance <= 0, dopri on a model with hysteretic storeys:
# exit 1, one message naming the file, line and parameter, no output directory.
set -eu
poundfe=$1 inputs=$2 shear_pair=$3
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$here/helpers.sh"

table="$inputs/table-3.1.prm"
dopri() { # $1: name, $2: relative tolerance, $3: absolute tolerance
  with "$table" "Method = dopri; Relative tolerance = $2; Absolute tolerance = $3" |
    sed 's/^\( *set Time step *=\).*/\1 1e-3/' > "$work/$1.prm"
  "$poundfe" run "$work/$1.prm" --output "$work/$1" > /dev/null
}
dopri run 1e-10 1e-12
dopri reference 1e-13 1e-15
sed -e 's/^\( *set Time step *=\).*/\1 2e-6/' -e 's/^\( *set End time *=\).*/\1 0.45/' \
    -e 's/^\( *set Output interval *=\).*/\1 0.01/' "$table" > "$work/newmark.prm"
"$poundfe" run "$work/newmark.prm" --output "$work/newmark" > /dev/null

python3 - "$here" "$work" <<'PY' || fail "dopri on Table 3.1"
import csv, json, sys
sys.path.insert(0, sys.argv[1])
import thesis_tables
work = sys.argv[2]
TIMES = ("start_time_s", "max_penetration_time_s", "end_time_s")
def times(name):
    return [[float(r[k]) for k in TIMES] for r in csv.DictReader(open(f"{work}/{name}/impacts.csv"))]
run, ref, newmark = times("run"), times("reference"), times("newmark")
assert len(run) == len(ref) == 6 and len(newmark) == 1, (len(run), len(ref), len(newmark))
worst = max(abs(a - b) for r, f in zip(run, ref) for a, b in zip(r, f))
independent = max(abs(a - b) for a, b in zip(ref[0], newmark[0]))
print(f"dopri 1e-10 against 1e-13: {worst:.3g} s; first impact against Newmark 2e-6 s: {independent:.3g} s")
assert worst <= 2e-5, worst
assert independent <= 1e-7, independent
c = thesis_tables.Comparison()
thesis_tables.compare_table_3_1(c, f"{work}/run")
assert not c.failures, c.failures
energy = json.load(open(f"{work}/run/summary.json"))["energy"]["max_relative_balance_error"]
print(f"energy balance error {energy:.3g}")
assert energy <= 1e-6, energy
PY

refused() { # $1: name, $2: input, $3: entries, $4: the parameter the message must name
  with "$2" "$3" > "$work/$1.prm"
  set +e
  "$poundfe" run "$work/$1.prm" --output "$work/$1" > /dev/null 2> "$work/$1.err"
  local status=$?
  set -e
  [ "$status" = 1 ] || fail "$1: exit $status, not 1"
  grep -q "$work/$1.prm:[0-9]*: parameter '$4'" "$work/$1.err" || fail "$1: $(cat "$work/$1.err")"
  [ ! -e "$work/$1" ] || fail "$1: wrote $work/$1"
}
refused zero-rtol "$table" "Method = dopri; Relative tolerance = 0" "Time integration/Relative tolerance"
refused negative-atol "$table" "Method = dopri; Absolute tolerance = -1e-9" "Time integration/Absolute tolerance"
refused hysteretic "$shear_pair" "Method = dopri" "Time integration/Method"
echo "dopri: ok"
