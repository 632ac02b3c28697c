// What the translation units of poundfe._core share (module.cc: errors,
// Input, modal; time_history_binding.cc: time history, commands), and
// exception_type, which the lean extension poundfe._opensees
// (opensees_binding.cc: the OpenSees commands of poundfe.opensees) uses too.
// Nothing here names deal.II.
#ifndef poundfe_python_module_h
#define poundfe_python_module_h

#include <pybind11/pybind11.h>

#include <memory>
#include <string>

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

  /// An exception type `name` of the module m, derived from `base`, named
  /// `python_module`.NAME, the module where Python finds it again (pickle
  /// looks the type up by that name); the module m keeps it alive (a
  /// handle: nothing is released after Python has finalised).
  inline pybind11::handle
  exception_type(pybind11::module_ &m,
                 const char        *name,
                 PyObject          *base,
                 const char        *doc,
                 const char        *python_module = "poundfe")
  {
    const std::string qualified = std::string(python_module) + "." + name;
    pybind11::object  type      = pybind11::reinterpret_steal<pybind11::object>(
      PyErr_NewExceptionWithDoc(qualified.c_str(), doc, base, nullptr));
    if (!type)
      throw pybind11::error_already_set();
    m.attr(name) = type;
    return type.release();
  }

  /// run_time_history and command (time_history_binding.cc).
  void bind_run(pybind11::module_ &m);
} // namespace poundfe::python

#endif
