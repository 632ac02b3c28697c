#include <poundfe/base/exceptions.h>
#include <poundfe/base/input_text.h>
#include <poundfe/mesh/gmsh_check.h>
#include <poundfe/mesh/line_mesh.h>

#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>

#include <sstream>

namespace poundfe
{
  LineMesh
  read_line_mesh(const std::string &file)
  {
    const std::string text = read_input_text(file, "mesh file");
    check_gmsh_text(file, text); // read_msh trusts its input (mesh/gmsh_check.h)
    std::istringstream in(text);

    dealii::Triangulation<1, 2> triangulation;
    dealii::GridIn<1, 2>        grid_in;
    grid_in.attach_triangulation(triangulation);
    try
      {
        grid_in.read_msh(in);
      }
    catch (const dealii::ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        throw InputError(file, 0, "", "not a readable Gmsh mesh of line elements: " +
                                        info.str());
      }

    LineMesh mesh;
    mesh.vertices.reserve(triangulation.n_vertices());
    for (const auto &v : triangulation.get_vertices())
      mesh.vertices.push_back({v[0], v[1]});
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        mesh.cells.push_back({{cell->vertex_index(0), cell->vertex_index(1)}});
        mesh.material_ids.push_back(cell->material_id());
      }
    if (mesh.cells.empty())
      throw InputError(file, 0, "", "the mesh has no line elements");
    return mesh;
  }
} // namespace poundfe
