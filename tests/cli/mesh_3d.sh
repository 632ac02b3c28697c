#!/usr/bin/env bash
# 3D frames drawn in Gmsh through the command line (doc/verification.md,
# "3D frames drawn in Gmsh"): tests/cli/mesh-3d-pair.prm, the L-shaped
# frame of meshes/frame3d-l.msh next to a generated 3D frame
#  1. `run` completes; the slabs pound with their plan point in impacts.csv;
#     the mesh frame's column-base hinges report; the VTU series is written;
#     the energy balance closes to 1e-6;
#  2. the same mesh written by Gmsh 4.1 gives the same modes as the 2.2 file;
#  3. hostile input: a 2D mesh with Dimension = 3, a member of zero length
#     (its two nodes at one point),
#     a physical id not in Group ids, an orientation along a member, a mesh
#     without horizontal members: exit 1, one line naming the file, line and
#     entry, nothing written.
#   mesh_3d.sh POUNDFE TESTS_CLI_DIR MESHES_DIR
set -u
poundfe=$1
cli=$2
meshes=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
. "$cli/expect.sh"
sed "s|= ../../meshes/frame3d-l.msh|= frame.msh|" "$cli/mesh-3d-pair.prm" > pair.prm
grep -q "= frame.msh" pair.prm || { echo "FAIL pair.prm: no Mesh file changed"; exit 1; }
cp "$meshes/frame3d-l.msh" frame.msh

# 1. the run
"$poundfe" run pair.prm --output run > /dev/null || fail "run: exit $?"
grep -q '"status": "completed"' run/summary.json || fail "run not completed"
head -1 run/impacts.csv | grep -q "plan_x_m,plan_y_m" || fail "impacts.csv without plan point"
impacts=$(($(wc -l < run/impacts.csv) - 1))
[ "$impacts" -gt 0 ] || fail "the L and its neighbour pound nowhere"
grep -q "L2_C1.1_bottom_y" run/hinges.csv || fail "no hinge of the mesh frame's columns in hinges.csv"
[ -s run/solution.pvd ] || fail "no VTU series"
error=$(sed -n 's/.*"max_relative_balance_error": \([^,}]*\).*/\1/p' run/summary.json)
awk -v e="$error" 'BEGIN { exit !(e != "" && e < 1e-6) }' || fail "energy balance error $error"
echo "ok   the L-shaped mesh frame pounds its neighbour ($impacts impacts), energy balance error $error"

# 2. Gmsh 4.1: the same modes
"$poundfe" modal pair.prm --output modal22 > modal22.out || fail "modal 2.2: exit $?"
cp "$cli/mesh/frame3d-l-41.msh" frame.msh
"$poundfe" modal pair.prm --output modal41 > modal41.out || fail "modal 4.1: exit $?"
grep -E "^ +[0-9]+ +[0-9.]+ " modal22.out > modes22
grep -E "^ +[0-9]+ +[0-9.]+ " modal41.out > modes41
[ -s modes22 ] && cmp -s modes22 modes41 || fail "Gmsh 4.1 and 2.2 give other modes"
echo "ok   Gmsh 4.1 and 2.2 meshes: the same $(wc -l < modes22) modes"
cp "$meshes/frame3d-l.msh" frame.msh

# 3. hostile input
# msh FILE NODES LINES: a Gmsh 2.2 mesh ('tag x y z' per node, 'a b id' per line)
msh() {
  {
    printf '$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%s\n' "$(printf '%s\n' "$2" | wc -l)"
    printf '%s\n' "$2"
    printf '$EndNodes\n$Elements\n%s\n' "$(printf '%s\n' "$3" | wc -l)"
    printf '%s\n' "$3" | awk '{ print NR, 1, 2, $3, NR, $1, $2 }'
    printf '$EndElements\n'
  } > "$1"
}
bad() { sed "$1" pair.prm > bad.prm; expect 1 "$2" run bad.prm --output out; }
cp "$meshes/setback.msh" flat.msh
bad "s|= frame.msh|= flat.msh|" \
  "bad.prm:15: parameter 'Building 1/Mesh file': flat.msh lies in the horizontal plane z = 0"
msh zero.msh "1 0 0 0
2 0 0 3
3 6 0 3
4 6 0 3" "1 2 1
2 3 2
3 4 1"
bad "s|= frame.msh|= zero.msh|" "bad.prm:15: parameter 'Building 1/Mesh file': zero.msh:9: Gmsh mesh: nodes 3 and 4 are at one point (6, 0, 3)"
bad "s|set Group ids             = 1, 2|set Group ids = 1, 3|" \
  "bad.prm:16: parameter 'Building 1/Group ids': the mesh frame.msh uses physical id 2 (line element 17), which is not listed"
bad "s|set Floor masses          = 8e4, 6e4|set Floor masses = 8e4, 6e4\n  set Group orientation = 0 0 1; 0 0 1|" \
  "bad.prm:25: parameter 'Building 1/Group orientation': group 1: the vector (0, 0, 1) is along line element 1"
msh columns.msh "1 0 0 0
2 0 0 3
3 6 0 0
4 6 0 3" "1 2 1
3 4 1"
bad "s|= frame.msh|= columns.msh|" "bad.prm:15: parameter 'Building 1/Mesh file': columns.msh has no horizontal member"
echo "$((n - failures)) of $n hostile inputs refused as expected"
[ "$failures" -eq 0 ] || exit 1
echo "ok   mesh_3d"
