// Frames drawn in Gmsh: line cells embedded in 2D, read with deal.II's
// GridIn<1,2> (Gmsh 2.2 and 4.1). The result is plain data so that the model
// builder does not see deal.II.
#ifndef poundfe_mesh_line_mesh_h
#define poundfe_mesh_line_mesh_h

#include <poundfe/base/point.h>

#include <array>
#include <string>
#include <vector>

namespace poundfe
{
  struct LineMesh
  {
    std::vector<Point2>                      vertices;
    std::vector<std::array<unsigned int, 2>> cells;
    std::vector<unsigned int>                material_ids; // Gmsh physical ids
  };

  /// Read a Gmsh .msh file of line elements. Throws InputError.
  LineMesh read_line_mesh(const std::string &file);
} // namespace poundfe

#endif
