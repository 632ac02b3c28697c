#!/usr/bin/env bash
# `separation` from the command line (theory §7.1):
#  - the time-history minimum of one realization equals max_t (u_1 - u_2) of
#    `poundfe run`'s own floor_displacement.csv of the same file (realization
#    0), and the peaks max |u_i| likewise;
#  - the probability of pounding at gaps just below, at and just above that
#    value is 1, 0, 0 (one realization);
#  - one rank and two give the same realizations and tables;
#  - the response-spectrum route: u = Sd(T, zeta) of each one-storey building
#    (EC8 written out in Python), stale files of the other route removed, no
#    Spectrum/Target: bad input;
#  - one building: exit 1, one message, nothing written.
set -eu
poundfe=$1 mpirun=$2 input=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/helpers.sh"

# the time-history minimum and peaks of `separation` on $1 against `run`'s
# floor_displacement.csv; prints the minimum, u_left, u_right
against_run() {
  "$poundfe" run "$1" --output "$work/$2-run" > /dev/null
  "$poundfe" separation "$1" --output "$work/$2" > "$work/$2.log"
  grep -q "governing code rule" "$work/$2.log" || fail "separation: no governing rule on the console"
  python3 - "$work/$2-run/floor_displacement.csv" "$work/$2/separation.csv" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
head = rows[0]
i = next(k for k, h in enumerate(head) if h.startswith("S1_floor1"))
j = next(k for k, h in enumerate(head) if h.startswith("S2_floor1"))
u = [(float(r[i]), float(r[j])) for r in rows[1:]]
d = max(a - b for a, b in u)
u1 = max(abs(a) for a, b in u)
u2 = max(abs(b) for a, b in u)
sep = list(csv.DictReader(open(sys.argv[2])))
assert len(sep) == 1, "one common level expected"
s = sep[0]
for name, mine, theirs in (("time-history minimum", float(s["time_history_m"]), d),
                           ("u_left", float(s["u_left_m"]), u1),
                           ("u_right", float(s["u_right_m"]), u2)):
    if abs(mine - theirs) > 1e-12 * abs(theirs):
        sys.exit(f"FAIL separation: {name} {mine} differs from the run's {theirs}")
print(repr(d), repr(u1), repr(u2))
PY
}
read -r d u1 u2 < <(against_run "$input" sep) || fail "separation: against the run's floor displacements"
echo "ok   separation: time-history minimum $d m = max(u1 - u2) of the run's floor_displacement.csv"

# a deterministic load (no ground motion, a harmonic force on each building): one time history
sed -e 's/set Type = white-noise/set Type = none/' \
    -e 's/^subsection Output/subsection Nodal forces\n  set Harmonic = 1 1 0 ux 2000 9 0; 2 1 0 ux 1500 6 1\nend\n\nsubsection Time integration\n  set Time step = 0.005\n  set End time  = 6\nend\n\nsubsection Output/' \
    -e '/^subsection Time integration/,/^end/d' "$input" > "$work/harmonic.prm"
read -r dh _ < <(against_run "$work/harmonic.prm" harmonic) || fail "separation (harmonic force): against the run"
grep -q '"method": "time history without contact"' "$work/harmonic/summary.json" || fail "separation (harmonic force): not one time history"
[ -e "$work/harmonic/pounding_probability.csv" ] && fail "separation (harmonic force): a probability without random loading"
echo "ok   separation: one time history (harmonic force): minimum $dh m = max(u1 - u2) of the run"

below=$(python3 -c "print(repr($d * (1 - 1e-9)))") above=$(python3 -c "print(repr($d * (1 + 1e-9)))")
sed "s/^subsection Output/subsection Separation\n  set Gap values = $below, $d, $above\nend\n\nsubsection Output/" \
  "$input" > "$work/gaps.prm"
"$poundfe" separation "$work/gaps.prm" --output "$work/gaps" > /dev/null
python3 - "$work/gaps/pounding_probability.csv" <<'PY' || fail "separation: P(pounding) around the realization's value"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
p = [float(r["S1-S2_probability"]) for r in rows]
if p != [1.0, 0.0, 0.0]:
    sys.exit(f"FAIL separation: P(pounding) just below, at, just above = {p}, not [1, 0, 0]")
PY
echo "ok   separation: P(pounding) = 1 just below the realization's largest approach, 0 at and above"

sed 's/set Realizations = 1/set Realizations = 6/' "$input" > "$work/six.prm"
"$poundfe" separation "$work/six.prm" --output "$work/one" > /dev/null
"$mpirun" -np 2 "$poundfe" separation "$work/six.prm" --output "$work/two" > /dev/null
diff <(rows "$work/one/realizations.csv") <(rows "$work/two/realizations.csv") > /dev/null ||
  fail "separation: the realizations differ between 1 and 2 ranks"
for f in separation.csv pounding_probability.csv; do
  cmp -s "$work/one/$f" "$work/two/$f" || fail "separation: $f differs between 1 and 2 ranks"
done
same_summary "$work/one/summary.json" "$work/two/summary.json" "separation: summary differs between 1 and 2 ranks"
echo "ok   separation: -np 2 gives the tables of one rank"

# the response-spectrum route (theory §7.1b): each one-storey building's peak is
# Sd = Se(T, zeta) (T / 2 pi)^2 of EN 1998-1 (type 1, ground B: S 1.2, TC 0.5 s,
# TD 2 s), written out here, at its own T and zeta (0.5 s, 0.05; 0.8 s, 0.03);
# the run removes the earlier Monte Carlo's probability files of $work/one
spectrum_sections='subsection Separation\n  set Peak displacements = response spectrum\nend\n\nsubsection Spectrum\n  set Target = ec8-type-1\n  set Ground type = B\n  set Design ground acceleration = 0.3\nend\n\nsubsection Output'
sed "s/^subsection Output/$spectrum_sections/" "$input" > "$work/spectrum.prm"
"$poundfe" separation "$work/spectrum.prm" --output "$work/one" > "$work/spectrum.log"
grep -q "^poundfe separation: response spectrum" "$work/spectrum.log" || fail "separation (spectrum): the route is not named on the console"
grep -q '"peak_displacements": "response spectrum"' "$work/one/summary.json" || fail "separation (spectrum): the route is not named in summary.json"
for stale in pounding_probability.csv pounding_probability.png; do
  [ -e "$work/one/$stale" ] && fail "separation (spectrum): the earlier run's $stale is left"
done
python3 - "$work/one/separation.csv" <<'PY' || fail "separation (spectrum): u against Sd(T, zeta) by hand"
import csv, math, sys
def sd(T, zeta):
    ag, S, TC, TD = 0.3 * 9.80665, 1.2, 0.5, 2.0
    eta = max(0.55, math.sqrt(10 / (5 + 100 * zeta)))
    se = 2.5 * ag * S * eta * (1 if T <= TC else TC / T)
    return se * (T / (2 * math.pi)) ** 2
row = list(csv.DictReader(open(sys.argv[1])))[0]
u1, u2 = sd(0.5, 0.05), sd(0.8, 0.03)
for name, mine, theirs in (("u_left", float(row["u_left_m"]), u1), ("u_right", float(row["u_right_m"]), u2),
                           ("u_left_srss", float(row["u_left_srss_m"]), u1),
                           ("EC8", float(row["ec8_m"]), 0.7 * math.hypot(u1, u2))):
    if abs(mine - theirs) > 1e-12 * theirs:
        sys.exit(f"FAIL separation (spectrum): {name} {mine} differs from {theirs}")
PY
"$poundfe" separation "$work/spectrum.prm" --output "$work/switch" > /dev/null
"$poundfe" separation "$input" --output "$work/switch" > /dev/null
[ -e "$work/switch/spectrum_modes.csv" ] && fail "separation (time history): the earlier spectrum_modes.csv is left"
echo "ok   separation: response spectrum: u = Sd(T, zeta) of each one-storey building (EC8 by hand, 1e-12)"

sed 's/set Target = ec8-type-1/set Target = none/' "$work/spectrum.prm" > "$work/no-target.prm"
status=0
"$poundfe" separation "$work/no-target.prm" --output "$work/bad" > "$work/bad.log" 2>&1 || status=$?
[ "$status" -eq 1 ] || fail "separation (spectrum) without a target: exit $status, not 1"
[ "$(wc -l < "$work/bad.log")" -eq 1 ] || fail "separation (spectrum) without a target: not one message"
grep -q "Peak displacements" "$work/bad.log" || fail "separation (spectrum) without a target: message does not name the parameter"
[ -e "$work/bad" ] && fail "separation (spectrum) without a target: output written"
echo "ok   separation: response spectrum without Spectrum/Target is bad input (exit 1, nothing written)"

sed -e 's/set Number of buildings = 2/set Number of buildings = 1/' -e '/^subsection Building 2/,/^end/d' \
  "$input" > "$work/one-building.prm"
status=0
"$poundfe" separation "$work/one-building.prm" --output "$work/bad" > "$work/bad.log" 2>&1 || status=$?
[ "$status" -eq 1 ] || fail "separation of one building: exit $status, not 1"
[ "$(wc -l < "$work/bad.log")" -eq 1 ] || fail "separation of one building: not one message"
grep -q "Number of buildings" "$work/bad.log" || fail "separation of one building: message does not name the parameter"
[ -e "$work/bad" ] && fail "separation of one building: output written"
echo "ok   separation: one building is bad input (exit 1, nothing written)"
