// libFuzzer target: what the sampling commands (montecarlo, subset,
// fragility, dynamic-form) do with the `Random parameters` section once the
// model is built, and the algebraic limit states of `Reliability`:
//   - RandomParameterParameters::check (variables, correlation, limit states),
//   - attach_random_parameters: every variable's path resolved against the
//     built model (dynamics/model_parameter.h) and its distribution against
//     the value's range,
//   - ResponseLimitStates: every limit state compiled by muParser against
//     the runner's response columns, then evaluated on one row,
//   - one short realization at the variables' median (u = 0): the sampled
//     values written into the working model, its engine rebuilt, 5 steps,
//   - ReliabilityAnalysisParameters::check (random variables, constants and
//     limit states of the Reliability section).
// The models are read and built once (base_model.h), from the repository's
// inputs with a short random loading (read_base_models below): the
// sizes (storeys, steps) are theirs, so no input can make an execution take
// long. An input is
//   byte 0   which base model (its low 7 bits, modulo their number) and
//            whether to run the realization (its high bit: the realization
//            costs 10 times the rest, so only the inputs that ask for it)
//   then up to six lines: Random parameters/Variables, Correlation,
//   Limit states; Reliability/Random variables, Constants, Limit states.
// InputError and NumericalError are the normal refusals; anything else (an
// exception of another type, a crash, a sanitizer report, a hang) is a
// finding. Built and run by tests/fuzz/run.sh.
#include <poundfe/base/exceptions.h>
#include <poundfe/dynamics/realization.h>
#include <poundfe/reliability/random_parameters.h>

#include <deal.II/base/exceptions.h>

#include "base_model.h"
#include "reader_target.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace poundfe;
  using poundfe_fuzz::BaseModel;

  std::vector<std::unique_ptr<const BaseModel>> &
  base_models()
  {
    static std::vector<std::unique_ptr<const BaseModel>> models;
    return models;
  }

  /// The repository's inputs the target varies: shear buildings with
  /// Bouc-Wen storeys and gaps, a 3D pair, a frame with hinges, compliant
  /// foundations, links and bumpers, a Gmsh mesh building, a 3D frame pair;
  /// each with 0.05 s of loading (5 to 10 steps) and its own random
  /// parameters removed.
  void
  read_base_models()
  {
    const std::vector<ParameterOverride> short_loading = {
      {"Ground motion/Stochastic/Duration", "0.05"},
      {"Random parameters/Variables", ""},
      {"Random parameters/Correlation", ""},
      {"Random parameters/Limit states", ""},
      {"Output/Number of modes", "0"}};
    for (const char *file :
         {"tests/dynamics/uncertain-shear-pair.prm", "tests/dynamics/uncertain-3d-pair.prm",
          "input/thesis-shear-building-subset.prm", "input/three-storey-frame-hinges.prm",
          "input/soil-shear-pair.prm", "input/linked-shear-pair.prm", "input/setback-frame.prm",
          "input/3d-torsional-pair.prm"})
      base_models().push_back(poundfe_fuzz::read_base_model(file, short_loading));
  }

  /// The input's lines (at most `n`; missing ones are empty).
  std::vector<std::string>
  input_lines(const std::uint8_t *data, const std::size_t size, const unsigned int n)
  {
    std::vector<std::string> lines(n);
    std::istringstream       in(std::string(reinterpret_cast<const char *>(data), size));
    for (unsigned int i = 0; i < n && std::getline(in, lines[i]); ++i)
      {
      }
    return lines;
  }

  /// The sampling commands' set-up on `base` with the input's Random
  /// parameters, then (`realization`) one realization at u = 0 and the
  /// limit states on it.
  void
  resolve_random_parameters(const BaseModel &base, const std::vector<std::string> &lines,
                            const bool realization)
  {
    const InputParameters    &input = base.input;
    RandomParameterParameters p     = input.random_parameters;
    p.variables_text    = lines[0];
    p.correlation_text  = lines[1];
    p.limit_states_text = lines[2];
    p.check(input);
    RealizationRunner runner(base.analysis, time_history_parameters(input));
    attach_random_parameters(runner, p, input, input.model, input.contact, input.modal.eigensolver);
    const std::unique_ptr<const ResponseLimitStates> limit_states =
      p.has_limit_states() ?
        std::make_unique<const ResponseLimitStates>(p, runner.response_names(), input) :
        nullptr;
    if (!realization)
      return;
    std::vector<double> responses;
    runner.run(std::vector<double>(runner.n_variables(), 0.0), responses);
    if (responses.size() != runner.response_names().size())
      std::abort(); // a row that does not match its columns
    if (limit_states)
      limit_states->system_value(responses, "realization 0");
  }

  /// The Reliability section's check: its random variables, constants and
  /// limit-state expressions compiled by muParser.
  void
  check_reliability(const BaseModel &base, const std::vector<std::string> &lines)
  {
    ReliabilityAnalysisParameters r = base.input.reliability;
    r.random_variables_text         = lines[3];
    r.constants_text                = lines[4];
    r.limit_states_text             = lines[5];
    r.check(base.input);
  }
} // namespace

extern "C" int
LLVMFuzzerInitialize(int *, char ***)
{
  dealii::deal_II_exceptions::disable_abort_on_exception();
  read_base_models();
  return 0;
}

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, const std::size_t size)
{
  if (size == 0)
    return 0;
  const BaseModel &base = *base_models()[(data[0] & 0x7f) % base_models().size()];
  const std::vector<std::string> lines = input_lines(data + 1, size - 1, 6);
  const bool realization = data[0] & 0x80;
  poundfe_fuzz::run_expecting_refusals([&] { resolve_random_parameters(base, lines, realization); });
  poundfe_fuzz::run_expecting_refusals([&] { check_reliability(base, lines); });
  return 0;
}
