#include <poundfe/elements/frame_element.h>
#include <poundfe/elements/nonlinear_element.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/number_text.h>
#include <poundfe/output/vtu_series.h>

#include "vtu_arrays.h"

#include <deal.II/base/exceptions.h>

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <optional>

namespace poundfe
{
  using namespace vtu;

  struct VtuSeries::Impl
  {
    const Model &model;
    std::string  directory, name;

    /// Where each point's displacement comes from.
    struct PointSource
    {
      int    node    = -1; // a node's own DOFs; -1: inside an element or a barrier
      int    element = -1; // the frame element (model.members index) it lies in
      double xi      = 0;  // its place along that element
    };
    std::vector<Point2>       points;
    std::vector<PointSource>  sources;
    std::vector<unsigned int> point_of_node;

    unsigned int n_cells = 0;
    unsigned int first_gap_cell = 0, first_hinge_cell = 0;
    /// The cell of each hysteretic storey, in the order of the elements.
    std::vector<unsigned int> hysteretic_storey_cells;
    /// The static part of every file: cell ids (CellData), points and cells.
    std::string static_cell_data, geometry;
    double      model_size = 0; // largest extent, m

    std::vector<std::pair<double, std::string>> frames;
    /// Dimension 3: the spatial drawing (the planar members above are none).
    std::unique_ptr<VtuGeometry3D> space;

    Impl(const Model &model, const std::string &directory, const std::string &name);

    unsigned int add_point(const Point2 &position, const PointSource &source);
    // the constructor's phases: points of the nodes, the cells (adding the
    // points inside members and at barriers), the extent, the static text
    void  add_node_points();
    Cells make_cells();
    void  set_model_size();
    void  write_static_text(const Cells &cells);
    /// Global (ux, uy, rz) of every point.
    std::vector<std::array<double, 3>> point_displacements(const Vector &u) const;
    Vector6 element_displacements(const Member &member, const Vector &u) const;
    double  dof_value(const Vector &u, unsigned int node, Component c) const;
    /// The <Piece> of a planar model; `cell_arrays` adds the time-dependent CellData.
    std::string piece(const Vector &u, double point_scale, const std::string &cell_arrays) const;
    /// Writes one file around its field data and piece.
    void write_file(const std::string &field_data, const std::string &piece, double label);
  };

  unsigned int
  VtuSeries::Impl::add_point(const Point2 &position, const PointSource &source)
  {
    points.push_back(position);
    sources.push_back(source);
    return points.size() - 1;
  }

  VtuSeries::Impl::Impl(const Model &model, const std::string &directory, const std::string &name)
    : model(model)
    , directory(directory)
    , name(name)
  {
    if (model.dimension == 3)
      {
        space = std::make_unique<VtuGeometry3D>(model);
        return;
      }
    add_node_points();
    const Cells cells = make_cells();
    n_cells           = cells.types.size();
    set_model_size();
    write_static_text(cells);
  }

  void
  VtuSeries::Impl::add_node_points()
  {
    // one point per node; a hinge's member-side node is drawn at its joint
    point_of_node.assign(model.nodes.size(), 0);
    for (unsigned int n = 0; n < model.nodes.size(); ++n)
      if (model.nodes[n].tied_to < 0)
        point_of_node[n] = add_point(model.nodes[n].position, {static_cast<int>(n), -1, 0});
    for (unsigned int n = 0; n < model.nodes.size(); ++n)
      if (model.nodes[n].tied_to >= 0)
        point_of_node[n] = point_of_node[model.nodes[n].tied_to];
  }

  Cells
  VtuSeries::Impl::make_cells()
  {
    Cells cells;
    std::map<std::string, int> member_id; // the pieces of a member share its label
    for (unsigned int e = 0; e < model.members.size(); ++e)
      {
        const Member &m     = model.members[e];
        const Point2 &start = model.nodes[m.nodes[0]].position;
        const Point2 &end   = model.nodes[m.nodes[1]].position;
        std::vector<long> cell{point_of_node[m.nodes[0]]};
        for (unsigned int i = 1; i < n_member_subdivisions; ++i)
          {
            const double xi = double(i) / n_member_subdivisions;
            cell.push_back(add_point({start.x + xi * (end.x - start.x),
                                      start.y + xi * (end.y - start.y)},
                                     {-1, static_cast<int>(e), xi}));
          }
        cell.push_back(point_of_node[m.nodes[1]]);
        const int id = member_id.emplace(m.label, member_id.size() + 1).first->second;
        cells.add(cell, vtk_poly_line, frame_element, m.building, id);
      }
    for (const StoreyLink &link : model.links)
      {
        if (link.hysteretic)
          hysteretic_storey_cells.push_back(cells.types.size());
        cells.add({point_of_node[link.nodes[0]], point_of_node[link.nodes[1]]}, vtk_line, storey,
                  link.building, 0);
      }
    first_gap_cell = cells.types.size();
    for (const Gap &g : model.gaps)
      {
        std::array<long, 2> ends{{-1, -1}};
        for (unsigned int side = 0; side < 2; ++side)
          if (g.nodes[side] >= 0)
            ends[side] = point_of_node[g.nodes[side]];
        for (unsigned int side = 0; side < 2; ++side)
          if (ends[side] < 0) // the barrier, at the gap's width from the node
            {
              const Point2 &at = model.nodes[g.nodes[1 - side]].position;
              ends[side] = add_point({at.x + (side == 1 ? 1 : -1) * g.initial_gap, at.y}, {});
            }
        cells.add({ends[0], ends[1]}, vtk_line, gap, g.buildings[0], 0);
      }
    first_hinge_cell = cells.types.size();
    for (const Hinge &h : model.hinges)
      cells.add({point_of_node[h.joint_node]}, vtk_vertex, hinge, h.building,
                cells.members[h.member]);
    return cells;
  }

  void
  VtuSeries::Impl::set_model_size()
  {
    double x_min = 0, x_max = 0, y_min = 0, y_max = 0;
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        x_min = p == 0 ? points[p].x : std::min(x_min, points[p].x);
        x_max = p == 0 ? points[p].x : std::max(x_max, points[p].x);
        y_min = p == 0 ? points[p].y : std::min(y_min, points[p].y);
        y_max = p == 0 ? points[p].y : std::max(y_max, points[p].y);
      }
    model_size = std::max(x_max - x_min, y_max - y_min);
  }

  void
  vtu::write_cell_ids(std::string &out, const Cells &cells)
  {
    DataArrayWriter text(out);
    const std::pair<const char *, const std::vector<int> *> ids[] = {
      {"kind", &cells.kinds}, {"building", &cells.buildings}, {"member", &cells.members}};
    for (const auto &[array_name, values] : ids)
      {
        text.begin("Int32", array_name, 1);
        for (const int v : *values)
          text.whole(v);
        text.end();
      }
  }

  void
  vtu::write_geometry(std::string &out, const std::vector<std::array<double, 3>> &points,
                      const Cells &cells)
  {
    DataArrayWriter g(out);
    out += "<Points>\n";
    g.begin("Float64", "Points", 3);
    for (const auto &p : points)
      for (const double x : p)
        g.number(x);
    g.end();
    out += "</Points>\n<Cells>\n";
    g.begin("Int64", "connectivity", 1);
    for (const long c : cells.connectivity)
      g.whole(c);
    g.end();
    g.begin("Int64", "offsets", 1);
    for (const long o : cells.offsets)
      g.whole(o);
    g.end();
    g.begin("UInt8", "types", 1);
    for (const int t : cells.types)
      g.whole(t);
    g.end();
    out += "</Cells>\n";
  }

  void
  VtuSeries::Impl::write_static_text(const Cells &cells)
  {
    write_cell_ids(static_cell_data, cells);
    std::vector<std::array<double, 3>> at;
    for (const Point2 &p : points)
      at.push_back({{p.x, p.y, 0}});
    write_geometry(geometry, at, cells);
  }

  double
  VtuSeries::Impl::dof_value(const Vector &u, const unsigned int node, const Component c) const
  {
    const int equation = model.equation(Model::dof(node, c));
    return equation >= 0 ? u[equation] : 0.0;
  }

  Vector6
  VtuSeries::Impl::element_displacements(const Member &member, const Vector &u) const
  {
    Vector6 ue;
    for (unsigned int k = 0; k < 6; ++k)
      ue[k] = dof_value(u, member.nodes[k / 3], static_cast<Component>(k % 3));
    return ue;
  }

  std::vector<std::array<double, 3>>
  VtuSeries::Impl::point_displacements(const Vector &u) const
  {
    std::vector<std::array<double, 3>> d(points.size(), {{0, 0, 0}});
    for (unsigned int p = 0; p < points.size(); ++p)
      if (sources[p].node >= 0)
        for (unsigned int c = 0; c < 3; ++c)
          d[p][c] = dof_value(u, sources[p].node, static_cast<Component>(c));
    int                         element = -1;
    Vector6                     ue;
    std::optional<FrameElement> frame;
    for (unsigned int p = 0; p < points.size(); ++p)
      if (sources[p].element >= 0)
        {
          if (sources[p].element != element) // interior points come element by element
            {
              element         = sources[p].element;
              const Member &m = model.members[element];
              ue              = element_displacements(m, u);
              frame.emplace(model.nodes[m.nodes[0]].position, model.nodes[m.nodes[1]].position,
                            m.section);
            }
          d[p] = frame->displacement_at(ue, sources[p].xi);
        }
    return d;
  }

  std::string
  VtuSeries::Impl::piece(const Vector &u, const double point_scale,
                         const std::string &cell_arrays) const
  {
    std::string xml;
    xml.reserve(geometry.size() + static_cell_data.size() + cell_arrays.size() +
                60 * points.size() + 1024);
    xml += "<Piece NumberOfPoints=\"" + std::to_string(points.size()) + "\" NumberOfCells=\"" +
           std::to_string(n_cells) + "\">\n<PointData Vectors=\"displacement\">\n";
    const auto d = point_displacements(u);
    DataArrayWriter  text(xml);
    text.begin("Float64", "displacement", 3);
    for (const auto &p : d)
      {
        text.number(point_scale * p[0]);
        text.number(point_scale * p[1]);
        text.number(0);
      }
    text.end();
    text.begin("Float64", "rotation", 1);
    for (const auto &p : d)
      text.number(point_scale * p[2]);
    text.end();
    xml += "</PointData>\n<CellData Scalars=\"kind\">\n";
    xml += static_cell_data;
    xml += cell_arrays;
    xml += "</CellData>\n";
    xml += geometry;
    xml += "</Piece>\n";
    return xml;
  }

  void
  VtuSeries::Impl::write_file(const std::string &field_data, const std::string &piece,
                              const double label)
  {
    std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
                      "byte_order=\"LittleEndian\" header_type=\"UInt64\" "
                      "compressor=\"vtkZLibDataCompressor\">\n<UnstructuredGrid>\n";
    xml += field_data;
    xml += piece;
    xml += "</UnstructuredGrid>\n</VTKFile>\n";

    char file_name[64];
    std::snprintf(file_name, sizeof file_name, "%s-%05u.vtu", name.c_str(),
                  static_cast<unsigned int>(frames.size()));
    write_file_atomically(directory + "/" + name + "/" + file_name, xml);
    frames.emplace_back(label, name + "/" + file_name);
  }

  VtuSeries::VtuSeries(const Model &model, const std::string &directory, const std::string &name)
    : impl(std::make_unique<Impl>(model, directory, name))
  {
    create_directories(directory + "/" + name);
  }

  VtuSeries::~VtuSeries() = default;

  namespace
  {
    /// The FieldData of a time frame: TIME.
    std::string
    time_field(const double time)
    {
      std::string     field_data = "<FieldData>\n";
      DataArrayWriter field(field_data);
      field.begin("Float64", "TIME", 1);
      field.number(time);
      field.end();
      return field_data + "</FieldData>\n";
    }
  } // namespace

  void
  VtuSeries::write(const double time, const Vector &u, const NonlinearElements &elements)
  {
    if (impl->space)
      {
        impl->write_file(time_field(time), impl->space->piece(u, 1.0, &elements), time);
        return;
      }
    const Model        &model = impl->model;
    const unsigned int  n     = impl->n_cells;
    // end forces N V M at both ends, then force, contact, penetration, z,
    // plastic deformation
    std::vector<std::array<double, 6>> end_forces(n, {{0, 0, 0, 0, 0, 0}});
    std::vector<double> force(n, 0), penetration(n, 0), z(n, 0), plastic(n, 0);
    std::vector<int>    contact(n, 0);
    for (unsigned int e = 0; e < model.members.size(); ++e)
      {
        const Member      &m = model.members[e];
        const FrameElement element(model.nodes[m.nodes[0]].position,
                                   model.nodes[m.nodes[1]].position, m.section);
        const Vector6      f = element.local_end_forces(impl->element_displacements(m, u));
        for (unsigned int k = 0; k < 6; ++k)
          end_forces[e][k] = f[k];
      }
    for (unsigned int l = 0; l < model.links.size(); ++l)
      {
        const StoreyLink &link  = model.links[l];
        const unsigned int cell = model.members.size() + l;
        if (!link.hysteretic) // a hysteretic storey's force comes from its element
          force[cell] = link.stiffness * (impl->dof_value(u, link.nodes[1], Component::ux) -
                                          impl->dof_value(u, link.nodes[0], Component::ux));
      }
    unsigned int n_hinges = 0, n_storeys = 0, n_gaps = 0;
    for (const NonlinearElement &element : elements)
      {
        unsigned int cell = 0;
        switch (element.kind)
          {
            case ElementKind::hinge:
              cell = impl->first_hinge_cell + n_hinges++;
              break;
            case ElementKind::storey:
              cell = impl->hysteretic_storey_cells[n_storeys++];
              break;
            case ElementKind::gap:
              cell = impl->first_gap_cell + n_gaps++;
              contact[cell]     = element.is_active();
              penetration[cell] = std::max(0.0, element.history_variable());
              force[cell]       = element.force();
              continue;
            default: // springs and friction to the ground: not drawn
              continue;
          }
        force[cell] = element.force();
        z[cell]     = element.history_variable();
        if (element.initial_stiffness() > 0)
          plastic[cell] = element.deformation(u) - element.force() / element.initial_stiffness();
      }
    for (unsigned int l = 0; l < model.links.size(); ++l) // a storey's shear as V
      {
        const unsigned int cell = model.members.size() + l;
        end_forces[cell][1]     = force[cell];
        end_forces[cell][4]     = -force[cell];
      }

    std::string cell_arrays;
    DataArrayWriter   text(cell_arrays);
    static const char *end_force_names[6] = {"N_start", "V_start", "M_start",
                                             "N_end",   "V_end",   "M_end"};
    for (unsigned int k = 0; k < 6; ++k)
      {
        text.begin("Float64", end_force_names[k], 1);
        for (const auto &f : end_forces)
          text.number(f[k]);
        text.end();
      }
    const std::pair<const char *, const std::vector<double> *> arrays[] = {
      {"force", &force}, {"penetration", &penetration}, {"z", &z},
      {"plastic_deformation", &plastic}};
    for (const auto &[array_name, values] : arrays)
      {
        text.begin("Float64", array_name, 1);
        for (const double v : *values)
          text.number(v);
        text.end();
      }
    text.begin("Int32", "contact", 1);
    for (const int c : contact)
      text.whole(c);
    text.end();

    impl->write_file(time_field(time), impl->piece(u, 1.0, cell_arrays), time);
  }

  void
  VtuSeries::write_mode(const unsigned int mode, const double frequency, const Vector &shape)
  {
    double largest = 0; // translation of the shape
    if (impl->space)
      largest = impl->space->largest_translation(shape);
    else
      for (const auto &d : impl->point_displacements(shape))
        largest = std::max(largest, std::hypot(d[0], d[1]));
    const double size  = impl->space ? impl->space->size() : impl->model_size;
    const double scale = largest > 0 ? mode_amplitude * size / largest : 1.0;

    std::string field_data;
    DataArrayWriter   field(field_data);
    field_data += "<FieldData>\n";
    const std::pair<const char *, double> values[] = {
      {"mode", mode}, {"frequency_Hz", frequency}, {"period_s", frequency > 0 ? 1 / frequency : 0.0}, {"scale", scale}};
    for (const auto &[field_name, value] : values)
      {
        field.begin("Float64", field_name, 1);
        field.number(value);
        field.end();
      }
    field_data += "</FieldData>\n";
    impl->write_file(field_data,
                     impl->space ? impl->space->piece(shape, scale, nullptr) :
                                   impl->piece(shape, scale, {}),
                     mode);
  }

  void
  VtuSeries::finish()
  {
    std::string pvd = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" "
                      "byte_order=\"LittleEndian\">\n<Collection>\n";
    NumberText text;
    for (const auto &[label, file] : impl->frames)
      {
        char buffer[NumberText::max_length];
        pvd += "  <DataSet timestep=\"" + std::string(buffer, text.write(buffer, label)) +
               "\" group=\"\" part=\"0\" file=\"" + file + "\"/>\n";
      }
    pvd += "</Collection>\n</VTKFile>\n";
    write_file_atomically(impl->directory + "/" + impl->name + ".pvd", pvd);
  }
} // namespace poundfe
