#!/usr/bin/env bash
# Gmsh meshes are checked before deal.II's GridIn::read_msh reads them
# (mesh/gmsh_check.h): the malformed files that crashed poundfe (a node
# block larger than announced: heap corruption, glibc abort; an element
# block of entity dimension 9: SIGSEGV; 2e9 nodes announced: bad_alloc),
# the mesh fuzzer's finding and other damage are refused with exit 1 and
# one line naming the mesh file, the line and what is wrong; the example
# frame's mesh in Gmsh 2.2 and in 4.1 (written by gmsh 4 from it) still
# reads, to the same frequencies.
#   mesh_check.sh POUNDFE INPUT_DIR MESH_DIR
set -u
poundfe=$1
inputs=$2
meshes=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
. "$meshes/../expect.sh"
sed 's|= ../meshes/setback.msh|= frame.msh|' "$inputs/setback-frame.prm" > frame.prm
grep -q "= frame.msh" frame.prm || { echo "FAIL frame.prm: no Mesh file changed"; exit 1; }

# mesh FILE STATUS TEXT: modal of the frame with FILE as its mesh
mesh() { cp "$1" frame.msh; expect "$2" "$3" modal frame.prm --output out; }
bad=$meshes/bad
mesh "$bad/node-blocks-overflow.msh" 1 "frame.msh:6: Gmsh mesh: the node blocks hold more nodes than the 2 announced"
mesh "$bad/entity-dimension.msh" 1 "frame.msh:14: Gmsh mesh: an element block's entity dimension: expected a whole number from 0 to 3, got '9'"
mesh "$bad/huge-count.msh" 1 "frame.msh:5: Gmsh mesh: 2000000000 nodes announced, but the rest of the file holds at most 8"
mesh "$bad/truncated.msh" 1 "frame.msh:19: Gmsh mesh: 130 elements announced, but the rest of the file holds at most 20"
mesh "$bad/point-missing-node.msh" 1 "frame.msh:12: Gmsh mesh: an element refers to node 99, which \$Nodes does not give"
mesh "$bad/self-line.msh" 1 "frame.msh:32: Gmsh mesh: a line element from node 10 to itself"
mesh "$bad/triangle.msh" 1 "frame.msh:32: Gmsh mesh: element type 2: a frame mesh holds line elements (type 1) and points (type 15) only"
mesh "$bad/fuzz-crash-14302a55.msh" 1 "frame.msh:1: Gmsh mesh: expected \$MeshFormat at the start"
# more damage, made here from the example
src=$meshes/../../../meshes/setback.msh
sed 's/^2.2 0 8$/3.0 0 8/' "$src" > v3.msh && mesh v3.msh 1 "frame.msh:2: Gmsh mesh: format version '3.0': only 2.2 and 4.1 are read"
sed 's/^2.2 0 8$/2.2 1 8/' "$src" > binary.msh && mesh binary.msh 1 "frame.msh:2: Gmsh mesh: a binary file (file type 1)"
sed 's/^5 6 3.5 0$/5 6 3.5x 0/' "$src" > coordinate.msh && mesh coordinate.msh 1 "frame.msh:10: Gmsh mesh: a node coordinate: expected a finite number, got '3.5x'"
sed 's/^5 6 3.5 0$/4 6 3.5 0/' "$src" > twice.msh && mesh twice.msh 1 "frame.msh:10: Gmsh mesh: node 4 is given twice"
sed 's/^12 1 2 2 12 8 9$/12 1 2 2 12 4 5/' "$src" > repeated.msh && mesh repeated.msh 1 "frame.msh:31: Gmsh mesh: the line element between nodes 4 and 5 is given twice"
sed '/^\$EndNodes$/d' "$src" > no-end.msh && mesh no-end.msh 1 "frame.msh:17: Gmsh mesh: expected \$EndNodes, got '\$Elements'"
head -n 18 "$src" > cut.msh && mesh cut.msh 1 "frame.msh:18: Gmsh mesh: the file ends where the number of elements should come"
printf '$NOD\n2\n1 0 0 0\n2 0 3 0\n$ENDNOD\n' > gmsh1.msh && mesh gmsh1.msh 1 "frame.msh:1: Gmsh mesh: a Gmsh 1 file (\$NOD)"

# the example in both versions: the same frequencies
mesh "$src" 0 "mode  frequency"
cp stdout modes-22.txt
mesh "$meshes/setback-41.msh" 0 "mode  frequency"
diff modes-22.txt stdout > /dev/null || fail "Gmsh 4.1 mesh: other frequencies than 2.2: $(head -5 stdout)"

echo "$n mesh cases, $failures failures"
[ "$failures" -eq 0 ]
