// The engines' parameter parts of a whole input: each engine takes only
// the sections it reads (deal.II step-33 style), and the commands (and
// tests) take them from the InputParameters they read here.
#ifndef poundfe_input_engine_parameters_h
#define poundfe_input_engine_parameters_h

#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/run.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/report/run_parameters.h>

namespace poundfe
{
  // Analysis prepare_analysis(const InputParameters &input): declared in
  // dynamics/analysis.h while Analysis holds the whole input (TRANSITIONAL).

  /// What a time history of the input reads: the file, Time integration,
  /// Ground motion, Nodal forces.
  TimeHistoryParameters time_history_parameters(const InputParameters &input);

  /// What a run with the standard outputs reads: the time history's parts,
  /// Output, Spectrum, Drift limits, Contact.
  RunParameters run_parameters(const InputParameters &input);

  /// The excitation of the input's ground motion and nodal forces.
  Excitation make_excitation(const Analysis &analysis, const InputParameters &input);

  // TRANSITIONAL (issue 27), defined in source/input/engine_parameters.cc
  // from Analysis::input for the engines and tests that still pass the
  // analysis alone: TimeHistory(const Analysis &), RealizationRunner(const
  // Analysis &) and make_excitation(const Analysis &), declared beside the
  // engines (dynamics/run.h, dynamics/realization.h).
} // namespace poundfe

#endif
