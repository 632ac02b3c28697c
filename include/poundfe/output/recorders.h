// Recorders: the time-history files a user chooses (recorder_parameters.h
// has the input), as observers of the time loop.
#ifndef poundfe_output_recorders_h
#define poundfe_output_recorders_h

#include <poundfe/output/observer.h>
#include <poundfe/output/recorder_parameters.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  class PeakResponse;

  /// The names of a node's three DOFs: ux, uy, rz (a 2D node; a 3D floor's
  /// diaphragm at its mass centre, or a joint's horizontal part); uz, rx, ry
  /// (a 3D joint's vertical part, a basemat's rocking); hinge_ry, hinge_rz
  /// (a 3D hinge's relative rotations about the member's local axes).
  std::array<const char *, 3> node_components(const Model &model, unsigned int node);
  /// Whether a DOF named so (node_components) is a rotation (rad).
  bool is_rotation(const std::string &component);

  /// "<building>_node<n>_<component>" of each equation (node_components;
  /// the columns of phase_portrait.csv with _m or _rad; the rows of a mode
  /// shape in Python).
  std::vector<std::string> equation_labels(const Model &model);

  /// Steps between rows for an interval in s (0: every step).
  unsigned int steps_per_interval(double interval, double time_step);

  /// A time-series table a recorder writes.
  struct TableShape
  {
    RecordedQuantity quantity;
    std::string      file;      // its table, e.g. "hinges.csv"
    unsigned int     n_columns; // with the time
    unsigned int     every;     // steps between rows
  };

  /// The recorders of a run and the files they write (names in its
  /// directory, each table before its columns file).
  struct Recorders
  {
    std::vector<std::unique_ptr<StepObserver>> observers;
    std::vector<std::string>                   files;
    std::vector<TableShape>                    tables;
  };

  /// For the console, when `table` over a run of `n_steps` steps would
  /// pass 1 GB in `format` (a CSV number takes about 21 bytes: the city
  /// block's hinges.csv; .npy 8): its size and how to record less. Empty
  /// otherwise.
  std::string large_table_note(const TableShape &table, unsigned long n_steps, OutputFormat format);

  class TableWriter;
  class MemoryResults;

  /// Where the recorders of a run partitioned by building send their rows
  /// (observation by rank: report/run_outputs.cc). Every rank's recorders
  /// compute every column; each column is kept from the rank that owns
  /// what it records, and rank 0 writes the files.
  class RowSink
  {
  public:
    virtual ~RowSink() = default;
    /// Whether this rank writes the files (rank 0).
    virtual bool writes_files() const = 0;
    /// What a recorder adds its rows to: they reach `writer` (rank 0's;
    /// nullptr on the others) merged over the ranks. `owners`: of each
    /// column but the time.
    virtual std::unique_ptr<TableWriter> merged(std::unique_ptr<TableWriter> writer,
                                                std::vector<ColumnOwner>     owners) = 0;
  };

  /// The requested recorders plus the defaults, as observers writing into
  /// `directory` in `parameters.format`. They read the floor response of
  /// `peaks`, which must be observed before them. Checks every request
  /// (InputError for an unknown member label) before it prepares the
  /// directory (prepare_output_directory: what an earlier command wrote there
  /// is removed) or makes a file; also removes the recorder files of either
  /// format that an earlier run left without a manifest. With `ranks`
  /// (observation by rank) the rows go through it, and only the rank that
  /// writes the files touches the directory. With `memory` (not with
  /// `ranks`) the tables go there and the directory is not touched.
  Recorders
  make_recorders(const RecorderParameters &parameters, const std::string &input_file,
                 const ResponseView &state, const PeakResponse &peaks, double time_step,
                 const std::string &directory, RowSink *ranks = nullptr,
                 MemoryResults *memory = nullptr);
} // namespace poundfe

#endif
