#include <poundfe/input/engine_parameters.h>
#include <poundfe/dynamics/realization.h>

#include <iostream>
#include <set>

namespace poundfe
{
  Analysis
  prepare_analysis(const InputParameters &input)
  {
    Analysis analysis = prepare_analysis(input, input.model, input.contact, input.springs,
                                         input.friction, input.modal, input.output.n_modes);
    analysis.input = input; // TRANSITIONAL (issue 27): see Analysis::input
    // once per process: a sweep prepares an analysis per value
    static std::set<std::string> said;
    if (writes_outputs())
      for (const std::string &warning : analysis.warnings)
        if (said.insert(warning).second)
          std::cerr << "poundfe: warning: " << warning << "\n";
    return analysis;
  }

  TimeHistoryParameters
  time_history_parameters(const InputParameters &input)
  {
    return {input, input.time_integration, input.ground_motion, input.nodal_forces};
  }

  RunParameters
  run_parameters(const InputParameters &input)
  {
    return {time_history_parameters(input), input.output, input.spectrum, input.drift_limits,
            input.contact};
  }

  Excitation
  make_excitation(const Analysis &analysis, const InputParameters &input)
  {
    return make_excitation(analysis, time_history_parameters(input));
  }

  // TRANSITIONAL (issue 27): the engines and tests that still pass the
  // analysis alone read the whole input it carries. These go with
  // Analysis::input.
  Excitation
  make_excitation(const Analysis &analysis)
  {
    return make_excitation(analysis, time_history_parameters(analysis.input));
  }

  TimeHistory::TimeHistory(const Analysis &analysis)
    : TimeHistory(analysis, time_history_parameters(analysis.input))
  {}

  RealizationRunner::RealizationRunner(const Analysis &analysis)
    : RealizationRunner(analysis, time_history_parameters(analysis.input))
  {}
} // namespace poundfe
