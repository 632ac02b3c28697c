// Private to source/output: the pieces of VTK XML text that the planar
// (vtu_series.cc) and the spatial (vtu_series_3d.cc) drawings share — the
// compressed binary DataArray (Kitware, "VTK File Formats": XML format,
// vtkZLibDataCompressor), the cell lists, the cell kinds — and the spatial
// drawing itself (VtuGeometry3D, doc/theory.md §10); a frame's arrays in a
// form both writers read (FieldFrame), for the VTU files and for HDF5 + XDMF
// (xdmf_series.cc).
#ifndef poundfe_output_vtu_arrays_h
#define poundfe_output_vtu_arrays_h

#include <poundfe/assembly/linear_system.h>
#include <poundfe/model/model.h>

#include <deal.II/base/exceptions.h>

#include <mpi.h>
#include <zlib.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  class NonlinearElements;
  struct ElementFrameStates;

  namespace vtu
  {
    // VTK cell types (vtkCellType.h)
    constexpr int vtk_vertex = 1, vtk_line = 3, vtk_poly_line = 4;

    constexpr int vtk_polygon = 7;

    enum CellKind : int
    {
      frame_element = 0,
      storey        = 1,
      gap           = 2,
      hinge         = 3,
      slab          = 4, // a rigid floor's outline (3D)
      mass_centre   = 5, // a rigid floor's master node (3D)
      contact_point = 6, // a gap's point of contact in plan (3D)
      section_point = 7, // an integration point of a member on fibre sections
      contact_arrow = 8  // the stem from a contact point up to its force arrow's point (3D)
    };

    static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
                  "the VTU files declare byte_order=\"LittleEndian\"");

    /// Base64 (RFC 4648) of `n` bytes, appended to `out`.
    inline void
    append_base64(std::string &out, const unsigned char *data, const std::size_t n)
    {
      static const char digits[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
      for (std::size_t i = 0; i < n; i += 3)
        {
          const unsigned int b = (data[i] << 16) | (i + 1 < n ? data[i + 1] << 8 : 0) |
                                 (i + 2 < n ? data[i + 2] : 0);
          out += digits[(b >> 18) & 63];
          out += digits[(b >> 12) & 63];
          out += i + 1 < n ? digits[(b >> 6) & 63] : '=';
          out += i + 2 < n ? digits[b & 63] : '=';
        }
    }

    /// One DataArray in VTK's compressed binary form: the values' bytes
    /// (little endian, as declared in the file) deflated by zlib in one
    /// block, written as base64 of the header {1 block, size, size,
    /// compressed size} (UInt64) followed by base64 of the block.
    class DataArrayWriter
    {
    public:
      explicit DataArrayWriter(std::string &out)
        : out(out)
      {}
      void
      begin(const char *type, const char *name, const unsigned int n_components)
      {
        this->type = type;
        raw.clear();
        out += "<DataArray type=\"";
        out += type;
        out += "\" Name=\"";
        out += name;
        out += "\" NumberOfComponents=\"" + std::to_string(n_components) +
               "\" format=\"binary\">\n";
      }
      void number(const double x) { append(x); }
      void
      whole(const long x)
      {
        if (std::strcmp(type, "Int32") == 0)
          append(static_cast<std::int32_t>(x));
        else if (std::strcmp(type, "UInt8") == 0)
          append(static_cast<std::uint8_t>(x));
        else
          append(static_cast<std::int64_t>(x));
      }
      void
      end()
      {
        uLongf compressed_size = compressBound(raw.size());
        compressed.resize(compressed_size);
        const int status =
          compress2(compressed.data(), &compressed_size,
                    reinterpret_cast<const Bytef *>(raw.data()), raw.size(), Z_BEST_SPEED);
        AssertThrow(status == Z_OK, dealii::ExcMessage("zlib failed to compress a VTU array"));
        const std::uint64_t header[4] = {1, raw.size(), raw.size(), compressed_size};
        append_base64(out, reinterpret_cast<const unsigned char *>(header), sizeof header);
        append_base64(out, compressed.data(), compressed_size);
        out += "\n</DataArray>\n";
      }

    private:
      template <typename T>
      void
      append(const T x)
      {
        raw.append(reinterpret_cast<const char *>(&x), sizeof x); // x86/ARM: little endian
      }
      std::string               &out;
      const char                *type = "";
      std::string                raw;
      std::vector<unsigned char> compressed;
    };
    /// The cells of a VTU file as its arrays: connectivity, offsets, VTK
    /// types, and the CellData ids (kind, building 1-based, member).
    struct Cells
    {
      std::vector<long> connectivity, offsets;
      std::vector<int>  types, kinds, buildings, members;

      void
      add(const std::vector<long> &cell_points, const int type, const CellKind kind,
          const unsigned int building, const int member)
      {
        connectivity.insert(connectivity.end(), cell_points.begin(), cell_points.end());
        offsets.push_back(connectivity.size());
        types.push_back(type);
        kinds.push_back(kind);
        buildings.push_back(building + 1);
        members.push_back(member);
      }
    };

    /// The <Points> and <Cells> of a piece.
    void write_geometry(std::string &out, const std::vector<std::array<double, 3>> &points,
                        const Cells &cells);

    /// One array of a frame (field, point or cell data), whatever the file
    /// format: `n_components` values per point or cell, in that order.
    struct FieldArray
    {
      std::string         name;
      unsigned int        n_components = 1;
      bool                integer      = false; // Int32 in the files, else Float64
      bool                constant     = false; // the same in every frame (ids)
      std::vector<double> values;               // integers are exact in a double
    };

    /// A frame's arrays, each list in the order the VTU file gives them.
    struct FieldFrame
    {
      std::vector<FieldArray> field, point, cell;
    };

    /// The cell ids (kind, building, member), constant arrays.
    std::vector<FieldArray> cell_id_arrays(const Cells &cells);

    /// The fibre members' integration points, as cell data: their vertex
    /// cells from `first_cell` on, one per point, in the order of the
    /// members' elements, `numbers` their places along their members.
    struct SectionPointCells
    {
      unsigned int              first_cell = 0;
      std::vector<unsigned int> numbers; // 1-based along its member
      /// "integration_point" of every cell (0 off the points), constant.
      FieldArray number_array(std::size_t n_cells) const;
      /// One array per name of the points' values, `names.size()` per point
      /// from values[first] on (0 off the points).
      void add_arrays(const std::vector<const char *> &names, const std::vector<double> &values,
                      std::size_t first, std::size_t n_cells, FieldFrame &frame) const;
    };

    /// Where the frames of a series go: VTU files and a .pvd index
    /// (make_vtu_writer, vtu_series.cc) or one HDF5 file and its XDMF index
    /// (make_xdmf_writer, xdmf_series.cc). The geometry is given once.
    class FieldWriter
    {
    public:
      virtual ~FieldWriter() = default;
      /// A frame labelled `label` (a time, s, or a mode number).
      virtual void write_frame(double label, const FieldFrame &frame) = 0;
      /// Writes the index (and closes the data file) atomically.
      virtual void finish() = 0;
    };

    using Points3 = std::vector<std::array<double, 3>>;
    /// <directory>/<name>/<name>-NNNNN.vtu and <directory>/<name>.pvd.
    std::unique_ptr<FieldWriter> make_vtu_writer(const std::string &directory,
                                                 const std::string &name, const Points3 &points,
                                                 const Cells &cells);
    /// The rows of a frame this process writes when the ranks of a
    /// partitioned run write one HDF5 file together (MPI-IO, collective):
    /// points[p], cells[c] whether they are its own. Rank 0 writes the
    /// geometry, the constant arrays and the field data.
    struct FieldRanks
    {
      MPI_Comm          communicator;
      std::vector<char> points, cells;
    };

    /// <directory>/<name>.h5 and <directory>/<name>.xdmf; with `ranks`,
    /// written by the ranks together (every call collective).
    std::unique_ptr<FieldWriter> make_xdmf_writer(const std::string &directory,
                                                  const std::string &name, const Points3 &points,
                                                  const Cells &cells,
                                                  const FieldRanks *ranks = nullptr);

    /// The drawing of a 3D model (Model/Dimension = 3; vtu_series_3d.cc).
    class VtuGeometry3D
    {
    public:
      explicit VtuGeometry3D(const Model &model);
      /// How far above its contact point a contact force's arrow point
      /// stands, as a fraction of the model's size: clear of the slabs'
      /// plane, near enough to be read as the same hit.
      static constexpr double contact_arrow_lift = 0.02;
      /// The point and cell arrays of a frame: displacements times `scale`;
      /// the member end forces and the gaps' states when `states` is given
      /// (a time frame).
      FieldFrame frame(const Vector &u, double scale, const ElementFrameStates *states) const;
      const Points3 &point_positions() const { return points; }
      const Cells   &cell_list() const { return cells; }
      /// The largest translation of a point under u.
      double largest_translation(const Vector &u) const;
      /// The model's largest extent along x, y or z, m.
      double size() const { return model_size; }

    private:
      /// A sum of coefficient times model DOF (fixed DOFs contribute 0).
      using Combination = std::vector<std::pair<unsigned int, double>>;
      /// A point's six motions (ux, uy, uz, rx, ry, rz).
      using Motion = std::array<Combination, 6>;
      using Point3 = std::array<double, 3>;

      /// The point at `at` of building b: an existing one there, or a new one.
      unsigned int point_at(unsigned int b, const Point3 &at, const Motion &motion, int node);
      unsigned int new_point(const Point3 &at, const Motion &motion, int node);
      void         add_members();
      void         add_floors();
      void         add_gaps();
      void         add_contact_point(unsigned int g);
      /// Each contact point's arrow point, `lift` above it, and the stem
      /// between them.
      void         add_contact_arrows(double lift);
      double       value(const Combination &c, const Vector &u) const;
      void time_arrays(const Vector &u, const ElementFrameStates &states, FieldFrame &frame) const;
      /// The vertex cells of the fibre members' integration points (after
      /// every other cell), on their member's line; a Gauss-Lobatto end
      /// point is the member's end point.
      void add_section_points();
      /// The local end forces of the members on fibre sections: their
      /// elements' resisting forces (the elastic K u is wrong once one
      /// cracks), into end_forces_start/end.
      void set_fibre_end_forces(const ElementFrameStates &states, FieldArray &start,
                                FieldArray &end) const;
      /// The section arrays of a time frame (cell data, 0 off the points).
      void add_section_arrays(const ElementFrameStates &states, FieldFrame &frame) const;
      /// Where the fibre members' forces begin in `states`, after the
      /// elements' entries and the sections'; Assert the sizes agree.
      std::size_t first_member_force(const ElementFrameStates &states) const;
      /// The contact points' displacements (into d) and forces on the gaps'
      /// first buildings, per point, at the elements' state.
      std::vector<std::array<double, 3>>
      contact_points(const ElementFrameStates &states, double scale,
                     std::vector<std::array<double, 6>> &d) const;

      const Model                     &model;
      std::vector<Point3>              points;
      std::map<std::array<long long, 4>, unsigned int> point_index; // (building, x, y, z in µm)
      std::vector<Motion>              motions;
      std::vector<int>                 point_node; // the model node a point stands for; -1
      Cells                            cells;
      std::vector<int>                 gap_cell;     // per model gap; -1: not drawn
      /// Per model gap: its contact point's point and vertex cell (contact in
      /// plan), -1: none. The point stands at the rest contact point; in a
      /// time frame it moves to the element's contact point.
      std::vector<int>                 gap_point, gap_vertex;
      /// Per model gap: the point above its contact point that carries the
      /// contact force (a Glyph's arrow there lies above the slabs, which
      /// would hide it in their plane) and the stem cell; -1: none.
      std::vector<int>                 gap_arrow, gap_stem;
      std::vector<int>                 master_point; // per model node; -1: none
      /// Per member: the points of its ends.
      std::vector<std::array<long, 2>> member_ends;
      /// The integration points of fibre members: their vertex cells come
      /// last, one per point, in the order of the members' elements.
      SectionPointCells                section_points;
      std::vector<unsigned int>        section_members; // those members, in order
      double                           model_size = 0;
    };
  } // namespace vtu
} // namespace poundfe

#endif
