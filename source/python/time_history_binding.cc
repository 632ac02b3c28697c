// poundfe._core's time history and commands: the command line's own
// run_time_history (the same observers, files and numbers) with one more
// observer that calls Python back every N steps, and any command of the
// command table through the command line's own dispatcher. The GIL is released while poundfe
// steps; the observer takes it back for the callback and, every few hundred
// steps, to let Ctrl-C (KeyboardInterrupt) stop a run.
#include "module.h"

#include <poundfe/base/interruption.h>
#include <poundfe/base/interruption_scope.h>
#include <poundfe/commands/command_table.h>
#include <poundfe/commands/dispatch.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/report/run_outputs.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/output/floor_response.h>
#include <poundfe/output/memory_results.h>

#include <deal.II/base/mpi.h>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <exception>
#include <sstream>
#include <iostream>

namespace py = pybind11;

namespace poundfe::python
{
  namespace
  {
    /// What the callback sees at a step: copies, so that the callback may
    /// keep them.
    struct StepState
    {
      unsigned long       step = 0;
      double              time = 0, ground_acceleration = 0;
      Eigen::VectorXd     displacement, velocity, acceleration; // per equation, relative
      std::vector<double> floor_displacement, drift_ratio, floor_acceleration;
      std::size_t         n_impacts = 0;
      /// Each building's name and its first floor's index in the floor arrays.
      std::shared_ptr<const std::vector<std::pair<std::string, unsigned int>>> layout;
      unsigned int n_floors = 0;

      /// {name: {floor_displacement, drift_ratio, floor_acceleration}},
      /// each building's floors bottom up (slices of the whole arrays).
      py::dict
      buildings() const
      {
        py::dict d;
        for (std::size_t b = 0; b < layout->size(); ++b)
          {
            const unsigned int first = (*layout)[b].second;
            const unsigned int end   = b + 1 < layout->size() ? (*layout)[b + 1].second : n_floors;
            const auto slice = [&](const std::vector<double> &v) {
              return std::vector<double>(v.begin() + first, v.begin() + end);
            };
            py::dict building;
            building["floor_displacement"] = slice(floor_displacement);
            building["drift_ratio"]        = slice(drift_ratio);
            building["floor_acceleration"] = slice(floor_acceleration);
            d[py::str((*layout)[b].first)] = building;
          }
        return d;
      }
    };

    /// Calls `callback(state)` at step 0 and every `every` steps; checks for
    /// Ctrl-C every `signal_steps` steps. A Python exception raised by
    /// either (KeyboardInterrupt) is kept and ends the run as an
    /// interruption (RunStopped), so that its files are finished and its
    /// summary says "interrupted"; kept_exception() gives it to Python,
    /// which raises it with the results so far once the run has returned.
    class CallbackObserver : public StepObserver
    {
    public:
      CallbackObserver(py::object callback, const unsigned int every, const Model &model)
        : callback(std::move(callback))
        , every(std::max(1u, every))
        , floors(model)
      {
        auto buildings = std::make_shared<std::vector<std::pair<std::string, unsigned int>>>();
        for (unsigned int b = 0; b < model.buildings.size(); ++b)
          buildings->emplace_back(model.buildings[b].name, floors.index(b, 0));
        layout = std::move(buildings);
      }

      void
      observe_step(const ResponseView &state) override
      {
        if (kept) // raised at step 0, outside the run's loop: stopped at the first step
          throw RunStopped();
        const bool call  = !callback.is_none() && state.step() % every == 0;
        const bool check = state.step() % signal_steps == 0;
        if (!call && !check)
          return;
        try
          {
            py::gil_scoped_acquire acquire;
            if (PyErr_CheckSignals() != 0)
              throw py::error_already_set();
            if (call)
              callback(py::cast(state_of(state)));
          }
        catch (const py::error_already_set &)
          {
            kept = std::current_exception();
            if (state.step() > 0)
              throw RunStopped();
          }
      }

      /// The Python exception that stopped the run (with the GIL held);
      /// None when none did.
      py::object
      kept_exception() const
      {
        if (!kept)
          return py::none();
        try
          {
            std::rethrow_exception(kept);
          }
        catch (const py::error_already_set &e)
          {
            return e.value();
          }
      }

    private:
      static constexpr unsigned int signal_steps = 256;

      StepState
      state_of(const ResponseView &view)
      {
        floors.evaluate(view.time(), view.displacement(), view.velocity(), view.acceleration(),
                        view.ground_acceleration());
        StepState s;
        s.step                = view.step();
        s.time                = view.time();
        s.ground_acceleration = view.ground_acceleration();
        s.displacement        = view.displacement();
        s.velocity            = view.velocity();
        s.acceleration        = view.acceleration();
        s.floor_displacement  = floors.displacement();
        s.drift_ratio         = floors.drift_ratio();
        s.floor_acceleration  = floors.absolute_acceleration();
        s.n_impacts           = view.impact_log().impacts().size();
        s.layout              = layout;
        s.n_floors            = floors.n_floors();
        return s;
      }

      py::object         callback;
      const unsigned int every;
      FloorResponse      floors;
      std::shared_ptr<const std::vector<std::pair<std::string, unsigned int>>> layout;
      std::exception_ptr kept;
    };

    /// A run's tables as NumPy arrays (rows x columns, the time first),
    /// moved out of `memory` without a copy, with their headers; its other
    /// texts (summary.json, impacts.csv, the profiles) by file name.
    py::dict
    memory_dict(MemoryResults &memory)
    {
      py::list tables;
      for (MemoryResults::Table &table : memory.tables)
        {
          const std::size_t n_columns = table.header.size();
          auto *values = new std::vector<double>(std::move(table.values));
          py::capsule owner(values, [](void *p) { delete static_cast<std::vector<double> *>(p); });
          const py::ssize_t n_rows = static_cast<py::ssize_t>(values->size() / n_columns);
          py::array_t<double> array({n_rows, static_cast<py::ssize_t>(n_columns)}, values->data(),
                                    owner);
          tables.append(py::make_tuple(table.stem, table.header, array));
        }
      py::dict texts;
      for (const auto &[name, text] : memory.texts)
        texts[py::str(name)] = py::str(text);
      py::dict d;
      d["tables"] = tables;
      d["texts"]  = texts;
      return d;
    }

    /// A time history through the command line's run_time_history: into
    /// `directory` (its files; VTU frames and plots as the input asks), or
    /// with an empty `directory` into memory (the same observers, no file).
    py::dict
    run_time_history_into(const InputParameters &input, const std::string &directory,
                          py::object callback, const unsigned int every)
    {
      const std::shared_ptr<const Analysis> analysis = prepare(input);
      CallbackObserver observer(std::move(callback), every, analysis->model);
      RunResult        result;
      MemoryResults    memory;
      {
        py::gil_scoped_release release;
        const RunParameters parameters = run_parameters(input);
        const Excitation    excitation = make_excitation(*analysis, parameters.time_history);
        RunOptions          options;
        options.output_directory = directory;
        options.memory           = directory.empty() ? &memory : nullptr;
        options.observers        = {&observer};
        result                   = run_time_history(*analysis, parameters, excitation, options);
      }
      py::dict d = directory.empty() ? memory_dict(memory) : py::dict();
      d["status"]               = result.status.name();
      d["message"]              = result.status.message;
      d["output_failed"]        = result.status.output_failed;
      d["steps"]                = result.status.steps;
      d["end_time"]             = result.status.end_time;
      d["wall_time"]            = result.status.wall_time;
      d["n_impacts"]            = result.n_impacts;
      d["n_nonlinear_elements"] = result.n_nonlinear_elements;
      d["max_energy_error"]     = result.max_energy_error;
      d["warnings"]             = result.warnings;
      d["modes"]                = modes_of(*analysis);
      d["exception"]            = observer.kept_exception(); // raised by run() with the results
      return d;
    }

    /// MPI (and PETSc) for the commands that need it, initialised once on
    /// demand as program.cc does, and finalised when Python exits.
    dealii::Utilities::MPI::MPI_InitFinalize *mpi = nullptr;

    void
    ensure_mpi()
    {
      if (mpi != nullptr) // (dispatch_command asks only while MPI is not initialised)
        return;
      static int   argc     = 1;
      static char  name[]   = "python";
      static char *words[]  = {name, nullptr};
      static char **argv    = words;
      mpi = new dealii::Utilities::MPI::MPI_InitFinalize(argc, argv, 1);
      // called inside a command's InterruptionScope: PETSc's initialisation
      // replaced its handlers, as program.cc's
      install_interruption_handlers();
    }

    /// `poundfe NAME ARGUMENTS... [--output DIR] [--realizations N] [--set
    /// PATH=VALUE]...` through the command line's own dispatcher
    /// (commands/dispatch.h): the same rules, checks and messages, raised as
    /// exceptions (a refused command line as ValueError, bad input as
    /// InputError) instead of exit status 1; returns the exit status otherwise.
    /// With `report`, what the command writes on standard output (its report
    /// on the terminal) goes there instead.
    int
    run_command_of_table(const std::string &name, const std::vector<std::string> &arguments,
                         const std::string &output, const unsigned int n_realizations,
                         const std::vector<std::pair<std::string, std::string>> &overrides,
                         std::string *report = nullptr, MemoryResults *memory = nullptr)
    {
      const Command *command = find_command(name);
      if (command == nullptr)
        throw py::value_error("unknown command '" + name + "'\n" + usage_text());
      CommandRequest request{arguments, output, n_realizations, {}};
      request.memory = memory;
      for (const auto &[path, value] : overrides)
        request.overrides.push_back({path, value});
      int status = 0;
      {
        py::gil_scoped_release release;
        std::ostringstream     captured;
        // std::cout's buffer is swapped back however the command ends
        struct Restore
        {
          std::streambuf *buffer;
          ~Restore() { std::cout.rdbuf(buffer); }
        } restore{report ? std::cout.rdbuf(captured.rdbuf()) : std::cout.rdbuf()};
        // Ctrl-C stops the command as on the command line (its results so
        // far kept, exit status 130), Python's handler back afterwards
        const InterruptionScope signals;
        status = dispatch_command(*command, request, ensure_mpi, std::cerr);
        std::cout.flush();
        if (report)
          *report = captured.str();
      }
      return status;
    }

    /// run_command_of_table with its report kept: (status, report).
    std::pair<int, std::string>
    run_command_reported(const std::string &name, const std::vector<std::string> &arguments,
                         const std::string &output, const unsigned int n_realizations,
                         const std::vector<std::pair<std::string, std::string>> &overrides)
    {
      std::string report;
      const int   status =
        run_command_of_table(name, arguments, output, n_realizations, overrides, &report);
      return {status, report};
    }

    /// A command of the table (a row with CommandRule::in_memory) with its
    /// results in memory, no file written: {status, report, tables, texts}
    /// (memory_dict's tables and texts by file name).
    py::dict
    run_command_in_memory(const std::string &name, const std::vector<std::string> &arguments,
                          const unsigned int                                        n_realizations,
                          const std::vector<std::pair<std::string, std::string>> &overrides)
    {
      std::string   report;
      MemoryResults memory;
      const int     status =
        run_command_of_table(name, arguments, "", n_realizations, overrides, &report, &memory);
      py::dict d        = memory_dict(memory);
      d["exit_status"]  = status;
      d["report"]       = report;
      return d;
    }
  } // namespace

  void
  bind_run(py::module_ &m)
  {
    py::class_<StepState>(m, "StepState", "The state at a step, handed to a run's callback.")
      .def_readonly("step", &StepState::step)
      .def_readonly("time", &StepState::time, "s")
      .def_readonly("ground_acceleration", &StepState::ground_acceleration, "m/s^2")
      .def_readonly("displacement", &StepState::displacement, "per equation, m or rad, relative")
      .def_readonly("velocity", &StepState::velocity, "per equation, relative")
      .def_readonly("acceleration", &StepState::acceleration, "per equation, relative")
      .def_readonly("floor_displacement", &StepState::floor_displacement,
                    "per floor (building by building, bottom up), m, relative")
      .def_readonly("drift_ratio", &StepState::drift_ratio, "per storey")
      .def_readonly("floor_acceleration", &StepState::floor_acceleration,
                    "per floor, m/s^2, absolute")
      .def_readonly("n_impacts", &StepState::n_impacts, "impacts so far")
      .def_property_readonly("buildings", &StepState::buildings,
                             "{building: {floor_displacement, drift_ratio, floor_acceleration}}, "
                             "each building's floors bottom up")
      .def("__repr__", [](const StepState &s) {
        return "<poundfe.StepState step " + std::to_string(s.step) + ", t = " +
               std::to_string(s.time) + " s>";
      });

    m.def("run_time_history", &run_time_history_into, py::arg("input"), py::arg("directory"),
          py::arg("callback") = py::none(), py::arg("every") = 1,
          "A time history into `directory` (\"\": into memory); use poundfe.run.");
    m.def(
      "command",
      [](const std::string &name, const std::vector<std::string> &arguments,
         const std::string &output, const unsigned int realizations,
         const std::vector<std::pair<std::string, std::string>> &overrides) {
        return run_command_of_table(name, arguments, output, realizations, overrides);
      },
      py::arg("name"), py::arg("arguments"), py::arg("output") = "", py::arg("realizations") = 0,
      py::arg("overrides") = std::vector<std::pair<std::string, std::string>>{},
      "A command of the command table; use poundfe.command.");
    m.def("command_reported", &run_command_reported, py::arg("name"), py::arg("arguments"),
          py::arg("output") = "", py::arg("realizations") = 0,
          py::arg("overrides") = std::vector<std::pair<std::string, std::string>>{},
          "A command of the command table, its report returned: (status, report); use "
          "poundfe.montecarlo, ....");
    m.def("command_in_memory", &run_command_in_memory, py::arg("name"), py::arg("arguments"),
          py::arg("realizations") = 0,
          py::arg("overrides") = std::vector<std::pair<std::string, std::string>>{},
          "A command of the command table with its results in memory (no file): {exit_status, "
          "report, tables, texts}; use poundfe.montecarlo, ....");
    m.def(
      "in_memory",
      [](const std::string &name) {
        const Command *command = find_command(name);
        return command != nullptr && command->has(CommandRule::in_memory);
      },
      py::arg("name"), "Whether command `name` can leave its results in memory.");
    py::module_::import("atexit").attr("register")(py::cpp_function([]() {
      delete mpi;
      mpi = nullptr;
    }));
  }
} // namespace poundfe::python
