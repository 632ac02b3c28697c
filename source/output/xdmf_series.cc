// The field output of large models: one HDF5 file and an XDMF 3 index
// (Output/Field format = xdmf). The XDMF file (XDMF Model and Format,
// xdmf.org, version 3) is light XML that describes the heavy data of the
// HDF5 file (The HDF Group, HDF5 Reference Manual, C API): a temporal
// collection (Grid GridType="Collection" CollectionType="Temporal") of one
// uniform grid per frame, each with its Time, the points (GeometryType XYZ)
// and the cells (TopologyType Mixed: per cell its XDMF type, Polyvertex 1,
// Polyline 2 or Polygon 3, then its number of points and their indices),
// and one Attribute per array (Center Node, Cell or Grid) pointing into the
// HDF5 file as "<name>.h5:/path".
//   <name>.h5: /mesh/points (points x 3, float64), /mesh/topology (the
//   Mixed list, int64), /mesh/connectivity, /mesh/offsets, /mesh/types (the
//   VTU file's cell arrays, int64, int64, int32), the constant arrays
//   (kind, building, member, node: int32) once under /mesh, and a group
//   /frames/NNNNN per frame with its field, point and cell arrays under the
//   VTU files' names (float64, contact int32), points or cells first, the
//   components second. An array of 1024 values or more is one chunk,
//   byte-shuffled and deflated (zlib level 1, as the VTU arrays); smaller
//   ones are contiguous (a chunk's index would cost more than it saves).
//   Measured: input/city-block.prm, 11 frames, 37 MB against 106 MB
//   uncompressed and 69 MB of VTU files. The file is in the HDF5 1.8 format.
// Both files are written under "<file>.tmp" and renamed when the series
// finishes (the HDF5 file first, so that the index never names a missing
// file); every frame write is a safe point of the interruption, as an
// AtomicFile write is. One process writes, or (FieldRanks, a partitioned
// run) the ranks write one file together through MPI-IO (HDF5's parallel
// driver, H5Pset_fapl_mpio): every call is collective, each rank selects
// its own rows of each point and cell array (a union of hyperslabs, the
// same selection in memory and in the file) and rank 0 the rest; the
// deflated arrays need collective transfers (HDF5 >= 1.10.2). Every HDF5
// call's status is agreed by the ranks (one MPI_Allreduce), so a failure
// on one rank stops all of them at the same call, never one rank waiting
// in a collective call that another has left. The interruption is then
// the run's agreed stop, not this writer's (one rank's signal would leave
// the others in a collective call).
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/number_text.h>
#include <poundfe/output/output_directory.h>

#include "vtu_arrays.h"

#include <hdf5.h>
#include <sys/mman.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace poundfe
{
  namespace vtu
  {
    namespace
    {
      /// The XDMF cell type of a VTK cell type (XDMF3, "Mixed" topology).
      int
      xdmf_cell_type(const int vtk_type)
      {
        switch (vtk_type)
          {
            case vtk_vertex:
              return 1; // Polyvertex
            case vtk_line:
            case vtk_poly_line:
              return 2; // Polyline
            case vtk_polygon:
              return 3; // Polygon
            default:
              Assert(false, dealii::ExcMessage("a cell type XDMF output does not know"));
              return 0;
          }
      }

      /// An array written to the HDF5 file, as the index names it.
      struct StoredArray
      {
        std::string  name, path;
        const char  *center; // Node, Cell or Grid
        std::size_t  n_rows;
        unsigned int n_components;
        bool         integer;
      };

      /// Whose rows an array's are under MPI: rank 0's (the geometry, the
      /// constant and field arrays) or each rank's own points or cells.
      enum class Rows
      {
        root,
        points,
        cells
      };

      class XdmfWriter : public FieldWriter
      {
      public:
        XdmfWriter(const std::string &directory, const std::string &name, const Points3 &points,
                   const Cells &cells, const FieldRanks *ranks);
        ~XdmfWriter() override;
        void write_frame(double label, const FieldFrame &frame) override;
        void finish() override;

      private:
        /// The id, or on failure (a negative id) closes and removes the file
        /// and throws OutputError with errno (EIO when the library set none).
        /// Under MPI the ranks agree: a failure on any rank is every rank's.
        hid_t checked(hid_t id);
        /// Throws, after the ranks agreed, when `failure` (an errno, 0: none)
        /// is not 0 on some rank, as checked() does.
        void agree(int failure);
        /// The space of an array (memory and file: the buffer is the whole
        /// array) with this rank's `rows` selected; H5S_ALL for one process.
        hid_t selected(hid_t space, Rows rows, hsize_t width) const;
        /// Dataset creation properties: one chunk of the whole array, the
        /// bytes shuffled and deflated (zlib level 1, as the VTU files).
        hid_t compressed_layout(const hsize_t *dimensions, int n_dimensions);
        /// Smaller arrays are stored contiguous, uncompressed (in the 3D test,
        /// cli/xdmf, the end forces are compressed, the rest is not).
        static constexpr hsize_t min_compressed_values = 1024;
        /// Under MPI: rows of a chunk (each rank's points and cells are
        /// contiguous per building, so most chunks are one rank's). Measured
        /// on the city block, 51 frames on 2 ranks (doc/benchmarks.md, stop
        /// 36): whole arrays as one chunk 12.9-13.0 s and 155 MB (one rank
        /// deflates each array); 2^16 rows 12.0-12.7 s, 160 MB; 2^14 rows
        /// 11.6-11.8 s but 193 MB (shorter shuffled chunks deflate worse).
        static constexpr hsize_t rows_per_chunk = hsize_t(1) << 16;
        void  write_mesh(const Points3 &points, const Cells &cells);
        void  write(hid_t group, const std::string &name, const std::vector<double> &values,
                    unsigned int n_components, bool integer, Rows rows);
        void  write(hid_t group, const std::string &name, const std::vector<long long> &values);
        StoredArray store(hid_t group, const std::string &group_path, const char *center,
                          const FieldArray &array);
        std::string index() const;
        std::string data_item(std::size_t n_rows, unsigned int n_components, bool integer,
                              unsigned int precision, const std::string &path) const;
        void        close_file();
        /// One process, after a failure: the file's descriptor is pointed at
        /// an anonymous file in memory (memfd), so that closing it, which
        /// flushes HDF5's cached metadata and cannot be told not to,
        /// succeeds. On a full disk the close otherwise fails, and leaves the
        /// library a half-destroyed file that its exit handler touches again
        /// (SIGSEGV after the run had ended); the file on disk is removed.
        void        redirect_to_memory() const;

        const std::string h5_path, temporary_path, xdmf_path, h5_name, series_name;
        hid_t             file = -1;
        int               failed_with = 0;
        bool              renamed     = false; // the HDF5 file is in place
        std::size_t       n_points, n_cells, topology_size = 0;
        /// Under MPI: the communicator, this rank, the collective transfer
        /// and its own points and cells as runs (first row, number of rows).
        std::optional<MPI_Comm> communicator;
        int                     rank     = 0;
        hid_t                   transfer = H5P_DEFAULT;
        std::vector<std::pair<hsize_t, hsize_t>> point_runs, cell_runs;
        /// Per frame: its label and arrays; the constant arrays, written once.
        std::vector<std::pair<double, std::vector<StoredArray>>> frames;
        std::vector<StoredArray>                                 constant;
      };

      /// The runs of consecutive true entries of `own`: (first, length).
      std::vector<std::pair<hsize_t, hsize_t>>
      runs_of(const std::vector<char> &own)
      {
        std::vector<std::pair<hsize_t, hsize_t>> runs;
        for (hsize_t i = 0; i < own.size(); ++i)
          if (own[i])
            {
              if (!runs.empty() && runs.back().first + runs.back().second == i)
                ++runs.back().second;
              else
                runs.emplace_back(i, 1);
            }
        return runs;
      }

      XdmfWriter::XdmfWriter(const std::string &directory, const std::string &name,
                             const Points3 &points, const Cells &cells, const FieldRanks *ranks)
        : h5_path(directory + "/" + name + ".h5")
        , temporary_path(h5_path + ".tmp")
        , xdmf_path(directory + "/" + name + ".xdmf")
        , h5_name(name + ".h5")
        , series_name(name)
        , n_points(points.size())
        , n_cells(cells.types.size())
      {
        if (ranks)
          {
            AssertDimension(ranks->points.size(), n_points);
            AssertDimension(ranks->cells.size(), n_cells);
            communicator = ranks->communicator;
            MPI_Comm_rank(ranks->communicator, &rank);
            point_runs = runs_of(ranks->points);
            cell_runs  = runs_of(ranks->cells);
          }
        else
          throw_if_interrupted(); // a safe point: nothing of this file exists yet
        register_output(h5_path); // listed before it exists (output_directory.h)
        // before the library starts (its first call): a file whose close
        // fails even so is never closed again by HDF5's exit handler, which
        // would touch what the failed close freed
        static const bool no_exit_handler = H5dont_atexit() >= 0;
        (void)no_exit_handler;
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); // failures become OutputError
        errno = 0;
        // the HDF5 1.8 file format (readable by every HDF5 since 2008): groups
        // of a few arrays stored compactly in their object header
        const hid_t access = checked(H5Pcreate(H5P_FILE_ACCESS));
        checked(H5Pset_libver_bounds(access, H5F_LIBVER_V18, H5F_LIBVER_V18));
        // closing the file closes the groups and datasets a failure left open
        // (else H5Fclose refuses, the file stays open to MPI_Finalize, and a
        // full disk keeps the space of the removed temporary)
        checked(H5Pset_fclose_degree(access, H5F_CLOSE_STRONG));
        if (communicator)
          {
            checked(H5Pset_fapl_mpio(access, *communicator, MPI_INFO_NULL));
            transfer = checked(H5Pcreate(H5P_DATASET_XFER));
            checked(H5Pset_dxpl_mpio(transfer, H5FD_MPIO_COLLECTIVE));
          }
        file = H5Fcreate(temporary_path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access);
        H5Pclose(access);
        checked(file);
        write_mesh(points, cells);
        checked(H5Gclose(checked(H5Gcreate2(file, "/frames", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT))));
      }

      XdmfWriter::~XdmfWriter()
      {
        // Under MPI closing is collective: a writer unwound by an exception
        // of one rank only leaves its file open (failures agreed by the
        // ranks closed it already, and the run finishes it on every rank).
        if (!communicator)
          close_file();
        if (transfer != H5P_DEFAULT)
          H5Pclose(transfer);
        if (!renamed && rank == 0) // not finished: an error or an interruption unwinds
          std::remove(temporary_path.c_str());
      }

      /// Why an HDF5 call failed: errno (one process), else (MPI-IO makes
      /// calls of its own, and its errno is whatever its last one left: an
      /// output directory's solution.h5.tmp that is a directory was reported
      /// "Bad file descriptor") ENOSPC if the file system of `path` has less
      /// than a megabyte left, and EIO otherwise.
      int
      reason_of_failure(const std::string &path, const bool errno_is_the_call_s)
      {
        if (errno_is_the_call_s && errno != 0)
          return errno;
        struct statvfs space;
        const std::string directory = path.substr(0, path.find_last_of('/') + 1);
        if (statvfs(directory.empty() ? "." : directory.c_str(), &space) == 0 &&
            double(space.f_bavail) * double(space.f_frsize) < double(1 << 20))
          return ENOSPC;
        return EIO;
      }

      hid_t
      XdmfWriter::checked(const hid_t id)
      {
        agree(id >= 0 ? 0 : reason_of_failure(h5_path, !communicator));
        return id;
      }

      void
      XdmfWriter::agree(int failure)
      {
        if (communicator) // the first errno of the ranks that failed
          MPI_Allreduce(MPI_IN_PLACE, &failure, 1, MPI_INT, MPI_MAX, *communicator);
        if (failure == 0)
          {
            errno = 0; // the next call's failure is its own
            return;
          }
        failed_with = failure;
        if (!communicator)
          redirect_to_memory();
        close_file(); // every rank, when under MPI
        if (rank == 0)
          std::remove(temporary_path.c_str());
        throw OutputError("write", h5_path, failed_with);
      }

      hid_t
      XdmfWriter::selected(const hid_t space, const Rows rows, const hsize_t width) const
      {
        if (!communicator)
          return H5S_ALL;
        const hid_t selection = H5Scopy(space);
        if (selection < 0)
          return selection;
        if (rows == Rows::root)
          {
            if (rank != 0)
              H5Sselect_none(selection);
            return selection;
          }
        H5Sselect_none(selection);
        for (const auto &[first, length] : rows == Rows::points ? point_runs : cell_runs)
          {
            const hsize_t start[2] = {first, 0}, count[2] = {length, width};
            if (H5Sselect_hyperslab(selection, H5S_SELECT_OR, start, nullptr, count, nullptr) < 0)
              {
                H5Sclose(selection);
                return -1;
              }
          }
        return selection;
      }

      void
      XdmfWriter::redirect_to_memory() const
      {
        void *handle = nullptr; // the sec2 driver's: its file descriptor
        if (file < 0 || H5Fget_vfd_handle(file, H5P_DEFAULT, &handle) < 0 || handle == nullptr)
          return;
        const int memory = ::memfd_create("poundfe-given-up", 0);
        if (memory >= 0)
          {
            ::dup2(memory, *static_cast<const int *>(handle)); // closes the file on disk
            ::close(memory);
          }
      }

      void
      XdmfWriter::close_file()
      {
        if (file >= 0)
          {
            const hid_t closing = file;
            file                = -1;
            H5Fclose(closing);
          }
      }

      hid_t
      XdmfWriter::compressed_layout(const hsize_t *dimensions, const int n_dimensions)
      {
        const hid_t layout = checked(H5Pcreate(H5P_DATASET_CREATE));
        if (communicator) // every value is written: no fill pass over the file first
          checked(H5Pset_fill_time(layout, H5D_FILL_TIME_NEVER));
        const hsize_t n_values = dimensions[0] * (n_dimensions == 2 ? dimensions[1] : 1);
        if (n_values < min_compressed_values) // a chunk's index costs more than it saves
          return layout;
        // a chunk is at most 4 GiB: 2^28 values (2 GiB of doubles) at most;
        // under MPI a chunk is deflated by one rank, which gathers it from
        // the others: chunks of rows_per_chunk let each rank deflate its own
        const hsize_t width    = n_dimensions == 2 ? dimensions[1] : 1;
        const hsize_t most     = communicator ? rows_per_chunk : (hsize_t(1) << 28) / width;
        const hsize_t chunk[2] = {std::min<hsize_t>(dimensions[0], most), width};
        checked(H5Pset_chunk(layout, n_dimensions, chunk));
        checked(H5Pset_shuffle(layout));
        checked(H5Pset_deflate(layout, 1));
        return layout;
      }

      void
      XdmfWriter::write(const hid_t group, const std::string &name,
                        const std::vector<double> &values, const unsigned int n_components,
                        const bool integer, const Rows rows)
      {
        const hsize_t dimensions[2] = {values.size() / n_components, n_components};
        const hid_t   space = checked(H5Screate_simple(n_components == 1 ? 1 : 2, dimensions, nullptr));
        const hid_t   layout = compressed_layout(dimensions, n_components == 1 ? 1 : 2);
        const hid_t   set    = checked(H5Dcreate2(group, name.c_str(),
                                                 integer ? H5T_STD_I32LE : H5T_IEEE_F64LE, space,
                                                 H5P_DEFAULT, layout, H5P_DEFAULT));
        H5Pclose(layout);
        const hid_t mine = checked(selected(space, rows, n_components));
        herr_t      status;
        if (integer) // another rank's rows may be NaN here: not converted
          {
            std::vector<std::int32_t> whole(values.size());
            std::transform(values.begin(), values.end(), whole.begin(), [](const double x) {
              return std::isfinite(x) ? static_cast<std::int32_t>(x) : 0;
            });
            status = H5Dwrite(set, H5T_NATIVE_INT32, mine, mine, transfer, whole.data());
          }
        else
          status = H5Dwrite(set, H5T_NATIVE_DOUBLE, mine, mine, transfer, values.data());
        if (mine != H5S_ALL)
          H5Sclose(mine);
        status = std::min(status, H5Dclose(set)); // a small array is written when closed
        H5Sclose(space);
        checked(status);
      }

      void
      XdmfWriter::write(const hid_t group, const std::string &name,
                        const std::vector<long long> &values)
      {
        const hsize_t dimensions[1] = {values.size()};
        const hid_t   space         = checked(H5Screate_simple(1, dimensions, nullptr));
        const hid_t   layout = compressed_layout(dimensions, 1);
        const hid_t   set = checked(H5Dcreate2(group, name.c_str(), H5T_STD_I64LE, space,
                                               H5P_DEFAULT, layout, H5P_DEFAULT));
        H5Pclose(layout);
        const hid_t  mine   = checked(selected(space, Rows::root, 1));
        herr_t status = H5Dwrite(set, H5T_NATIVE_LLONG, mine, mine, transfer, values.data());
        if (mine != H5S_ALL)
          H5Sclose(mine);
        status = std::min(status, H5Dclose(set));
        H5Sclose(space);
        checked(status);
      }

      void
      XdmfWriter::write_mesh(const Points3 &points, const Cells &cells)
      {
        const hid_t mesh = checked(H5Gcreate2(file, "/mesh", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
        std::vector<double> xyz;
        xyz.reserve(3 * points.size());
        for (const auto &p : points)
          xyz.insert(xyz.end(), p.begin(), p.end());
        write(mesh, "points", xyz, 3, false, Rows::root);
        std::vector<long long> topology;
        topology.reserve(cells.connectivity.size() + 2 * n_cells);
        for (std::size_t c = 0; c < n_cells; ++c)
          {
            const long first = c == 0 ? 0 : cells.offsets[c - 1];
            topology.push_back(xdmf_cell_type(cells.types[c]));
            topology.push_back(cells.offsets[c] - first);
            topology.insert(topology.end(), cells.connectivity.begin() + first,
                            cells.connectivity.begin() + cells.offsets[c]);
          }
        topology_size = topology.size();
        write(mesh, "topology", topology);
        write(mesh, "connectivity", {cells.connectivity.begin(), cells.connectivity.end()});
        write(mesh, "offsets", {cells.offsets.begin(), cells.offsets.end()});
        write(mesh, "types", std::vector<double>(cells.types.begin(), cells.types.end()), 1, true,
              Rows::root);
        checked(H5Gclose(mesh));
      }

      StoredArray
      XdmfWriter::store(const hid_t group, const std::string &group_path, const char *center,
                        const FieldArray &array)
      {
        const Rows rows = array.constant || center[0] == 'G' ? Rows::root :
                          center[0] == 'N'                    ? Rows::points :
                                                                 Rows::cells;
        write(group, array.name, array.values, array.n_components, array.integer, rows);
        return {array.name, group_path + "/" + array.name, center,
                array.values.size() / array.n_components, array.n_components, array.integer};
      }

      void
      XdmfWriter::write_frame(const double label, const FieldFrame &frame)
      {
        if (failed_with != 0) // the first failure again, already reported by its caller
          throw OutputError("write", h5_path, failed_with);
        if (!communicator)
          throw_if_interrupted(); // the destructor removes the temporary
        char group_path[32];
        std::snprintf(group_path, sizeof group_path, "/frames/%05u",
                      static_cast<unsigned int>(frames.size()));
        errno = 0;
        const hid_t group = checked(H5Gcreate2(file, group_path, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
        std::vector<StoredArray> stored;
        for (const auto &[center, arrays] :
             {std::pair{"Grid", &frame.field}, {"Node", &frame.point}, {"Cell", &frame.cell}})
          for (const FieldArray &array : *arrays)
            {
              if (!array.constant)
                {
                  stored.push_back(store(group, group_path, center, array));
                  continue;
                }
              bool known = false;
              for (const StoredArray &c : constant)
                known = known || c.name == array.name;
              if (!known)
                {
                  const hid_t mesh = checked(H5Gopen2(file, "/mesh", H5P_DEFAULT));
                  constant.push_back(store(mesh, "/mesh", center, array));
                  checked(H5Gclose(mesh));
                }
              for (const StoredArray &c : constant)
                if (c.name == array.name)
                  stored.push_back(c);
            }
        checked(H5Gclose(group));
        frames.emplace_back(label, std::move(stored));
      }

      std::string
      XdmfWriter::data_item(const std::size_t n_rows, const unsigned int n_components,
                            const bool integer, const unsigned int precision,
                            const std::string &path) const
      {
        const std::string dimensions =
          std::to_string(n_rows) + (n_components == 1 ? "" : " " + std::to_string(n_components));
        return "<DataItem Dimensions=\"" + dimensions + "\" NumberType=\"" +
               (integer ? "Int" : "Float") + "\" Precision=\"" + std::to_string(precision) +
               "\" Format=\"HDF\">" + h5_name + ":" + path + "</DataItem>";
      }

      std::string
      XdmfWriter::index() const
      {
        std::string xml = "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n<Domain>\n"
                          "<Grid Name=\"" + series_name +
                          "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
        const std::string geometry =
          "<Geometry GeometryType=\"XYZ\">" + data_item(n_points, 3, false, 8, "/mesh/points") +
          "</Geometry>\n<Topology TopologyType=\"Mixed\" NumberOfElements=\"" +
          std::to_string(n_cells) + "\">" + data_item(topology_size, 1, true, 8, "/mesh/topology") +
          "</Topology>\n";
        NumberText text;
        for (std::size_t f = 0; f < frames.size(); ++f)
          {
            char buffer[NumberText::max_length];
            char name[64];
            std::snprintf(name, sizeof name, "%s-%05u", series_name.c_str(),
                          static_cast<unsigned int>(f));
            xml += "<Grid Name=\"" + std::string(name) + "\" GridType=\"Uniform\">\n<Time Value=\"" +
                   std::string(buffer, text.write(buffer, frames[f].first)) + "\"/>\n" + geometry;
            for (const StoredArray &a : frames[f].second)
              xml += "<Attribute Name=\"" + a.name + "\" AttributeType=\"" +
                     (a.n_components == 1 ? "Scalar" : a.n_components == 3 ? "Vector" : "Matrix") +
                     "\" Center=\"" + a.center + "\">" +
                     data_item(a.n_rows, a.n_components, a.integer, a.integer ? 4 : 8, a.path) +
                     "</Attribute>\n";
            xml += "</Grid>\n";
          }
        return xml + "</Grid>\n</Domain>\n</Xdmf>\n";
      }

      void
      XdmfWriter::finish()
      {
        if (failed_with != 0)
          throw OutputError("write", h5_path, failed_with);
        errno = 0;
        if (!communicator) // a full disk fails here, where the file can still be given up
          checked(H5Fflush(file, H5F_SCOPE_LOCAL));
        const hid_t closing = file;
        file                = -1;
        agree(H5Fclose(closing) < 0 ? reason_of_failure(h5_path, !communicator) : 0); // collective under MPI
        if (rank != 0) // rank 0 alone renames and indexes
          {
            renamed = true;
            return;
          }
        throw_if_interrupted(); // before the rename: an interrupted file never appears
        if (std::rename(temporary_path.c_str(), h5_path.c_str()) != 0)
          {
            failed_with = errno;
            throw OutputError("write", h5_path, failed_with);
          }
        renamed = true;
        write_file_atomically(xdmf_path, index());
      }
    } // namespace

    std::unique_ptr<FieldWriter>
    make_xdmf_writer(const std::string &directory, const std::string &name, const Points3 &points,
                     const Cells &cells, const FieldRanks *ranks)
    {
      return std::make_unique<XdmfWriter>(directory, name, points, cells, ranks);
    }
  } // namespace vtu
} // namespace poundfe
