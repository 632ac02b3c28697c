// The engines' parameter parts of a whole input: each engine takes only
// the sections it reads (deal.II step-33 style), and the commands (and
// tests) take them from the InputParameters they read here.
#ifndef poundfe_input_engine_parameters_h
#define poundfe_input_engine_parameters_h

#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/report/run_parameters.h>

#include <mpi.h>

namespace poundfe
{
  /// The analysis of the input's model (Model, Contact, Springs, Friction,
  /// Modal analysis, Output/Number of modes), its warnings said once per
  /// process on stderr ("poundfe: warning: ...") where writes_outputs().
  Analysis prepare_analysis(const InputParameters &input);

  /// The analysis of a Contact/Model = nonsmooth input that is the rigid
  /// limit of a sweep of the penalty law's stiffness (`poundfe sweep`,
  /// Parameter = Contact/Stiffness): as prepare_analysis(), but the law's
  /// entries are not warned about as unused, since the sweep's penalty
  /// runs use them (and say the builder's own warnings on them).
  Analysis prepare_rigid_limit_analysis(const InputParameters &input);

  /// This rank's part of the input's model partitioned by building over
  /// `communicator` (dynamics/partitioned_history.h: prepare_rank_analysis),
  /// with Output/Number of modes modes of each of its buildings (none of
  /// the whole model), its buildings' warnings said as above. Collective.
  Analysis prepare_rank_analysis(const InputParameters &input, MPI_Comm communicator);

  /// What a time history of the input reads: the file, Time integration,
  /// Ground motion, Nodal forces.
  TimeHistoryParameters time_history_parameters(const InputParameters &input);

  /// What a run with the standard outputs reads: the time history's parts,
  /// Output, Spectrum, Drift limits, Contact.
  RunParameters run_parameters(const InputParameters &input);

  /// The excitation of the input's ground motion and nodal forces.
  Excitation make_excitation(const Analysis &analysis, const InputParameters &input);

  /// Every input file the input names (records, force tables, meshes,
  /// catalogues, hazard and fragility files), as each section lists them
  /// (`input_files()` beside its declarations), resolved against the
  /// parameter file's directory. What a resumed table is tied to besides
  /// the entries (output_directory.h: expect_output_directory).
  std::vector<NamedInputFile> named_input_files(const InputParameters &input);
} // namespace poundfe

#endif
