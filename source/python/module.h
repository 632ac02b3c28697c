// What the two translation units of poundfe._core share (module.cc: errors,
// Input, modal; time_history_binding.cc: time history, commands).
#ifndef poundfe_python_module_h
#define poundfe_python_module_h

#include <pybind11/pybind11.h>

#include <memory>

namespace poundfe
{
  struct Analysis;
  struct InputParameters;
} // namespace poundfe

namespace poundfe::python
{
  /// prepare_analysis with the GIL released.
  std::shared_ptr<const Analysis> prepare(const InputParameters &input);

  /// The whole model's modes and each building's (frequencies, periods,
  /// participating mass ratios, mass-normalised shapes, Rayleigh
  /// coefficients) and the equations' labels (the shapes' rows).
  pybind11::dict modes_of(const Analysis &analysis);

  /// run_time_history and command (run.cc).
  void bind_run(pybind11::module_ &m);
} // namespace poundfe::python

#endif
