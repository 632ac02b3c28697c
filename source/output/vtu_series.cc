#include <poundfe/base/exceptions.h>
#include <poundfe/elements/frame_element.h>
#include <poundfe/elements/member_element.h>
#include <poundfe/elements/nonlinear_element.h>
#include <poundfe/elements/plan_contact_element.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/number_text.h>
#include <poundfe/output/section_states.h>
#include <poundfe/output/vtu_series.h>

#include "vtu_arrays.h"

#include <deal.II/base/exceptions.h>

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <map>
#include <optional>
#include <tuple>

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

    Cells        cells;
    unsigned int first_gap_cell = 0, first_hinge_cell = 0;
    /// The integration points of fibre members: their vertex cells follow
    /// the hinges', one per point, in the order of the members' elements.
    SectionPointCells         section_points;
    std::vector<unsigned int> section_members; // those members, in order
    /// The cell of each hysteretic storey, in the order of the elements.
    std::vector<unsigned int> hysteretic_storey_cells;
    double      model_size = 0; // largest extent, m

    /// Dimension 3: the spatial drawing (the planar members above are none).
    std::unique_ptr<VtuGeometry3D> space;
    const FieldFormat              format;
    /// The ranks writing one file together (HDF5 + XDMF): the file is
    /// opened at the first frame, when each rank's rows are known.
    std::optional<MPI_Comm> communicator;
    /// Why the ranks' file could not be opened: finish() says it again
    /// (instead of opening an empty one).
    std::exception_ptr open_failure;
    /// The files (VTU + PVD, or HDF5 + XDMF).
    std::unique_ptr<FieldWriter> writer;

    Impl(const Model &model, const std::string &directory, const std::string &name,
         FieldFormat format);

    /// The writer of `format`, the ranks' (`ranks`) or one process's.
    void open(const FieldRanks *ranks);
    /// The drawing's points and cells, planar or spatial.
    std::size_t  n_points() const { return space ? space->point_positions().size() : points.size(); }
    const Cells &drawn_cells() const { return space ? space->cell_list() : cells; }
    /// The rows of each rank under MPI: those it draws whole from its `u`
    /// and `states` (NaN where it has no value: no NaN in any array of the
    /// row), the lowest such rank's. Collective.
    FieldRanks rows_of_ranks(const Vector &u, const ElementFrameStates &states) const;
    /// The arrays of a time frame.
    FieldFrame time_frame(double time, const Vector &u, const ElementFrameStates &states) const;
    /// The cell values of the nonlinear elements and storey links in a time
    /// frame: force, penetration, hysteretic z, plastic deformation, contact.
    struct ElementCellValues
    {
      std::vector<double> force, penetration, z, plastic;
      std::vector<int>    contact;
    };
    ElementCellValues element_cell_values(const Vector &u, const ElementFrameStates &states) const;
    /// The local end forces N V M at both ends of every cell: the members'
    /// (K_e u_e plus self-weight's fixed-end forces, or the fibre members'
    /// resisting forces) and a storey link's shear as V.
    std::vector<std::array<double, 6>>
    cell_end_forces(const Vector &u, const ElementFrameStates &states,
                    const std::vector<double> &link_force) const;

    unsigned int add_point(const Point2 &position, const PointSource &source);
    // the constructor's phases: points of the nodes, the cells (adding the
    // points inside members and at barriers), the extent, the static text
    void  add_node_points();
    Cells make_cells();
    /// The vertex cells of the fibre members' integration points; a point
    /// where a member already has one (members[e]: its points at xi = k /
    /// n_member_subdivisions) is shared.
    void  add_section_cells(Cells &cells, const std::vector<std::vector<long>> &members);
    /// The section arrays of a time frame (cell data, 0 off the points).
    void  add_section_arrays(const ElementFrameStates &states, FieldFrame &frame) const;
    /// The local end forces of the members on fibre sections: their
    /// elements' resisting forces (the elastic K u is wrong once one cracks).
    void  set_fibre_end_forces(const ElementFrameStates               &states,
                               std::vector<std::array<double, 6>> &end_forces) const;
    void  set_model_size();
    /// Global (ux, uy, rz) of every point.
    std::vector<std::array<double, 3>> point_displacements(const Vector &u) const;
    Vector6 element_displacements(const Member &member, const Vector &u) const;
    double  dof_value(const Vector &u, unsigned int node, Component c) const;
    /// The point data (displacement, rotation) and the cell ids of a planar
    /// model; the caller adds the time-dependent cell data.
    FieldFrame frame(const Vector &u, double point_scale) const;
    /// The frame of `u`, planar or spatial (`states`: of a time frame).
    FieldFrame frame(const Vector &u, double scale, const ElementFrameStates *states) const;
  };

  unsigned int
  VtuSeries::Impl::add_point(const Point2 &position, const PointSource &source)
  {
    points.push_back(position);
    sources.push_back(source);
    return points.size() - 1;
  }

  VtuSeries::Impl::Impl(const Model &model, const std::string &directory, const std::string &name,
                        const FieldFormat format)
    : model(model)
    , directory(directory)
    , name(name)
    , format(format)
  {
    if (model.dimension == 3)
      space = std::make_unique<VtuGeometry3D>(model);
    else
      {
        add_node_points();
        cells = make_cells();
        set_model_size();
      }
  }

  void
  VtuSeries::Impl::open(const FieldRanks *ranks)
  {
    Points3 at;
    if (!space)
      for (const Point2 &p : points)
        at.push_back({{p.x, p.y, 0}});
    const Points3 &positions = space ? space->point_positions() : at;
    writer = format == FieldFormat::xdmf ?
               make_xdmf_writer(directory, name, positions, drawn_cells(), ranks) :
               make_vtu_writer(directory, name, positions, drawn_cells());
  }

  FieldRanks
  VtuSeries::Impl::rows_of_ranks(const Vector &u, const ElementFrameStates &states) const
  {
    // the drawing of zeros where this rank has values, NaN where not
    Vector probe = Vector::Zero(u.size());
    for (Eigen::Index q = 0; q < u.size(); ++q)
      if (std::isnan(u[q]))
        probe[q] = u[q];
    ElementFrameStates probe_states = states;
    for (double &x : probe_states.values)
      x = std::isnan(x) ? x : 0.0;
    const FieldFrame frame = time_frame(0, probe, probe_states);

    int rank = 0, n_ranks = 1;
    MPI_Comm_rank(*communicator, &rank);
    MPI_Comm_size(*communicator, &n_ranks);
    FieldRanks ranks{*communicator, {}, {}};
    for (auto [arrays, n_rows, own] :
         {std::tuple{&frame.point, n_points(), &ranks.points},
          {&frame.cell, drawn_cells().types.size(), &ranks.cells}})
      {
        std::vector<int> drawn_by(n_rows, rank); // then the lowest rank that draws the row
        for (const FieldArray &array : *arrays)
          for (std::size_t i = 0; i < array.values.size(); ++i)
            if (!std::isfinite(array.values[i]))
              drawn_by[i / array.n_components] = n_ranks;
        MPI_Allreduce(MPI_IN_PLACE, drawn_by.data(), n_rows, MPI_INT, MPI_MIN, *communicator);
        for (const int r : drawn_by)
          {
            AssertThrow(r < n_ranks,
                        dealii::ExcMessage("a row of the field output that no rank can draw"));
            own->push_back(r == rank);
          }
      }
    return ranks;
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
    std::vector<std::vector<long>> member_points;
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
        member_points.push_back(std::move(cell));
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
    add_section_cells(cells, member_points);
    return cells;
  }

  void
  VtuSeries::Impl::add_section_cells(Cells &cells, const std::vector<std::vector<long>> &members)
  {
    section_points.first_cell = cells.types.size();
    for (unsigned int e = 0; e < model.members.size(); ++e)
      {
        const Member &m = model.members[e];
        if (!m.fibre.fibre() ||
            !dynamic_cast<const FibreSection *>(model.section_laws.at(m.fibre.section).get()))
          continue; // its element has no section states (ElementFrameStates::evaluate)
        const Point2 &start = model.nodes[m.nodes[0]].position;
        const Point2 &end   = model.nodes[m.nodes[1]].position;
        section_members.push_back(e);
        const std::vector<double> xi = fibre_member_integration(m.fibre).points;
        for (unsigned int i = 0; i < xi.size(); ++i)
          {
            const double k     = xi[i] * n_member_subdivisions;
            const long   shared = std::lround(k);
            const long   point =
              std::abs(k - shared) < 1e-12 ?
                members[e][shared] :
                add_point({start.x + xi[i] * (end.x - start.x), start.y + xi[i] * (end.y - start.y)},
                          {-1, static_cast<int>(e), xi[i]});
            cells.add({point}, vtk_vertex, section_point, m.building, cells.members[e]);
            section_points.numbers.push_back(i + 1);
          }
      }
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

  std::vector<FieldArray>
  vtu::cell_id_arrays(const Cells &cells)
  {
    std::vector<FieldArray> ids;
    for (const auto &[array_name, values] :
         {std::pair{"kind", &cells.kinds}, {"building", &cells.buildings},
          {"member", &cells.members}})
      ids.push_back({array_name, 1, true, true, std::vector<double>(values->begin(), values->end())});
    return ids;
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

  FieldFrame
  VtuSeries::Impl::frame(const Vector &u, const double point_scale) const
  {
    const auto d = point_displacements(u);
    FieldArray displacement{"displacement", 3, false, false, {}};
    FieldArray rotation{"rotation", 1, false, false, {}};
    displacement.values.reserve(3 * d.size());
    rotation.values.reserve(d.size());
    for (const auto &p : d)
      {
        displacement.values.insert(displacement.values.end(),
                                   {point_scale * p[0], point_scale * p[1], 0.0});
        rotation.values.push_back(point_scale * p[2]);
      }
    FieldFrame frame;
    frame.point.push_back(std::move(displacement));
    frame.point.push_back(std::move(rotation));
    frame.cell = cell_id_arrays(cells);
    if (!section_points.numbers.empty())
      frame.cell.push_back(section_points.number_array(cells.types.size()));
    return frame;
  }

  FieldFrame
  VtuSeries::Impl::frame(const Vector &u, const double scale,
                         const ElementFrameStates *states) const
  {
    return space ? space->frame(u, scale, states) : frame(u, scale);
  }

  namespace
  {
    /// VTU files and their .pvd index: each frame one file, written whole
    /// (the points, cells and constant arrays encoded once).
    class VtuWriter : public FieldWriter
    {
    public:
      VtuWriter(const std::string &directory, const std::string &name, const Points3 &points,
                const Cells &cells)
        : directory(directory)
        , name(name)
        , n_points(points.size())
        , n_cells(cells.types.size())
      {
        write_geometry(geometry, points, cells);
        create_directories(directory + "/" + name);
      }

      void
      write_frame(const double label, const FieldFrame &frame) override
      {
        std::string xml =
          "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
          "byte_order=\"LittleEndian\" header_type=\"UInt64\" "
          "compressor=\"vtkZLibDataCompressor\">\n<UnstructuredGrid>\n<FieldData>\n";
        xml.reserve(geometry.size() + 16 * (n_points + n_cells) + 1024);
        append_arrays(xml, frame.field);
        xml += "</FieldData>\n<Piece NumberOfPoints=\"" + std::to_string(n_points) +
               "\" NumberOfCells=\"" + std::to_string(n_cells) +
               "\">\n<PointData Vectors=\"displacement\">\n";
        append_arrays(xml, frame.point);
        xml += "</PointData>\n<CellData Scalars=\"kind\">\n";
        append_arrays(xml, frame.cell);
        xml += "</CellData>\n";
        xml += geometry;
        xml += "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";

        char file_name[64];
        std::snprintf(file_name, sizeof file_name, "%s-%05u.vtu", name.c_str(),
                      static_cast<unsigned int>(frames.size()));
        write_file_atomically(directory + "/" + name + "/" + file_name, xml);
        frames.emplace_back(label, name + "/" + file_name);
      }

      void
      finish() override
      {
        std::string pvd = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" "
                          "byte_order=\"LittleEndian\">\n<Collection>\n";
        NumberText text;
        for (const auto &[label, file] : frames)
          {
            char buffer[NumberText::max_length];
            pvd += "  <DataSet timestep=\"" + std::string(buffer, text.write(buffer, label)) +
                   "\" group=\"\" part=\"0\" file=\"" + file + "\"/>\n";
          }
        pvd += "</Collection>\n</VTKFile>\n";
        write_file_atomically(directory + "/" + name + ".pvd", pvd);
      }

    private:
      /// The DataArrays of `arrays`; a constant one's text is made once.
      void
      append_arrays(std::string &xml, const std::vector<FieldArray> &arrays)
      {
        for (const FieldArray &array : arrays)
          {
            if (array.constant)
              {
                auto [it, added] = constant_text.try_emplace(array.name);
                if (added)
                  encode(it->second, array);
                xml += it->second;
              }
            else
              encode(xml, array);
          }
      }

      static void
      encode(std::string &xml, const FieldArray &array)
      {
        DataArrayWriter text(xml);
        text.begin(array.integer ? "Int32" : "Float64", array.name.c_str(), array.n_components);
        for (const double v : array.values)
          if (array.integer)
            text.whole(static_cast<long>(v));
          else
            text.number(v);
        text.end();
      }

      const std::string                           directory, name;
      const std::size_t                           n_points, n_cells;
      std::string                                 geometry;
      std::map<std::string, std::string>          constant_text;
      std::vector<std::pair<double, std::string>> frames;
    };
  } // namespace

  std::unique_ptr<FieldWriter>
  vtu::make_vtu_writer(const std::string &directory, const std::string &name,
                       const Points3 &points, const Cells &cells)
  {
    return std::make_unique<VtuWriter>(directory, name, points, cells);
  }

  VtuSeries::VtuSeries(const Model &model, const std::string &directory, const std::string &name,
                       const FieldFormat format)
    : impl(std::make_unique<Impl>(model, directory, name, format))
  {
    impl->open(nullptr);
  }

  VtuSeries::VtuSeries(const Model &model, const std::string &directory, const std::string &name,
                       const MPI_Comm communicator)
    : impl(std::make_unique<Impl>(model, directory, name, FieldFormat::xdmf))
  {
    impl->communicator = communicator;
  }

  VtuSeries::~VtuSeries() = default;

  void
  ElementFrameStates::evaluate(const NonlinearElements &elements, const Vector &u,
                               const std::vector<char> *observed)
  {
    kinds.resize(elements.size());
    values.assign(n_entries * elements.size(), 0.0);
    std::vector<double> member_forces; // appended after the sections' entries
    for (unsigned int h = 0; h < elements.size(); ++h)
      {
        const NonlinearElement &e = elements[h];
        kinds[h]                  = e.kind;
        const bool seen           = !observed || (*observed)[h];
        for (unsigned int i = 0; fibre_section_of(e, i) != nullptr; ++i) // after all elements
          {
            const FibreSection &section = *fibre_section_of(e, i);
            const std::size_t   at      = values.size();
            values.resize(at + n_section_state_values(section), 0.0);
            if (seen)
              section_state_values(section, fibre_kinds(section.geometry()), &values[at]);
          }
        if (fibre_section_of(e, 0) != nullptr) // global end forces: 6 in the plane, 12 in space
          {
            const auto append = [&](const auto &f) {
              for (Eigen::Index k = 0; k < f.size(); ++k)
                member_forces.push_back(seen ? f[k] : 0.0);
            };
            if (const auto *plane = dynamic_cast<const MemberElement<2> *>(&e))
              append(plane->member().resisting_force());
            else
              append(static_cast<const MemberElement<3> &>(e).member().resisting_force());
          }
        if (!seen)
          continue;
        double *x  = &values[n_entries * h];
        x[force]   = e.force();
        x[history] = e.history_variable();
        x[active]  = e.is_active();
        if (e.initial_stiffness() > 0)
          x[plastic] = e.deformation(u) - e.force() / e.initial_stiffness();
        if (const auto *contact = dynamic_cast<const PlanGapElement *>(&e))
          {
            const std::array<double, 2> p = contact->contact_point();
            const std::array<double, 2> f = contact->force_on_first();
            x[in_reach]                   = contact->in_reach();
            x[point_x]                    = p[0];
            x[point_y]                    = p[1];
            x[force_x]                    = f[0];
            x[force_y]                    = f[1];
          }
      }
    values.insert(values.end(), member_forces.begin(), member_forces.end());
  }

  void
  VtuSeries::write(const double time, const Vector &u, const NonlinearElements &elements)
  {
    ElementFrameStates states;
    states.evaluate(elements, u);
    write(time, u, states);
  }

  void
  VtuSeries::write(const double time, const Vector &u, const ElementFrameStates &states)
  {
    if (impl->open_failure)
      std::rethrow_exception(impl->open_failure);
    if (!impl->writer) // the ranks' file, at its first frame
      {
        const FieldRanks ranks = impl->rows_of_ranks(u, states);
        try
          {
            impl->open(&ranks);
          }
        catch (const OutputError &)
          {
            impl->open_failure = std::current_exception();
            throw;
          }
      }
    impl->writer->write_frame(time, impl->time_frame(time, u, states));
  }

  VtuSeries::Impl::ElementCellValues
  VtuSeries::Impl::element_cell_values(const Vector &u, const ElementFrameStates &states) const
  {
    const unsigned int n = cells.types.size();
    ElementCellValues  values{std::vector<double>(n, 0), std::vector<double>(n, 0),
                             std::vector<double>(n, 0), std::vector<double>(n, 0),
                             std::vector<int>(n, 0)};
    for (unsigned int l = 0; l < model.links.size(); ++l)
      {
        const StoreyLink &link  = model.links[l];
        const unsigned int cell = model.members.size() + l;
        if (!link.hysteretic) // a hysteretic storey's force comes from its element
          values.force[cell] = link.stiffness * (dof_value(u, link.nodes[1], Component::ux) -
                                                 dof_value(u, link.nodes[0], Component::ux));
      }
    unsigned int n_hinges = 0, n_storeys = 0, n_gaps = 0;
    using State = ElementFrameStates;
    for (unsigned int h = 0; h < states.kinds.size(); ++h)
      {
        unsigned int cell = 0;
        switch (states.kinds[h])
          {
            case ElementKind::hinge:
              cell = first_hinge_cell + n_hinges++;
              break;
            case ElementKind::storey:
              cell = hysteretic_storey_cells[n_storeys++];
              break;
            case ElementKind::gap:
              cell = first_gap_cell + n_gaps++;
              values.contact[cell]     = states(h, State::active) != 0;
              values.penetration[cell] = std::max(0.0, states(h, State::history));
              values.force[cell]       = states(h, State::force);
              continue;
            default: // springs and friction to the ground: not drawn
              continue;
          }
        values.force[cell]   = states(h, State::force);
        values.z[cell]       = states(h, State::history);
        values.plastic[cell] = states(h, State::plastic);
      }
    return values;
  }

  std::vector<std::array<double, 6>>
  VtuSeries::Impl::cell_end_forces(const Vector &u, const ElementFrameStates &states,
                                   const std::vector<double> &link_force) const
  {
    std::vector<std::array<double, 6>> end_forces(cells.types.size(), {{0, 0, 0, 0, 0, 0}});
    for (unsigned int e = 0; e < model.members.size(); ++e)
      {
        const Member      &m = model.members[e];
        const FrameElement element(model.nodes[m.nodes[0]].position,
                                   model.nodes[m.nodes[1]].position, m.section);
        // K_e u_e plus the fixed-end forces of a distributed self-weight
        const Vector6 f = element.local_end_forces(element_displacements(m, u)) +
                          element.rotation() * self_weight_end_forces(model, m);
        for (unsigned int k = 0; k < 6; ++k)
          end_forces[e][k] = f[k];
      }
    set_fibre_end_forces(states, end_forces);
    for (unsigned int l = 0; l < model.links.size(); ++l) // a storey's shear as V
      {
        const unsigned int cell = model.members.size() + l;
        end_forces[cell][1]     = link_force[cell];
        end_forces[cell][4]     = -link_force[cell];
      }
    return end_forces;
  }

  FieldFrame
  VtuSeries::Impl::time_frame(const double time, const Vector &u,
                              const ElementFrameStates &states) const
  {
    FieldFrame frame = this->frame(u, 1.0, &states);
    frame.field.push_back({"TIME", 1, false, false, {time}});
    if (space)
      return frame;
    const ElementCellValues values = element_cell_values(u, states);
    const std::vector<std::array<double, 6>> end_forces =
      cell_end_forces(u, states, values.force);

    static const char *end_force_names[6] = {"N_start", "V_start", "M_start",
                                             "N_end",   "V_end",   "M_end"};
    for (unsigned int k = 0; k < 6; ++k)
      {
        FieldArray array{end_force_names[k], 1, false, false, {}};
        for (const auto &f : end_forces)
          array.values.push_back(f[k]);
        frame.cell.push_back(std::move(array));
      }
    for (const auto &[array_name, cell_values] :
         {std::pair{"force", &values.force}, {"penetration", &values.penetration},
          {"z", &values.z}, {"plastic_deformation", &values.plastic}})
      frame.cell.push_back({array_name, 1, false, false, *cell_values});
    frame.cell.push_back({"contact", 1, true, false,
                          std::vector<double>(values.contact.begin(), values.contact.end())});
    add_section_arrays(states, frame);
    return frame;
  }

  void
  VtuSeries::Impl::add_section_arrays(const ElementFrameStates &states, FieldFrame &frame) const
  {
    if (section_points.numbers.empty())
      return;
    // the section entries follow the elements', point after point in the
    // order of the members' elements, which is the cells' order
    const std::size_t first = ElementFrameStates::n_entries * states.kinds.size();
    AssertThrow(states.values.size() == first +
                                          n_section_state_entries * section_points.numbers.size() +
                                          6 * section_members.size(),
                dealii::ExcMessage("the fibre members' integration points and their drawing differ"));
    section_points.add_arrays({"section_N", "section_M", "axial_strain", "curvature",
                               "concrete_strain", "steel_strain_max", "steel_strain_min"},
                              states.values, first, cells.types.size(), frame);
  }

  FieldArray
  vtu::SectionPointCells::number_array(const std::size_t n_cells) const
  {
    FieldArray number{"integration_point", 1, true, true, std::vector<double>(n_cells, 0.0)};
    std::copy(numbers.begin(), numbers.end(), number.values.begin() + first_cell);
    return number;
  }

  void
  vtu::SectionPointCells::add_arrays(const std::vector<const char *> &names,
                                     const std::vector<double> &values, const std::size_t first,
                                     const std::size_t n_cells, FieldFrame &frame) const
  {
    const std::size_t n_values = names.size();
    for (std::size_t k = 0; k < n_values; ++k)
      {
        FieldArray array{names[k], 1, false, false, std::vector<double>(n_cells, 0.0)};
        for (std::size_t p = 0; p < numbers.size(); ++p)
          array.values[first_cell + p] = values[first + n_values * p + k];
        frame.cell.push_back(std::move(array));
      }
  }

  void
  VtuSeries::Impl::set_fibre_end_forces(const ElementFrameStates               &states,
                                        std::vector<std::array<double, 6>> &end_forces) const
  {
    // after the elements' entries and the sections' (add_section_arrays checks the size)
    const std::size_t first = ElementFrameStates::n_entries * states.kinds.size() +
                              n_section_state_entries * section_points.numbers.size();
    if (states.values.size() != first + 6 * section_members.size())
      return; // add_section_arrays refuses the frame
    for (std::size_t k = 0; k < section_members.size(); ++k)
      {
        const Member      &m = model.members[section_members[k]];
        const FrameElement element(model.nodes[m.nodes[0]].position,
                                   model.nodes[m.nodes[1]].position, m.section);
        const Vector6 f = element.rotation() * Eigen::Map<const Vector6>(&states.values[first + 6 * k]);
        for (unsigned int c = 0; c < 6; ++c)
          end_forces[section_members[k]][c] = f[c];
      }
  }

  void
  VtuSeries::write_mode(const unsigned int mode, const double frequency, const Vector &shape)
  {
    Assert(impl->writer, dealii::ExcMessage("mode shapes are written by one process"));
    double largest = 0; // translation of the shape
    if (impl->space)
      largest = impl->space->largest_translation(shape);
    else
      for (const auto &d : impl->point_displacements(shape))
        largest = std::max(largest, std::hypot(d[0], d[1]));
    const double size  = impl->space ? impl->space->size() : impl->model_size;
    const double scale = largest > 0 ? mode_amplitude * size / largest : 1.0;

    FieldFrame frame = impl->frame(shape, scale, nullptr);
    for (const auto &[field_name, value] :
         {std::pair{"mode", double(mode)}, {"frequency_Hz", frequency},
          {"period_s", frequency > 0 ? 1 / frequency : 0.0}, {"scale", scale}})
      frame.field.push_back({field_name, 1, false, false, {value}});
    impl->writer->write_frame(mode, frame);
  }

  void
  VtuSeries::finish()
  {
    if (impl->open_failure)
      std::rethrow_exception(impl->open_failure);
    if (!impl->writer) // the ranks' file without a frame
      {
        const FieldRanks none{*impl->communicator, std::vector<char>(impl->n_points(), 0),
                              std::vector<char>(impl->drawn_cells().types.size(), 0)};
        impl->open(&none);
      }
    impl->writer->finish();
  }
  double
  total_gap_force(const NonlinearElements &elements)
  {
    double force = 0;
    for (const NonlinearElement &e : elements)
      if (e.kind == ElementKind::gap)
        force += std::abs(e.force());
    return force;
  }

  void
  VtuRecorder::initialize(const ResponseView &state)
  {
    next  = 0;
    peaks = ImpactPeakRule();
    held  = HeldStep();
    observe_step(state);
  }

  void
  VtuRecorder::observe_step(const ResponseView &state)
  {
    // the gaps' total |force| at this step (summed only when asked for)
    const double force = impact_peaks ? total_gap_force(state.elements) : 0.0;
    if (peaks.held_was_peak(force))
      series.write(held.time, held.u, held.states);
    const bool regular = state.step() == next;
    if (regular)
      {
        next += every;
        series.write(state.time(), state.displacement(), state.elements);
      }
    if (peaks.hold(force, regular))
      {
        held.time = state.time();
        held.u    = state.displacement();
        held.states.evaluate(state.elements, state.displacement());
      }
  }
} // namespace poundfe
