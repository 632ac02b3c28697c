// The compiled part of the Python module `poundfe` (poundfe._core): the
// errors as Python exceptions, the parameter file as an `Input` object and
// the modes of a prepared analysis (a run's Results.modes). The time history and the commands are in time_history_binding.cc; the
// Pythonic layer (results as numpy arrays, the model builder) is in
// source/python/poundfe/*.py. The OpenSees commands of poundfe.opensees are
// the lean extension poundfe._opensees (opensees_binding.cc), without deal.II.
//
// Every entry point reads its input through the command line's reader
// (read_parameters, with overrides): a Python user gets the same checks and
// the same messages. The GIL is released while poundfe computes.
#include "module.h"

#include <poundfe/input/engine_parameters.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/input/parameter_text.h>
#include <poundfe/output/recorders.h>
#include <poundfe/sections/section_parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/multithread_info.h>

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <sstream>

namespace py = pybind11;

namespace poundfe::python
{
  namespace
  {
    /// The exception types, made once at import (the module keeps them
    /// alive: handles, so nothing is released after Python has finalised).
    py::handle input_error_type, numerical_error_type, output_error_type;

    /// poundfe's errors as Python exceptions with the same message (the
    /// command line prints "poundfe: error: " before it). InputError also
    /// carries file, line, parameter and problem as attributes.
    void
    translate_exception(std::exception_ptr error)
    {
      try
        {
          if (error)
            std::rethrow_exception(error);
        }
      catch (const InputError &e)
        {
          py::object exception   = input_error_type(e.what());
          exception.attr("file")      = e.file();
          exception.attr("line")      = e.line();
          exception.attr("parameter") = e.parameter();
          exception.attr("problem")   = e.problem();
          PyErr_SetObject(input_error_type.ptr(), exception.ptr());
        }
      catch (const NumericalError &e)
        {
          PyErr_SetString(numerical_error_type.ptr(), e.what());
        }
      catch (const OutputError &e)
        {
          PyErr_SetString(output_error_type.ptr(), e.what());
        }
      catch (const Interrupted &e)
        {
          PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
        }
    }
  } // namespace

  namespace
  {
    std::vector<ParameterOverride>
    overrides_of(const std::vector<std::pair<std::string, std::string>> &pairs)
    {
      std::vector<ParameterOverride> overrides;
      for (const auto &[path, value] : pairs)
        overrides.push_back({path, value});
      return overrides;
    }

    /// Frequencies, periods, participating mass ratios and shapes.
    py::dict
    modes_dict(const Modes &modes)
    {
      std::vector<double> frequency, period;
      for (unsigned int i = 0; i < modes.n_modes(); ++i)
        frequency.push_back(modes.frequency(i)), period.push_back(modes.period(i));
      py::dict d;
      d["omega_rad_s"]                = modes.omega;
      d["frequencies_hz"]             = frequency;
      d["periods_s"]                  = period;
      d["participating_mass_ratio_x"] = modes.participating_mass_ratio;
      if (!modes.participating_mass_ratio_y.empty()) // a 3D model: along y and about z too
        {
          d["participating_mass_ratio_y"]  = modes.participating_mass_ratio_y;
          d["participating_mass_ratio_rz"] = modes.participating_mass_ratio_rz;
        }
      d["shapes"]                     = modes.shapes; // one mode per column, a copy
      return d;
    }
  } // namespace

  namespace
  {
    /// The Moment curvature section's analysis: its curve as NumPy arrays
    /// (the columns of moment_curvature.csv) and its summary.
    py::dict
    moment_curvature_of(const InputParameters &input)
    {
      MomentCurvatureResult result;
      unsigned int          n_fibres = 0;
      {
        py::gil_scoped_release release;
        result = input.moment_curvature.run(input, input.sections, n_fibres);
      }
      const std::size_t n = result.points.size();
      Eigen::VectorXd   columns[9];
      for (Eigen::VectorXd &c : columns)
        c.resize(n);
      for (std::size_t i = 0; i < n; ++i)
        {
          const MomentCurvaturePoint &p = result.points[i];
          const double values[9] = {p.curvature, p.moment, p.axial_strain, p.concrete_strain,
                                    p.steel_strain_max, p.steel_strain_min, p.tangent,
                                    p.moment_z, p.moment_y};
          for (unsigned int j = 0; j < 9; ++j)
            columns[j](i) = values[j];
        }
      py::dict d;
      const char *names[9] = {"curvature", "moment", "axial_strain", "concrete_strain_min",
                              "steel_strain_max", "steel_strain_min", "tangent", "moment_z",
                              "moment_y"};
      for (unsigned int j = 0; j < 9; ++j)
        d[names[j]] = columns[j];
      const auto point = [](const MomentCurvaturePoint &p) {
        py::dict q;
        q["curvature"] = p.curvature;
        q["moment"]    = p.moment;
        return q;
      };
      if (result.yielded)
        d["first_yield"] = point(result.first_yield);
      d["peak"]        = point(result.peak);
      d["ultimate"]    = point(result.ultimate);
      d["ductility"]   = result.ductility();
      d["stop_reason"] = result.stop_reason;
      d["fibres"]      = n_fibres;
      py::list events;
      for (const MomentCurvatureEvent &e : result.events)
        events.append(py::make_tuple(e.what, e.at.curvature, e.at.moment));
      d["events"] = events;
      return d;
    }
  } // namespace

  std::shared_ptr<const Analysis>
  prepare(const InputParameters &input)
  {
    py::gil_scoped_release release;
    return std::make_shared<const Analysis>(prepare_analysis(input));
  }

  py::dict
  modes_of(const Analysis &analysis)
  {
    py::dict result = modes_dict(analysis.modes);
    result["equations"] = equation_labels(analysis.model);
    py::list buildings;
    for (unsigned int b = 0; b < analysis.model.buildings.size(); ++b)
      {
        py::dict building = modes_dict(analysis.building_modes[b]);
        building["name"]        = analysis.model.buildings[b].name;
        building["rayleigh_a0"] = analysis.system.rayleigh[b][0];
        building["rayleigh_a1"] = analysis.system.rayleigh[b][1];
        buildings.append(building);
      }
    result["buildings"] = buildings;
    return result;
  }

  namespace
  {
    void
    bind_input(py::module_ &m)
    {
      py::class_<InputParameters, std::shared_ptr<InputParameters>>(
        m, "Input", "A parameter file, read and checked (poundfe.read).")
        .def_property_readonly("file", [](const InputParameters &p) { return p.file; })
        .def_property_readonly("directory", [](const InputParameters &p) { return p.directory; })
        .def_property_readonly("overrides",
                               [](const InputParameters &p) {
                                 std::vector<std::pair<std::string, std::string>> pairs;
                                 for (const ParameterOverride &o : p.overrides)
                                   pairs.emplace_back(o.path, o.value);
                                 return pairs;
                               })
        .def_property_readonly("buildings",
                               [](const InputParameters &p) {
                                 std::vector<std::string> names;
                                 for (const BuildingParameters &b : p.model.buildings)
                                   names.push_back(b.name);
                                 return names;
                               },
                               "The buildings' names, in order.")
        .def_property_readonly("separations",
                               [](const InputParameters &p) { return p.model.separations; },
                               "Model/Separations, m.")
        .def_property_readonly(
          "time_step", [](const InputParameters &p) { return p.time_integration.newmark.time_step; })
        .def_property_readonly("output_directory",
                               [](const InputParameters &p) { return p.output.directory; })
        .def_property_readonly(
          "input_files",
          [](const InputParameters &p) {
            std::vector<std::pair<std::string, std::string>> files;
            for (const NamedInputFile &f : named_input_files(p))
              files.emplace_back(f.entry, f.name);
            return files;
          },
          "The files the input names: (entry, name as written) pairs, e.g. "
          "('IDA/Suite', 'recs/suite.csv'); a name is relative to `directory`.")
        .def_property_readonly("values",
                               [](const InputParameters &p) { return p.values; },
                               "Every entry as read (defaults included): (path, text) pairs "
                               "in the order the program declares them.")
        .def("__repr__", [](const InputParameters &p) {
          std::string text = "<poundfe.Input '" + p.file + "'";
          for (const ParameterOverride &o : p.overrides)
            text += " " + o.path + "=" + o.value;
          return text + ">";
        });

      m.def(
        "read",
        [](const std::string &file, const std::vector<std::pair<std::string, std::string>> &pairs) {
          py::gil_scoped_release release;
          return std::make_shared<InputParameters>(read_parameters(file, overrides_of(pairs)));
        },
        py::arg("file"), py::arg("overrides") = std::vector<std::pair<std::string, std::string>>{},
        "Read and check a .prm or .json file, with (path, value) overrides.");

      m.def(
        "read_text",
        [](const std::string &name, const std::string &text,
           const std::vector<std::pair<std::string, std::string>> &pairs) {
          py::gil_scoped_release release;
          return std::make_shared<InputParameters>(
            read_parameter_text(name, text, overrides_of(pairs)));
        },
        py::arg("name"), py::arg("text"),
        py::arg("overrides") = std::vector<std::pair<std::string, std::string>>{},
        "Read and check a parameter file's text without a file (a Model's), named `name` in "
        "messages; relative file names against the working directory.");

      m.def(
        "declarations",
        []() {
          std::ostringstream text;
          print_parameters(text);
          return text.str();
        },
        "What `poundfe print-parameters` prints: every section and entry as declared.");

      m.def("moment_curvature", &moment_curvature_of, py::arg("input"),
            "The Moment curvature section's curve (NumPy arrays) and its summary, as a dict.");
    }
  } // namespace
} // namespace poundfe::python

PYBIND11_MODULE(_core, m)
{
  using namespace poundfe::python;
  m.doc() = "poundfe's compiled core; use the package poundfe.";
  // As program.cc: deal.II's errors are exceptions, and one thread (the
  // numbers do not depend on a thread count).
  dealii::deal_II_exceptions::disable_abort_on_exception();
  dealii::MultithreadInfo::set_thread_limit(1);

  input_error_type = exception_type(
    m, "InputError", PyExc_ValueError,
    "Bad input: the message names the file, the line where known and the parameter "
    "(attributes file, line, parameter, problem).");
  numerical_error_type = exception_type(
    m, "NumericalError", PyExc_RuntimeError,
    "A solver or the integrator could not continue (the command line's exit status 2).");
  output_error_type =
    exception_type(m, "OutputError", PyExc_OSError, "A results file could not be written.");
  py::register_exception_translator(&translate_exception);

  bind_input(m);
  bind_run(m);
}
