// The lean extension poundfe._opensees, under poundfe.opensees (OpenSeesPy's
// calling conventions): over the interpreter's library alone (poundfe_lean:
// no deal.II, MPI, PETSc or Trilinos, as poundfe-opensees.so), so that
// `import poundfe.opensees` loads none of them. One entry,
// opensees_call(name, arguments), over the
// process's one OpenSeesInterpreter (commands/opensees_interpreter.h: the
// Tcl command procedures of `poundfe opensees` on one domain, which `wipe`
// clears). Python's values become the words a Tcl script would give: an
// int (or bool, or NumPy integer) an integer, a float (or NumPy float) a
// real, a str a text, a list, tuple or NumPy array one list word; results
// come back as float, int, lists of them or None, as OpenSeesPy returns
// them. A refusal is poundfe.opensees.OpenSeesError with the command's message; the
// Python layer (poundfe/opensees.py) adds the caller's file and line.
#include "module.h"

#include <poundfe/commands/opensees_interpreter.h>

#include <iostream>
#include <memory>

namespace py = pybind11;

namespace poundfe::python
{
  namespace
  {
    py::handle opensees_error_type;

    /// Made at the first call, on that thread, and kept to the process's
    /// end (Tcl outlives Python's finalisation; opensees_finish writes the
    /// recorders' files before it).
    OpenSeesInterpreter *instance = nullptr;

    OpenSeesInterpreter &
    interpreter()
    {
      if (!instance)
        instance = new OpenSeesInterpreter(std::cerr);
      return *instance;
    }

    bool
    is_numpy(const py::handle &object)
    {
      const py::object module = py::type::handle_of(object).attr("__module__");
      return py::isinstance<py::str>(module) && module.cast<std::string>() == "numpy";
    }

    /// The word of Python value `object`, argument `position` of `command`.
    OpenSeesValue
    word_of(const py::handle &object, const std::string &command, const std::size_t position)
    {
      using Kind = OpenSeesValue::Kind;
      OpenSeesValue value;
      if (py::isinstance<py::str>(object))
        value.kind = Kind::text, value.text = object.cast<std::string>();
      else if (py::isinstance<py::int_>(object)) // bool too
        value.kind = Kind::integer, value.integer = object.cast<long long>();
      else if (py::isinstance<py::float_>(object)) // numpy.float64 too
        value.kind = Kind::real, value.real = object.cast<double>();
      else if (py::isinstance<py::list>(object) || py::isinstance<py::tuple>(object))
        {
          value.kind = Kind::list;
          for (const py::handle item : object)
            value.items.push_back(word_of(item, command, position));
        }
      else if (is_numpy(object) && py::hasattr(object, "tolist")) // a scalar or an array
        return word_of(object.attr("tolist")(), command, position);
      else
        throw OpenSeesCommandError(command, command + ": argument " + std::to_string(position) +
                                              " is a " + std::string(py::str(object.get_type().attr("__name__"))) +
                                              ", not a number, a string or a list");
      return value;
    }

    py::object
    python_of(const OpenSeesValue &value)
    {
      using Kind = OpenSeesValue::Kind;
      switch (value.kind)
        {
          case Kind::integer:
            return py::int_(value.integer);
          case Kind::real:
            return py::float_(value.real);
          case Kind::text:
            return py::str(value.text);
          case Kind::list:
            {
              py::list list;
              for (const OpenSeesValue &item : value.items)
                list.append(python_of(item));
              return std::move(list);
            }
          case Kind::none:
            break;
        }
      return py::none();
    }

    [[noreturn]] void
    raise(const OpenSeesCommandError &e)
    {
      py::object exception         = py::handle(opensees_error_type)(e.what());
      exception.attr("command")    = e.command;
      PyErr_SetObject(opensees_error_type.ptr(), exception.ptr());
      throw py::error_already_set();
    }

    py::object
    call(const std::string &name, const py::tuple &arguments)
    {
      OpenSeesValue result;
      try
        {
          std::vector<OpenSeesValue> words;
          for (std::size_t i = 0; i < arguments.size(); ++i)
            words.push_back(word_of(arguments[i], name, i + 1));
          OpenSeesInterpreter &commands = interpreter();
          py::gil_scoped_release release;
          result = commands.call(name, words);
        }
      catch (const OpenSeesCommandError &e)
        {
          raise(e);
        }
      return python_of(result);
    }

    void
    bind_opensees(py::module_ &m)
    {
      opensees_error_type =
        exception_type(m, "OpenSeesError", PyExc_Exception,
                       "An OpenSees command refused (poundfe.opensees): the message starts with the "
                       "command's name and ends with the caller's file and line (attributes "
                       "command, file, line).",
                       "poundfe.opensees");
      m.def("opensees_call", &call, py::arg("name"), py::arg("arguments"),
            "Runs OpenSees command `name` with the tuple `arguments` (poundfe.opensees).");
      m.def(
        "opensees_commands",
        []() {
          py::list list;
          try
            {
              for (const auto &[name, supported] : interpreter().commands())
                list.append(py::make_tuple(name, supported));
            }
          catch (const OpenSeesCommandError &e)
            {
              raise(e);
            }
          return list;
        },
        "The OpenSees commands (name, supported) that opensees_call runs.");
      m.def(
        "opensees_finish",
        []() {
          try
            {
              if (instance)
                instance->finish_recorders();
            }
          catch (const std::exception &e) // a recorder's write error
            {
              raise(OpenSeesCommandError("", e.what()));
            }
        },
        "Every OpenSees recorder's file written (at the interpreter's exit); a "
        "write error raises OpenSeesError.");
    }
  } // namespace
} // namespace poundfe::python

PYBIND11_MODULE(_opensees, m)
{
  m.doc() = "The OpenSees interpreter's compiled part; use poundfe.opensees.";
  poundfe::python::bind_opensees(m);
}
