#!/usr/bin/env bash
# Fibre members in 3D frame buildings (Model/Dimension = 3, Member model =
# fibre):
#   - the example input/fibre-frame-3d.prm (two RC frames with bars on all
#     four faces, gravity first, a horizontal pair at 30 degrees, the slabs
#     pound), shortened to 2 s: run completes with the energy balance within
#     1e-8 of its scale and impacts; its gravity state compresses every
#     column (the section states recorder's N at t = 0 < 0) and bends the
#     columns about both local axes under the pair (Mz and My columns);
#   - modal after gravity completes with six modes, also with Concrete01
#     (no tension) beams, its reactions the floor weights;
#   - run after gravity of a frame with Concrete02 columns and Concrete01
#     beams (fibre-3d-concrete02-columns.prm), modal of a pair with
#     Concrete01 in both (fibre-3d-concrete01-pair.prm): both complete,
#     their reactions the floor weights;
#   - bad input (expect.sh): a fibre building drawn in Gmsh (Type = mesh)
#     with a generated frame's Column sections (a mesh's are Group sections),
#     a 3D rigidity given to a fibre building, a section without its GJ, a
#     section states label no member has (the example in 3D form):
#     exit 1, one line naming the entry, nothing written.
#   fibre_frames_3d.sh POUNDFE EXAMPLE MESH_INPUT
set -u
poundfe=$1 example=$2 mesh_input=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
. "$(dirname "$0")/expect.sh" 2> /dev/null || . "$OLDPWD/$(dirname "$0")/expect.sh"

# 1. the example, 2 s of its pair
sed -e 's/set Duration   = 6/set Duration   = 2/' \
    -e 's/set Number of modes = 6/set Number of modes = 6\
  subsection Recorders\
    set Record = section states of A_C1.1.1, A_C1.3.2\
  end/' "$example" > short.prm
"$poundfe" run short.prm --output run > /dev/null || fail "example run: exit $?"
python3 - run/summary.json run/sections.csv <<'PY' || fail "example: energy balance, impacts or sections"
import csv, json, sys
s = json.load(open(sys.argv[1]))
error = s["energy"]["max_relative_balance_error"]
impacts = sum(g.get("impacts", 0) for g in s.get("gaps", []))
rows = list(csv.DictReader(open(sys.argv[2])))
first = rows[0]
n0 = [float(v) for k, v in first.items() if k.endswith("_N_N")]
mz = max(abs(float(r[k])) for r in rows for k in r if k.endswith("_Mz_N_m"))
my = max(abs(float(r[k])) for r in rows for k in r if k.endswith("_My_N_m"))
print(f"energy balance {error:.3g}, impacts {impacts}, N at t = 0 {min(n0):.4g}..{max(n0):.4g} N, "
      f"peak |Mz| {mz:.4g}, |My| {my:.4g} N m")
sys.exit(0 if error <= 1e-8 and impacts > 0 and n0 and max(n0) < 0 and mz > 0 and my > 0 else 1)
PY
"$poundfe" modal "$example" --output modal > /dev/null || fail "example modal: exit $?"
python3 - modal/summary.json <<'PY' || fail "modal: not six modes"
import json, sys
periods = json.load(open(sys.argv[1]))["modes"]["periods_s"]
print("periods", periods)
sys.exit(0 if len(periods) == 6 and all(p > 0 for p in periods) else 1)
PY
# its gravity state: each frame's vertical reactions (the applied loads on
# its joints' uz) sum to its floor masses x g (Model/Gravity = 9.81; no
# member mass) to 1e-9; the peak is a column's shortening, uz at (x, y, z)
python3 - modal/summary.json <<'PY' || fail "modal: gravity reactions or peak label"
import json, re, sys
g = json.load(open(sys.argv[1]))["gravity"]
weights = [3 * 40000 * 9.81, 2 * 20000 * 9.81]  # A: 3 floors of 40 t, B: 2 of 20 t
errors = [abs(r - w) / w for r, w in zip(g["base_vertical_reactions_N"], weights)]
print("reactions", g["base_vertical_reactions_N"], "relative errors", errors, g["peak_displacement_at"])
ok = len(errors) == 2 and max(errors) <= 1e-9
ok = ok and re.search(r"at \([^,]+, [^,]+, [^,]+\) uz$", g["peak_displacement_at"]) is not None
sys.exit(0 if ok else 1)
PY

# the same frames with Concrete01 (no tension) beams: the beams' force-based
# elements start from zero deformation, where a fibre cracks and closes at
# once; gravity then needs the elements' fallback to the sections' initial
# flexibility (exit 2 without it, "no compatible state"). Its reactions are
# the floor weights, 1e-9, as above
sed '/set Name                = beam30x50/a\    set Concrete law        = Concrete01' "$example" > c01.prm
grep -q "Concrete law        = Concrete01" c01.prm || fail "c01.prm: no Concrete01 beams"
"$poundfe" modal c01.prm --output c01 > /dev/null || fail "Concrete01 beams: modal exit $?"
python3 - c01/summary.json <<'PY' || fail "Concrete01 beams: gravity reactions"
import json, sys
g = json.load(open(sys.argv[1]))["gravity"]
weights = [3 * 40000 * 9.81, 2 * 20000 * 9.81]
errors = [abs(r - w) / w for r, w in zip(g["base_vertical_reactions_N"], weights)]
print("Concrete01 beams: reactions", g["base_vertical_reactions_N"], "relative errors", errors)
sys.exit(0 if len(errors) == 2 and max(errors) <= 1e-9 else 1)
PY

# building A alone with Concrete02 columns and Concrete01 beams: `run`
# restores gravity's committed state in the time history's own elements
# (the gravity path replayed), which must reach what gravity committed;
# reactions = floor weights, 1e-9. And the pair with Concrete01 in both
# frames, whose virgin beams sit at deformations ~1e-20: gravity converges
# (exit 2, "no compatible state", without the element's absolute floor)
tests=$(dirname "$mesh_input")
"$poundfe" run "$tests/fibre-3d-concrete02-columns.prm" --output mix > /dev/null ||
  fail "Concrete02 columns: run exit $?"
"$poundfe" modal "$tests/fibre-3d-concrete01-pair.prm" --output pair > /dev/null ||
  fail "Concrete01 pair: modal exit $?"
python3 - mix/summary.json pair/summary.json <<'PY' || fail "Concrete02 columns / Concrete01 pair: gravity reactions"
import json, sys
for name, weights in zip(sys.argv[1:], ([60000 * 9.81], [60000 * 9.81, 18000 * 9.81])):
    g = json.load(open(name))["gravity"]["base_vertical_reactions_N"]
    errors = [abs(r - w) / w for r, w in zip(g, weights)]
    print(name, "reactions", g, "relative errors", errors)
    if len(errors) != len(weights) or max(errors) > 1e-9:
        sys.exit(1)
PY

# 2. bad input
awk '/^subsection Building 1$/ { print; print "  set Member model = fibre"; print "  set Column sections = column40"; print "  set Beam sections = column40"; next } { print }' \
  "$mesh_input" > mesh.prm
sed -n '/^subsection Sections/,/^end/p' "$example" >> mesh.prm
sed -i "s#set Mesh file             = ../../meshes/#set Mesh file = $(dirname "$mesh_input")/../../meshes/#" mesh.prm
expect 1 "Building 1/Column sections': has no effect on a 3D mesh building" run mesh.prm --output out
awk '/set Member model         = fibre/ && !done { print; print "  set Column Iz = 1e-3"; done = 1; next } { print }' \
  "$example" > iz.prm
expect 1 "Column Iz': a fibre building (Member model = fibre) takes its rigidities" run iz.prm --output out
sed '0,/set Torsional rigidity  = 2.7e7/{/set Torsional rigidity  = 2.7e7/d}' "$example" > gj.prm
expect 1 "Sections/Section 1/Torsional rigidity" run gj.prm --output out
sed 's/set Record = section states every 0;.*/set Record = section states of A_C9.9/' \
  "$tests/fibre-3d-concrete02-columns.prm" > label.prm
expect 1 "labels are like A_C1.1.1 or A_BX1.1.1" run label.prm --output out
[ "$failures" -eq 0 ] || { echo "$failures checks failed"; exit 1; }
echo "fibre frames 3d: all checks passed"
