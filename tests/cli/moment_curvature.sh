#!/usr/bin/env bash
# `moment-curvature`:
#   - a steel I-shape of ElasticPP fibres: the last moment is fy Z (Z written
#     here; no fibre straddles the neutral axis, so the fibre sum is exact);
#   - the same section as OpenSees's patch commands (Type = fibres): the same curve;
#   - the RC column example: files, events in order, and the idealised yield
#     curvature phi' M_n / M' against Priestley, Calvi & Kowalsky's (2007)
#     2.10 eps_y / h of rectangular columns, within 10 %;
#   - bad input (expect.sh): exit 1, one line naming file, line and entry,
#     nothing written.
#   moment_curvature.sh POUNDFE EXAMPLE
set -u
poundfe=$1 example=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
. "$(dirname "$0")/expect.sh" 2> /dev/null || . "$OLDPWD/$(dirname "$0")/expect.sh"

ishape() { # $1: the section's Type and entries, $2: extra Sections entries
  cat <<PRM
subsection Sections
  set Number of sections = 1
  ${2:-}
  subsection Section 1
    set Name = W
$1
  end
end
subsection Moment curvature
  set Section = W
  set Target curvature = 2
  set Steps = 50
  set Moment drop = 0
end
subsection Output
  set Plots = false
end
PRM
}
ishape "    set Type = steel I
    set Depth = 0.3
    set Flange width = 0.15
    set Flange thickness = 0.0107
    set Web thickness = 0.0071
    set Steel law = ElasticPP
    set Yield stress = 355e6
    set Elastic modulus = 210e9
    set Ultimate strain = 0" > builder.prm
"$poundfe" moment-curvature builder.prm --output builder > /dev/null || fail "steel I: exit $?"
python3 - builder/moment_curvature.csv <<'PY' || fail "steel I: fy Z"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
d, bf, tf, tw, fy = 0.3, 0.15, 0.0107, 0.0071, 355e6
hw = d - 2 * tf
Z = bf * tf * (d - tf) + tw * hw * hw / 4
m = float(rows[-1]["moment_N_m"])
assert abs(m / (fy * Z) - 1) < 1e-12, (m, fy * Z)
print(f"ok   steel I: M = {m:.6f} N m, fy Z = {fy * Z:.6f} N m")
PY
# the same fibres by OpenSees's commands: flanges 4 x 8, web 16 x 1
python3 - > fibres.txt <<'PY'
d, bf, tf, tw = 0.3, 0.15, 0.0107, 0.0071
h, hw, b, t = d / 2, d / 2 - tf, bf / 2, tw / 2
print(f"patch rect steel 4 8 {hw!r} {-b!r} {h!r} {b!r}; patch rect steel 4 8 {-h!r} {-b!r} {-hw!r} {b!r};"
      f" patch rect steel 16 1 {-hw!r} {-t!r} {hw!r} {t!r}")
PY
ishape "    set Type = fibres
    set Fibres = $(cat fibres.txt)" \
  "set Materials = steel: ElasticPP E=210e9 epsyP=$(python3 -c 'print(repr(355e6/210e9))')" > fibres.prm
"$poundfe" moment-curvature fibres.prm --output fibres > /dev/null || fail "fibres: exit $?"
python3 - builder/moment_curvature.csv fibres/moment_curvature.csv <<'PY' || fail "builder and fibres differ"
import csv, sys
a, b = ([list(map(float, r)) for r in list(csv.reader(open(p)))[1:]] for p in sys.argv[1:])
assert len(a) == len(b)
worst = max(abs(x - y) / max(abs(x), 1e-30) for ra, rb in zip(a, b) for x, y in zip(ra[:2], rb[:2]) if x != 0)
assert worst < 1e-9, worst
print(f"ok   the builder and OpenSees's patches: largest relative difference {worst:.2g}")
PY

"$poundfe" moment-curvature "$example" --output rc > rc.txt || fail "example: exit $?"
python3 - rc <<'PY' || fail "example"
import csv, json, sys
s = json.load(open(sys.argv[1] + "/summary.json"))
rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(sys.argv[1] + "/moment_curvature.csv"))]
assert s["status"] == "completed", s["status"]
events = [e["what"] for e in s["events"]]
assert events[0] == "first yield of steel", events
assert s["first_yield"]["curvature_1_m"] < s["peak"]["curvature_1_m"] <= s["ultimate"]["curvature_1_m"]
assert s["curvature_ductility"] > 4, s["curvature_ductility"]
# Priestley, Calvi & Kowalsky's yield curvature: phi' at the first of the
# tension steel's yield and the concrete's -0.002, scaled by M_n / M' with M_n
# at the first of the concrete's -0.004 and the steel's 0.015 (interpolated)
def at(reached, key, value):
    a, b = next((a, b) for a, b in zip(rows, rows[1:]) if reached(b))
    t = (value - a[key]) / (b[key] - a[key])
    return {k: a[k] + t * (b[k] - a[k]) for k in a}
def first_of(limits):
    reached = lambda r: any(sign * r[key] >= sign * value for key, value, sign in limits)
    row = next(r for r in rows if reached(r))
    key, value, _ = next(l for l in limits if l[2] * row[l[0]] >= l[2] * l[1])
    return at(reached, key, value)
first = first_of([("concrete_strain_min", -0.002, -1), ("steel_strain_max", 450e6 / 200e9, 1)])
kn = first_of([("concrete_strain_min", -0.004, -1), ("steel_strain_max", 0.015, 1)])
phi_y = first["curvature_1_m"] * kn["moment_N_m"] / first["moment_N_m"]
priestley = 2.10 * 450e6 / 200e9 / 0.5
assert abs(phi_y / priestley - 1) < 0.10, (phi_y, priestley)
print(f"ok   RC column: yield {s['first_yield']['moment_N_m']/1e3:.1f} kN m, nominal "
      f"{kn['moment_N_m']/1e3:.1f} kN m, idealised yield curvature {phi_y:.5f} 1/m, "
      f"2.10 eps_y / h = {priestley:.5f} 1/m, ductility {s['curvature_ductility']:.2f}")
PY

# bad input: each refused with its file, line and entry, nothing written
bad() { # $1: the expected text, $2: sed expression on the example
  sed -e "$2" "$example" > bad.prm
  expect 1 "$1" moment-curvature bad.prm --output out
}
bad "bad.prm:15: parameter 'Sections/Section 1/Cover': must be less than half" 's/set Cover .*/set Cover = 0.25/'
bad "bad.prm:15: parameter 'Sections/Section 1/Cover': the stirrups lie outside" 's/set Cover .*/set Cover = 0.004/'
bad "parameter 'Sections/Section 1/Bar diameter': " 's/set Bar diameter .*/set Bar diameter = 0.2/'
bad "bad.prm:13: parameter 'Sections/Section 1/Depth': must be positive" 's/set Depth .*/set Depth = 0/'
bad "parameter 'Sections/Section 1/Width': must be positive" 's/set Width .*/set Width = -0.5/'
bad "parameter 'Sections/Section 1/Spalling strain': must exceed the peak strain" 's/set Spalling strain .*/set Spalling strain = 0.0015/'
bad "parameter 'Sections/Section 1/Crushing strain': must exceed the peak strain" 's/set Spalling strain .*/&\n    set Crushing strain = 0.001/'
bad "parameter 'Moment curvature/Section': no section named 'C60'" 's/set Section          = C50/set Section = C60/'
fibre() { # $1: the expected text, $2: the Fibres, $3: the Materials
  ishape "    set Type = fibres
    set Fibres = $2" "set Materials = $3" > bad.prm
  expect 1 "$1" moment-curvature bad.prm --output out
}
steel="steel: Steel02 fy=420e6 E0=200e9 b=0.01"
fibre "bad.prm:7: parameter 'Sections/Section 1/Fibres': the section has no fibres" "" "$steel"
fibre "parameter 'Sections/Section 1/Fibres': command 2 'fiber 0 0 -1e-4 steel': a fibre's area must be positive" \
  "fiber 0.1 0 1e-4 steel; fiber 0 0 -1e-4 steel" "$steel"
fibre "command 1 'patch rect concrete 2 2 0 0 1 1': no material 'concrete'" "patch rect concrete 2 2 0 0 1 1" "$steel"
fibre "bad.prm:3: parameter 'Sections/Materials': unknown material 'Steel9'" "fiber 0 0 1e-4 steel" "steel: Steel9 fy=1"
fibre "parameter 'Sections/Materials': epscu: Concrete01: the crushing strain must exceed epsc0" "fiber 0 0 1e-4 c" \
  "c: Concrete01 fpc=-30e6 epsc0=-0.002 fpcu=-6e6 epscu=-0.001"
fibre "must go counter-clockwise" "patch quad steel 1 1 0 0 0 1 1 1 1 0" "$steel"
report "moment-curvature"
