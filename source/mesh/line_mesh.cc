// Gmsh line meshes in 2D and 3D (include/poundfe/mesh/line_mesh.h).
#include <poundfe/base/exceptions.h>
#include <poundfe/base/input_text.h>
#include <poundfe/mesh/gmsh_check.h>
#include <poundfe/mesh/line_mesh.h>

#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>

#include <sstream>

namespace poundfe
{
  namespace
  {
    /// The line cells of `file` embedded in `spacedim` dimensions: every
    /// vertex (its coordinates through `add_vertex`), the cells' vertex
    /// indices and physical ids into `cells` and `material_ids`.
    template <int spacedim, typename Mesh, typename AddVertex>
    void
    read_line_cells(const std::string &file, Mesh &mesh, const AddVertex &add_vertex)
    {
      const std::string text = read_input_text(file, "mesh file");
      check_gmsh_text(file, text); // read_msh trusts its input (mesh/gmsh_check.h)
      std::istringstream in(text);

      dealii::Triangulation<1, spacedim> triangulation;
      dealii::GridIn<1, spacedim>        grid_in;
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
      mesh.vertices.reserve(triangulation.n_vertices());
      for (const auto &v : triangulation.get_vertices())
        add_vertex(v);
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          mesh.cells.push_back({{cell->vertex_index(0), cell->vertex_index(1)}});
          mesh.material_ids.push_back(cell->material_id());
        }
      if (mesh.cells.empty())
        throw InputError(file, 0, "", "the mesh has no line elements");
    }
  } // namespace

  LineMesh
  read_line_mesh(const std::string &file)
  {
    LineMesh mesh;
    read_line_cells<2>(file, mesh, [&](const dealii::Point<2> &v) {
      mesh.vertices.push_back({v[0], v[1]});
    });
    return mesh;
  }

  LineMesh3D
  read_line_mesh_3d(const std::string &file)
  {
    LineMesh3D mesh;
    read_line_cells<3>(file, mesh, [&](const dealii::Point<3> &v) {
      mesh.vertices.push_back({{v[0], v[1], v[2]}});
    });
    return mesh;
  }
} // namespace poundfe
