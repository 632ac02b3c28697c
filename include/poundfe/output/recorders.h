// Recorders: the time-history files a user chooses (recorder_parameters.h
// has the input), as observers of the time loop.
#ifndef poundfe_output_recorders_h
#define poundfe_output_recorders_h

#include <poundfe/output/observer.h>
#include <poundfe/output/recorder_parameters.h>

#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  class PeakResponse;

  /// "<building>_node<n>_<ux|uy|rz>" of each equation (the columns of
  /// phase_portrait.csv; the rows of a mode shape in Python).
  std::vector<std::string> equation_labels(const Model &model);

  /// Steps between rows for an interval in s (0: every step).
  unsigned int steps_per_interval(double interval, double time_step);

  /// The recorders of a run and the files they write (names in its
  /// directory, each table before its columns file).
  struct Recorders
  {
    std::vector<std::unique_ptr<StepObserver>> observers;
    std::vector<std::string>                   files;
  };

  /// The requested recorders plus the defaults, as observers writing into
  /// `directory` in `parameters.format`. They read the floor response of
  /// `peaks`, which must be observed before them. Checks every request
  /// (InputError for an unknown member label) before it prepares the
  /// directory (prepare_output_directory: what an earlier command wrote there
  /// is removed) or makes a file; also removes the recorder files of either
  /// format that an earlier run left without a manifest.
  Recorders
  make_recorders(const RecorderParameters &parameters, const std::string &input_file,
                 const ResponseView &state, const PeakResponse &peaks, double time_step,
                 const std::string &directory);
} // namespace poundfe

#endif
