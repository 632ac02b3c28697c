// Frames drawn in Gmsh: line cells embedded in 2D (x, y up) or in 3D (x, y,
// z up), read with deal.II's GridIn<1,2> / GridIn<1,3> (Gmsh 2.2 and 4.1)
// after mesh/gmsh_check.h has vetted the text. The result is plain data so
// that the model builder does not see deal.II.
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

  /// The same, embedded in 3D: vertices (x, y, z).
  struct LineMesh3D
  {
    std::vector<std::array<double, 3>>       vertices;
    std::vector<std::array<unsigned int, 2>> cells;
    std::vector<unsigned int>                material_ids; // Gmsh physical ids
  };

  /// Read a Gmsh .msh file of line elements (z dropped). Throws InputError.
  LineMesh read_line_mesh(const std::string &file);
  /// Read a Gmsh .msh file of line elements in 3D. Throws InputError.
  LineMesh3D read_line_mesh_3d(const std::string &file);
} // namespace poundfe

#endif
