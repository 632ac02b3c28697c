// What the translation units of poundfe._core share (module.cc: errors,
// Input, modal; time_history_binding.cc: time history, commands;
// opensees_binding.cc: the OpenSees commands of poundfe.opensees).
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

  /// An exception type `name` of the module m (poundfe.NAME), derived
  /// from `base`; the module keeps it alive.
  pybind11::handle exception_type(pybind11::module_ &m, const char *name, PyObject *base,
                                  const char *doc);

  /// run_time_history and command (time_history_binding.cc).
  void bind_run(pybind11::module_ &m);

  /// opensees_call, opensees_commands, opensees_finish (opensees_binding.cc).
  void bind_opensees(pybind11::module_ &m);
} // namespace poundfe::python

#endif
