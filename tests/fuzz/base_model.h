// A model the fuzz targets that need one read and build once, in
// LLVMFuzzerInitialize: reading a parameter file declares the whole
// parameter tree (about 7 ms), which would otherwise set the pace. The file
// is one of the repository's inputs (POUNDFE_SOURCE_DIR, set by run.sh),
// read with overrides (e.g. a short loading); an error in it means the
// target itself is broken, so the process stops.
#ifndef POUNDFE_TESTS_FUZZ_BASE_MODEL_H
#define POUNDFE_TESTS_FUZZ_BASE_MODEL_H

#include <poundfe/dynamics/analysis.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <string>
#include <vector>

namespace poundfe_fuzz
{
  struct BaseModel
  {
    poundfe::InputParameters input;
    poundfe::Analysis        analysis;
  };

  /// `file` (relative to the source tree) read with `overrides`; its model
  /// built when `build` (else `analysis` is empty).
  inline std::unique_ptr<const BaseModel>
  read_base_model(const std::string &file, const std::vector<poundfe::ParameterOverride> &overrides,
                  const bool build = true)
  {
    try
      {
        poundfe::InputParameters input =
          poundfe::read_parameters(std::string(POUNDFE_SOURCE_DIR) + "/" + file, overrides);
        poundfe::Analysis analysis = build ? poundfe::prepare_analysis(input) : poundfe::Analysis{};
        return std::make_unique<const BaseModel>(BaseModel{std::move(input), std::move(analysis)});
      }
    catch (const std::exception &e)
      {
        std::fprintf(stderr, "base model %s: %s\n", file.c_str(), e.what());
        std::abort();
      }
  }
} // namespace poundfe_fuzz

#endif
