#include <poundfe/elements/frame_element.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/vtu_series.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>

#include <cstdio>
#include <sstream>

namespace poundfe
{
  struct VtuSeries::Impl
  {
    const Model                          &model;
    std::string                           directory, name;
    dealii::Triangulation<1, 2>           triangulation;
    dealii::FESystem<1, 2>                fe{dealii::FE_Q<1, 2>(1), 3};
    dealii::DoFHandler<1, 2>              dof_handler;
    std::vector<int>                      equation_of_dealii_dof; // -1: fixed
    std::vector<std::pair<double, std::string>> frames;

    Impl(const Model &model, const std::string &directory, const std::string &name)
      : model(model)
      , directory(directory)
      , name(name)
    {
      std::vector<dealii::Point<2>> vertices;
      for (const Node &node : model.nodes)
        vertices.emplace_back(node.position.x, node.position.y);
      std::vector<dealii::CellData<1>> cells;
      auto add_cell = [&](const std::array<unsigned int, 2> &nodes) {
        dealii::CellData<1> cell;
        cell.vertices    = {nodes[0], nodes[1]};
        cell.material_id = cells.size(); // index: members first, then links
        cells.push_back(cell);
      };
      for (const Member &member : model.members)
        add_cell(member.nodes);
      for (const StoreyLink &link : model.links)
        add_cell(link.nodes);
      triangulation.create_triangulation(vertices, cells, dealii::SubCellData());
      dof_handler.reinit(triangulation);
      dof_handler.distribute_dofs(fe);

      equation_of_dealii_dof.assign(dof_handler.n_dofs(), -1);
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (unsigned int v = 0; v < 2; ++v)
          for (unsigned int c = 0; c < 3; ++c)
            {
              const auto         i    = cell->vertex_dof_index(v, c);
              const unsigned int node = cell->vertex_index(v);
              equation_of_dealii_dof[i]  = model.equation(n_dofs_per_node * node + c);
            }
    }
  };

  VtuSeries::VtuSeries(const Model &model, const std::string &directory, const std::string &name)
    : impl(std::make_unique<Impl>(model, directory, name))
  {
    create_directories(directory + "/" + name);
  }

  VtuSeries::~VtuSeries() = default;

  void
  VtuSeries::write(const double label, const Vector &u, const bool with_forces)
  {
    const Model           &model = impl->model;
    dealii::Vector<double> solution(impl->dof_handler.n_dofs());
    for (unsigned int i = 0; i < solution.size(); ++i)
      if (impl->equation_of_dealii_dof[i] >= 0)
        solution[i] = u[impl->equation_of_dealii_dof[i]];

    // Displacements of all model DOFs (fixed ones are zero).
    std::vector<double> model_u(model.n_dofs(), 0.0);
    for (unsigned int d = 0; d < model.n_dofs(); ++d)
      if (model.equation(d) >= 0)
        model_u[d] = u[model.equation(d)];

    const unsigned int                 n_cells = impl->triangulation.n_active_cells();
    std::vector<dealii::Vector<double>> forces(6, dealii::Vector<double>(n_cells));
    if (with_forces)
      for (const auto &cell : impl->triangulation.active_cell_iterators())
        {
          const unsigned int index = cell->material_id();
          const unsigned int slot  = cell->active_cell_index();
          if (index < model.members.size())
            {
              const Member      &m = model.members[index];
              const FrameElement element(model.nodes[m.nodes[0]].position,
                                         model.nodes[m.nodes[1]].position, m.section);
              Vector6            ue;
              for (unsigned int k = 0; k < 6; ++k)
                ue[k] = model_u[n_dofs_per_node * m.nodes[k / 3] + k % 3];
              const Vector6 f = element.local_end_forces(ue);
              for (unsigned int k = 0; k < 6; ++k)
                forces[k][slot] = f[k];
            }
          else
            {
              const StoreyLink &link = model.links[index - model.members.size()];
              const double      shear =
                link.stiffness * (model_u[Model::dof(link.nodes[1], Component::ux)] -
                                  model_u[Model::dof(link.nodes[0], Component::ux)]);
              forces[1][slot] = shear;
              forces[4][slot] = -shear;
            }
        }

    dealii::DataOut<1, 2> data_out;
    data_out.attach_dof_handler(impl->dof_handler);
    const std::vector<std::string> names{"displacement", "displacement", "rotation"};
    const std::vector<dealii::DataComponentInterpretation::DataComponentInterpretation>
      interpretation{dealii::DataComponentInterpretation::component_is_part_of_vector,
                     dealii::DataComponentInterpretation::component_is_part_of_vector,
                     dealii::DataComponentInterpretation::component_is_scalar};
    data_out.add_data_vector(solution, names, dealii::DataOut<1, 2>::type_dof_data,
                             interpretation);
    static const char *force_names[6] = {"N_start", "V_start", "M_start",
                                         "N_end",   "V_end",   "M_end"};
    if (with_forces)
      for (unsigned int k = 0; k < 6; ++k)
        data_out.add_data_vector(forces[k], force_names[k],
                                 dealii::DataOut<1, 2>::type_cell_data);
    data_out.build_patches();

    char file_name[64];
    std::snprintf(file_name, sizeof file_name, "%s-%05u.vtu", impl->name.c_str(),
                  static_cast<unsigned int>(impl->frames.size()));
    std::ostringstream vtu;
    data_out.write_vtu(vtu);
    write_file_atomically(impl->directory + "/" + impl->name + "/" + file_name, vtu.str());
    impl->frames.emplace_back(label, impl->name + "/" + file_name);
  }

  void
  VtuSeries::finish()
  {
    std::ostringstream pvd;
    dealii::DataOutBase::write_pvd_record(pvd, impl->frames);
    write_file_atomically(impl->directory + "/" + impl->name + ".pvd", pvd.str());
  }
} // namespace poundfe
