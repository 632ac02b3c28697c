#!/usr/bin/env bash
# Frames of fibre beam-columns (Building <i>/Member model = fibre):
#   - an elastic-section fibre frame (two Elastic fibres: EA and EI exact)
#     equals the elastic frame of the same EA, EI (elastic-hinges without
#     hinges, i.e. rigid ones): the modal periods and the floor histories of a
#     run to round-off (1e-9 relative);
#   - gravity gives each column of a two-bay frame of equal columns its
#     tributary axial force, the floor loads above it over the three columns
#     (member end forces at t = 0, 1e-6 relative: the gravity tolerance);
#   - the example input/fibre-frame-pounding.prm: run (energy balance <= 1e-8
#     of the energy scale while the frames pound), modal after gravity,
#     pushover, and a Monte Carlo whose random f'c of the column section
#     changes the peak drift from one realization to the next, and whose
#     realization 1 is the run of Realization = 1 at its f'c (gravity, then
#     the damping fitted at modes of that gravity tangent; 1e-12 relative);
#   - bad input (expect.sh): an unknown section name, a wrong count of
#     per-storey names, a fibre building without Sections, hinges in a fibre
#     building, a random Column E of a fibre building, a random f'c, fy or
#     steel E whose distribution can sample beyond the section's bounds, a
#     swept steel E beyond them: exit 1, one line naming file, line and
#     entry, nothing written.
#   fibre_frames.sh POUNDFE EXAMPLE
set -u
poundfe=$1 example=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
. "$(dirname "$0")/expect.sh" 2> /dev/null || . "$OLDPWD/$(dirname "$0")/expect.sh"
same_csv_source="$(dirname "$0")/helpers.sh"
[ -f "$same_csv_source" ] || same_csv_source="$OLDPWD/$same_csv_source"
same_csv() { ( . "$same_csv_source"; same_csv "$@" ); }

# A two-storey one-bay frame; $1: the members' entries, $2: more input.
frame() {
  cat <<PRM
subsection Building 1
  set Name              = F
  set Type              = frame
  set Number of storeys = 2
  set Number of bays    = ${3:-1}
  set Storey heights    = 3.0
  set Bay widths        = 5.0
  set Floor masses      = 20000
  set Column mass per length = 400
$1
  subsection Damping
    set Type          = modes
    set Damping ratio = 0.05
    set Modes         = 1, 2
  end
end
subsection Ground motion
  set Type = kanai-tajimi
  subsection Stochastic
    set Target PGA = 0.3
    set Duration   = 3
    set Seed       = 5
  end
end
subsection Time integration
  set Time step = 0.005
end
subsection Output
  set Plots = false
  set Number of modes = 4
${output_extra:-}
end
${2:-}
PRM
}
elastic_section() {
  cat <<'PRM'
subsection Sections
  set Number of sections = 1
  set Materials = el: Elastic E=3e10
  subsection Section 1
    set Name   = two-fibres
    set Type   = fibres
    set Fibres = fiber 0.1 0 0.08 el; fiber -0.1 0 0.08 el
  end
end
PRM
}

# 1. elastic-section fibre frame = elastic frame (EA = 3e10 0.16, EI = 3e10 0.16 0.1^2)
frame "  set Column E = 3e10
  set Column A = 0.16
  set Column I = 1.6e-3
  set Beam E = 3e10
  set Beam A = 0.16
  set Beam I = 1.6e-3" > elastic.prm
frame "  set Member model = fibre
  set Column sections = two-fibres
  set Beam sections = two-fibres" "$(elastic_section)" > fibre.prm
for f in elastic fibre; do
  "$poundfe" modal $f.prm --output modal-$f > /dev/null || fail "modal $f: exit $?"
  "$poundfe" run $f.prm --output run-$f > /dev/null || fail "run $f: exit $?"
done
python3 - modal-elastic/summary.json modal-fibre/summary.json <<'PY' || fail "elastic fibre frame: periods differ"
import json, sys
a, b = (json.load(open(p))["modes"]["periods_s"] for p in sys.argv[1:3])
worst = max(abs(x - y) / x for x, y in zip(a, b))
print(f"periods {a}: largest relative difference {worst:.3g}")
sys.exit(0 if len(a) == len(b) == 4 and worst <= 1e-9 else 1)
PY
for f in floor_displacement drift; do
  same_csv run-elastic/$f.csv run-fibre/$f.csv 1e-9 || fail "elastic fibre frame: $f.csv differs"
done

# 2. gravity: each of the three equal columns carries a third of the floors' weight above it
output_extra="  subsection Recorders
    set Record = member end forces of F_C1.1, F_C1.2, F_C1.3, F_C2.1, F_C2.2, F_C2.3
  end" frame "  set Member model = fibre
  set Column sections = two-fibres
  set Beam sections = two-fibres
  set Floor loads = 3e4" "$(elastic_section)
subsection Model
  subsection Gravity analysis
    set Type = static
  end
end" 2 | sed '/set Column mass per length = 400/d' > gravity.prm
"$poundfe" run gravity.prm --output gravity > /dev/null || fail "gravity run: exit $?"
python3 - gravity/member_forces.csv <<'PY' || fail "gravity: columns not tributary"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
first = rows[0]
weight = 20000 * 9.81 + 3e4  # per floor
worst = 0
for storey, floors_above in ((1, 2), (2, 1)):
    for line in (1, 2, 3):
        n = float(first[f"F_C{storey}.{line}_N2_N"])
        expected = floors_above * weight / 3
        worst = max(worst, abs(abs(n) - expected) / expected)
print(f"largest relative difference from the tributary load {worst:.3g}")
sys.exit(0 if worst <= 1e-6 else 1)
PY

# 3. the example: run, energy balance, modal, pushover, Monte Carlo with random f'c
"$poundfe" run "$example" --output run > /dev/null || fail "example run: exit $?"
python3 - run/summary.json <<'PY' || fail "example: energy balance or pounding"
import json, sys
s = json.load(open(sys.argv[1]))
e = s["energy"]
error = e["max_relative_balance_error"]
impacts = sum(g.get("impacts", 0) for g in s.get("gaps", []))
print(f"energy balance {error:.3g}, impacts {impacts}")
sys.exit(0 if error <= 1e-8 and impacts > 0 else 1)
PY
"$poundfe" modal "$example" --output modal > /dev/null || fail "example modal: exit $?"
"$poundfe" pushover "$example" --output pushover > /dev/null || fail "example pushover: exit $?"
sed '/^subsection Monte Carlo/,/^end/d' "$example" > mc.prm
cat >> mc.prm <<'PRM'
subsection Monte Carlo
  set Realizations = 3
end
subsection Random parameters
  set Variables = fc: Sections/Section 1/Concrete strength ~ uniform lower 15e6 upper 45e6
end
PRM
"$poundfe" montecarlo mc.prm --output mc > /dev/null || fail "montecarlo: exit $?"
python3 - mc/realizations.csv <<'PY' || fail "montecarlo: f'c does not change the peak drift"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
drifts = [float(r["max_drift_ratio"]) for r in rows]
fc = [float(r["fc"]) for r in rows]
print("f'c", fc, "peak drifts", drifts)
sys.exit(0 if len(set(drifts)) == len(drifts) and len(set(fc)) == len(fc) else 1)
PY
# realization 1 is the run of Realization = 1 at its f'c: gravity, then the
# Rayleigh damping fitted at modes of the gravity tangent of that f'c, in
# both (the same code path: 1e-12 relative, round-off)
fc1=$(python3 -c "import csv; print([r for r in csv.DictReader(open('mc/realizations.csv')) if r['realization'] == '1'][0]['fc'])")
"$poundfe" run mc.prm --set "Ground motion/Stochastic/Realization=1" \
  --set "Sections/Section 1/Concrete strength=$fc1" --output run1 > /dev/null || fail "run of realization 1: exit $?"
python3 - mc/realizations.csv run1/summary.json <<'PY' || fail "montecarlo realization 1 is not the run of it (gravity, Damping/Type = modes)"
import csv, json, sys
row = [r for r in csv.DictReader(open(sys.argv[1])) if r["realization"] == "1"][0]
s = json.load(open(sys.argv[2]))
bad = 0
for b in s["buildings"]:
    for i, st in enumerate(b["storeys"]):
        mc, run = float(row[f"{b['name']}_storey{i + 1}_peak_drift_ratio"]), st["peak_drift_ratio"]
        print(f"{b['name']} storey {i + 1}: montecarlo {mc:.17g}, run {run:.17g}")
        bad += abs(mc - run) > 1e-12 * max(abs(mc), abs(run))
sys.exit(bad)
PY

# 4. bad input
fibre_entries="  set Member model = fibre
  set Column sections = two-fibres
  set Beam sections = two-fibres"
frame "${fibre_entries/two-fibres/colA}" "$(elastic_section)" > unknown.prm
expect 1 "Column sections': no section named 'colA'" run unknown.prm --output out
frame "${fibre_entries/= two-fibres/= two-fibres, two-fibres, two-fibres}" "$(elastic_section)" > count.prm
expect 1 "Column sections': has 3 names" run count.prm --output out
frame "$fibre_entries" > none.prm
expect 1 "(Sections: none)" run none.prm --output out
frame "$fibre_entries
  subsection Hinges
    set Locations = column bases
    set Yield moment = 1e5
  end" "$(elastic_section)" > hinges.prm
expect 1 "Hinges/Locations" run hinges.prm --output out
frame "$fibre_entries
  set Column E = 3e10" "$(elastic_section)" > unused.prm
expect 1 "Column E': a fibre building" run unused.prm --output out
sed '/^subsection Monte Carlo/,/^end/d' "$example" > random-e.prm
printf 'subsection Random parameters\n  set Variables = e: Building 1/Column E ~ uniform lower 2e10 upper 3e10\nend\n' >> random-e.prm
expect 1 "is made of fibre members" montecarlo random-e.prm --output out
# a random or swept f'c, fy or steel E is held to the bounds of a typed one
# (f'c, fy <= 5e10 Pa, E <= 1e13 Pa: sections/material_bounds.h), refused at
# input: a distribution that can sample beyond them (a uniform beyond; a
# lognormal whose mean lies within ten standard deviations of them), a sweep
# value beyond
random_section() { # $1: the Variables entry
  sed '/^subsection Monte Carlo/,/^end/d' "$example"
  printf 'subsection Monte Carlo\n  set Realizations = 2\nend\n'
  printf 'subsection Random parameters\n  set Variables = %s\nend\n' "$1"
}
random_section "fc: Sections/Section 1/Concrete strength ~ uniform lower 15e6 upper 1e12" > random-fc.prm
expect 1 "can sample values > 5e+10, which 'Sections/Section 1/Concrete strength' cannot" \
  montecarlo random-fc.prm --output out
random_section "fy: Sections/Section 1/Yield stress ~ lognormal mean 1e10 cov 0.5" > random-fy.prm
expect 1 "can sample values > 5e+10, which 'Sections/Section 1/Yield stress' cannot" \
  montecarlo random-fy.prm --output out
# a normal f'c far below the bound is refused for the side it can cross, 0,
# and a lognormal or Weibull suggested, as for an entry with no upper bound
random_section "fc: Sections/Section 1/Concrete strength ~ normal mean 30e6 sd 4e6" > random-fc-normal.prm
expect 1 "can sample values <= 0, which 'Sections/Section 1/Concrete strength' cannot take (use a lognormal or Weibull whose mean" \
  montecarlo random-fc-normal.prm --output out
# a lognormal of a realistic mean and spread keeps ten standard deviations
# below the bound (the rule of 1e150 for every entry): it runs
random_section "fc: Sections/Section 1/Concrete strength ~ lognormal mean 30e6 cov 0.15" > random-fc-lognormal.prm
expect 0 "" montecarlo random-fc-lognormal.prm --set "Time integration/End time=0.05" --output lognormal
random_section "e: Sections/Section 1/Elastic modulus ~ uniform lower 2e11 upper 2e13" > random-steel-e.prm
expect 1 "> 1e+13, which 'Sections/Section 1/Elastic modulus' cannot" \
  montecarlo random-steel-e.prm --output out
{ sed '/^subsection Monte Carlo/,/^end/d' "$example"
  printf 'subsection Sweep\n  set Parameter = Sections/Section 1/Elastic modulus\n'
  printf '  set Values = 2e11, 1e14\nend\n'; } > sweep-steel-e.prm
expect 1 "at Sweep value Sections/Section 1/Elastic modulus = 1e+14: must be at most 1e+13 Pa" \
  sweep sweep-steel-e.prm --output out
[ "$failures" -eq 0 ] || { echo "$failures checks failed"; exit 1; }
echo "fibre frames: all checks passed"
