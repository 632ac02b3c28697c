// The check of a Gmsh .msh text before deal.II's GridIn::read_msh sees it.
// read_msh trusts its input: in a release build it writes past the end of
// its vertex array when the node blocks hold more nodes than announced,
// indexes an array of four maps with an entity dimension from the file, and
// loops on a failed stream for as many items as a count says; the mesh
// fuzzer (tests/fuzz, target mesh) found heap corruption inside it. So the
// text is read here first, token by token as read_msh reads it, against the
// MSH format of the Gmsh reference manual (C. Geuzaine, J.-F. Remacle,
// "Gmsh Reference Manual", section "MSH file format", versions 2.2 and
// 4.1), and refused unless every section and count is complete and every
// index lies in range:
//  - $MeshFormat, version 2.2 (2, 2.1) or 4.1, ASCII (file type 0), data
//    size 8; $EndMeshFormat;
//  - optionally $PhysicalNames ... $EndPhysicalNames, then (4.1)
//    $Entities with its four counts and each entity complete, at most one
//    physical tag each;
//  - $Nodes: the count, then exactly that many nodes (4.1: the blocks'
//    counts add up to it), tags 1..2^31-1 without repeats, coordinates
//    finite numbers; 4.1 parametric nodes are refused; $EndNodes;
//  - $Elements: the count, then exactly that many elements (4.1: blocks of
//    entity dimension 0..3 adding up to it), only line elements (type 1,
//    two distinct nodes) and points (type 15), every node tag one of
//    $Nodes, physical tags (the material ids members are assigned by)
//    0..2^31-1; $EndElements. What follows is not read (by read_msh either).
// A count may not promise more items than the rest of the file can hold,
// so no count makes anyone allocate or loop beyond the file's size.
#ifndef poundfe_mesh_gmsh_check_h
#define poundfe_mesh_gmsh_check_h

#include <string>

namespace poundfe
{
  /// Throws InputError naming `file`, the line and what is wrong unless
  /// `text` (as read_input_text gives it) is a Gmsh 2.2 or 4.1 ASCII mesh
  /// of line elements that GridIn<1,2> and GridIn<1,3>::read_msh read safely.
  void check_gmsh_text(const std::string &file, const std::string &text);
} // namespace poundfe

#endif
