// `poundfe opensees SCRIPT [ARGS...]`: runs an OpenSees Tcl script in a Tcl
// 8.6 interpreter (as tclsh: argv0, argv, argc; Tcl's own loops, procs,
// source, expr, puts, file and open) with poundfe's implementations of the
// OpenSees commands (opensees_tcl_model.cc, opensees_tcl_analysis.cc) on
// the domain of opensees/. An OpenSees command or option poundfe lacks is an
// error naming it; any error ends the script with its file and line (exit 1,
// no recorder file written). `exit` ends it cleanly with the recorders'
// files in place. poundfe's additions live in the namespace poundfe::.
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/base/interruption_hook.h>
#include <poundfe/base/lean_assert.h>
#include <poundfe/commands/command.h>

#include "opensees_tcl.h"

#include <atomic>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <ostream>
#include <regex>
#include <sstream>

namespace poundfe
{
  namespace opensees_tcl
  {
    namespace
    {
      /// What `step` on recorder `tag` threw, if anything: a write error
      /// as the script's error naming the recorder and its last line's time.
      template <typename Step>
      std::exception_ptr
      recorder_failure(const opensees::Recorder &recorder, const int tag, const Step &step)
      {
        try
          {
            step();
            return nullptr;
          }
        catch (const OutputError &e)
          {
            std::ostringstream message;
            message << "recorder " << tag << ": " << e.what() << " (its lines up to time "
                    << recorder.last_line_time() << ")";
            return std::make_exception_ptr(opensees::ScriptError(message.str()));
          }
        catch (...)
          {
            return std::current_exception();
          }
      }
    } // namespace

    void
    Session::finish_recorders(const std::size_t first, const std::size_t last)
    {
      std::exception_ptr failure;
      for (std::size_t i = first; i < last && !failure; ++i)
        failure = recorder_failure(*recorders[i], recorder_tags[i], [&]() {
          recorders[i]->write_out();
        });
      std::size_t placed = first; // recorders first to placed - 1 are in place
      while (placed < last && !failure)
        {
          failure = recorder_failure(*recorders[placed], recorder_tags[placed], [&]() {
            recorders[placed]->put_in_place();
          });
          if (!failure)
            ++placed;
        }
      if (failure) // all of the files or none
        for (std::size_t i = first; i < placed; ++i)
          if (const std::string path = recorders[i]->placed_path(); !path.empty())
            std::remove(path.c_str());
      recorders.erase(recorders.begin() + first, recorders.begin() + last);
      recorder_tags.erase(recorder_tags.begin() + first, recorder_tags.begin() + last);
      if (failure)
        std::rethrow_exception(failure);
    }

    void
    Session::record()
    {
      if (interruption_requested()) // after each committed step of an analysis
        throw Interrupted();
      for (auto &recorder : recorders)
        recorder->record(domain);
    }

    Words::Words(Tcl_Interp *interp, const int objc, Tcl_Obj *const objv[])
      : name(Tcl_GetString(objv[0]))
      , interp(interp)
      , objc(objc)
      , objv(objv)
    {}

    std::string
    Words::word(const char *what)
    {
      if (done())
        throw opensees::ScriptError("missing " + std::string(what));
      return Tcl_GetString(objv[next++]);
    }

    std::string
    Words::peek() const
    {
      return done() ? std::string() : std::string(Tcl_GetString(objv[next]));
    }

    double
    Words::real(const char *what)
    {
      const std::string text = word(what);
      double            value;
      if (Tcl_GetDoubleFromObj(nullptr, objv[next - 1], &value) != TCL_OK)
        throw opensees::ScriptError("expected a number for " + std::string(what) + ", got '" +
                                    text + "'");
      // Tcl reads "inf" as a double; no quantity of a model or an analysis is
      // infinite, and one would surface later as a singular matrix
      if (!std::isfinite(value))
        throw opensees::ScriptError("expected a finite number for " + std::string(what) +
                                    ", got '" + text + "'");
      return value;
    }

    int
    Words::integer(const char *what)
    {
      const std::string text = word(what);
      Tcl_WideInt       value;
      if (Tcl_GetWideIntFromObj(nullptr, objv[next - 1], &value) != TCL_OK)
        throw opensees::ScriptError("expected an integer for " + std::string(what) + ", got '" +
                                    text + "'");
      // Tcl's int reading wraps 2147483648 to -2147483648: refuse it instead.
      if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max())
        throw opensees::ScriptError(std::string(what) + " '" + text + "' is out of range");
      return static_cast<int>(value);
    }

    std::vector<double>
    Words::numbers(const char *what)
    {
      std::vector<double> values;
      double value;
      while (!done() && Tcl_GetDoubleFromObj(nullptr, objv[next], &value) == TCL_OK)
        values.push_back(real(what));
      return values;
    }

    std::vector<int>
    Words::integers(const char *what)
    {
      std::vector<int> values;
      int value;
      while (!done() && Tcl_GetIntFromObj(nullptr, objv[next], &value) == TCL_OK)
        values.push_back(integer(what));
      return values;
    }

    void
    unsupported(const std::string &what)
    {
      throw opensees::ScriptError(what + ": poundfe does not support it");
    }

    namespace
    {
      struct Definition
      {
        Session  *session;
        Procedure procedure;
      };

      int
      run_procedure(ClientData data, Tcl_Interp *interp, int objc, Tcl_Obj *const objv[])
      {
        auto       &definition = *static_cast<Definition *>(data);
        Words       words(interp, objc, objv);
        std::string message;
        try
          {
            Tcl_ResetResult(interp);
            if (interruption_requested()) // a safe point: the script's next OpenSees command
              throw Interrupted();
            definition.procedure(*definition.session, words);
            return TCL_OK;
          }
        catch (const Interrupted &e) // uncaught by the script's `catch` (CancelOnSignal)
          {
            Tcl_CancelEval(interp, nullptr, nullptr, TCL_CANCEL_UNWIND);
            message = e.what();
          }
        catch (const InputError &e) // a material's parameter
          {
            message = e.parameter().empty() ? e.problem() :
                                              "parameter '" + e.parameter() + "': " + e.problem();
          }
        catch (const std::exception &e)
          {
            message = e.what();
          }
        // "fix: node 9 does not exist"; a message naming the command already stays
        const bool named = message.compare(0, words.name.size(), words.name) == 0 &&
                           (message[words.name.size()] == ' ' || message[words.name.size()] == ':');
        const std::string text  = named ? message : words.name + ": " + message;
        Tcl_SetObjResult(interp, Tcl_NewStringObj(text.c_str(), -1));
        return TCL_ERROR;
      }

      void
      delete_definition(ClientData data)
      {
        delete static_cast<Definition *>(data);
      }
    } // namespace

    void
    define(Tcl_Interp *interp, Session &session, const std::string &name, Procedure procedure)
    {
      session.commands[name] = true;
      Tcl_CreateObjCommand(interp, name.c_str(), run_procedure,
                           new Definition{&session, std::move(procedure)}, delete_definition);
    }

    namespace
    {
      /// An empty list made a list object, not an empty text (Tcl's
      /// Tcl_NewListObj(0) is one): poundfe.opensees answers [], not None.
      void
      as_list(Tcl_Obj *list)
      {
        Tcl_ConvertToType(nullptr, list, Tcl_GetObjType("list"));
      }
    } // namespace

    void
    set_result(Tcl_Interp *interp, const double value)
    {
      Tcl_SetObjResult(interp, Tcl_NewDoubleObj(value));
    }

    void
    set_result(Tcl_Interp *interp, const std::vector<double> &values)
    {
      Tcl_Obj *list = Tcl_NewListObj(0, nullptr);
      for (const double v : values)
        Tcl_ListObjAppendElement(interp, list, Tcl_NewDoubleObj(v));
      as_list(list);
      Tcl_SetObjResult(interp, list);
    }

    void
    set_result(Tcl_Interp *interp, const std::vector<int> &values)
    {
      Tcl_Obj *list = Tcl_NewListObj(0, nullptr);
      for (const int v : values)
        Tcl_ListObjAppendElement(interp, list, Tcl_NewIntObj(v));
      as_list(list);
      Tcl_SetObjResult(interp, list);
    }

    namespace
    {
      /// OpenSees commands poundfe does not have yet: a script that uses one
      /// stops with its name rather than Tcl's "invalid command name".
      void
      define_unsupported(Tcl_Interp *interp, Session &session)
      {
        for (const char *name :
             {"imposedMotion", "groundMotion",
              "printA", "printB",
              "basicDeformation", "basicForce", "localForce", "block2D", "block3D", "nDMaterial", "frictionModel",
              "database", "geomTransfPDelta", "mp", "domainChange", "remesh", "setNodeCoord",
              "setNodeDisp", "setNodeVel", "setNodeAccel", "getLoadFactor", "sectionForce",
              "sectionDeformation", "sectionStiffness", "nodeEigenvector", "nodeMass",
              "nodeResponse", "nodeUnbalance", "nodeDOFs", "numFact", "numIter",
              "systemSize", "getEleClassTags", "setParameter", "parameter", "updateParameter",
              "loadPackage", "video", "logFile", "start", "stop"})
          {
            define(interp, session, name,
                   [](Session &, Words &words) { unsupported(words.name); });
            session.commands[name] = false;
          }
      }

      /// `exit ?status?`: the script ends here, cleanly (its recorders
      /// written), instead of Tcl ending the process.
      void
      define_exit(Tcl_Interp *interp, Session &session)
      {
        define(interp, session, "exit", [](Session &s, Words &words) {
          s.exit_status = words.done() ? 0 : words.integer("the exit status");
          s.exited      = true;
          throw opensees::ScriptError("exit");
        });
      }

      /// poundfe::report: what the script's analyses did, as a dict
      /// (steps, iterations, factorizations, failed_steps, time).
      void
      define_poundfe_namespace(Tcl_Interp *interp, Session &session)
      {
        Tcl_CreateNamespace(interp, "poundfe", nullptr, nullptr);
        define(interp, session, "poundfe::report", [](Session &s, Words &words) {
          opensees::AnalysisCounts c = s.counts;
          if (s.analysis)
            {
              c.steps += s.analysis->counts.steps;
              c.iterations += s.analysis->counts.iterations;
              c.factorizations += s.analysis->counts.factorizations;
              c.failed_steps += s.analysis->counts.failed_steps;
            }
          const std::string text =
            "steps " + std::to_string(c.steps) + " iterations " + std::to_string(c.iterations) +
            " factorizations " + std::to_string(c.factorizations) + " failed_steps " +
            std::to_string(c.failed_steps);
          Tcl_SetObjResult(words.interp, Tcl_NewStringObj(text.c_str(), -1));
        });
        define_poundfe_commands(interp, session);
      }

      /// The file and line of a Tcl error: the innermost `(file "F" line N)`
      /// of errorInfo (a sourced file's own line; a procedure's error at the
      /// line that called it), else the script and -errorline.
      std::pair<std::string, int>
      error_location(Tcl_Interp *interp, const std::string &script, const int code)
      {
        Tcl_Obj *options = Tcl_GetReturnOptions(interp, code);
        Tcl_IncrRefCount(options);
        Tcl_Obj *key = Tcl_NewStringObj("-errorinfo", -1), *info = nullptr;
        Tcl_IncrRefCount(key);
        Tcl_DictObjGet(nullptr, options, key, &info);
        const std::string text = info ? Tcl_GetString(info) : "";
        Tcl_DecrRefCount(key);
        key = Tcl_NewStringObj("-errorline", -1);
        Tcl_IncrRefCount(key);
        Tcl_Obj *line = nullptr;
        Tcl_DictObjGet(nullptr, options, key, &line);
        int error_line = 0;
        if (line)
          Tcl_GetIntFromObj(nullptr, line, &error_line);
        Tcl_DecrRefCount(key);
        Tcl_DecrRefCount(options);
        std::smatch      match;
        const std::regex file_line("\\(file \"([^\"]*)\" line ([0-9]+)\\)");
        if (std::regex_search(text, match, file_line))
          return {match[1].str(), std::stoi(match[2].str())};
        return {script, error_line};
      }

      /// argv0, argv and argc as tclsh sets them.
      void
      set_arguments(Tcl_Interp *interp, const std::vector<std::string> &arguments)
      {
        Tcl_Obj *argv = Tcl_NewListObj(0, nullptr);
        for (std::size_t i = 1; i < arguments.size(); ++i)
          Tcl_ListObjAppendElement(interp, argv, Tcl_NewStringObj(arguments[i].c_str(), -1));
        Tcl_SetVar2Ex(interp, "argv0", nullptr, Tcl_NewStringObj(arguments[0].c_str(), -1),
                      TCL_GLOBAL_ONLY);
        Tcl_SetVar2Ex(interp, "argv", nullptr, argv, TCL_GLOBAL_ONLY);
        Tcl_SetVar2Ex(interp, "argc", nullptr, Tcl_NewIntObj(arguments.size() - 1),
                      TCL_GLOBAL_ONLY);
        Tcl_SetVar2Ex(interp, "tcl_interactive", nullptr, Tcl_NewIntObj(0), TCL_GLOBAL_ONLY);
      }

      struct Interpreter
      {
        Tcl_Interp *interp = Tcl_CreateInterp();
        ~Interpreter()
        {
          // what the script's puts wrote, before any message of ours
          for (const int channel : {TCL_STDOUT, TCL_STDERR})
            if (Tcl_Channel c = Tcl_GetStdChannel(channel))
              Tcl_Flush(c);
          Tcl_DeleteInterp(interp);
        }
      };

      /// SIGINT or SIGTERM also in a loop of Tcl's own commands (`while 1
      /// {}`), which calls no OpenSees command to see the flag: the signal
      /// handler marks a Tcl async handler (Tcl_AsyncMark, Tcl's call for
      /// signal handlers), which Tcl runs at its next safe point and which
      /// cancels the script with TCL_CANCEL_UNWIND, which no `catch` stops.
      class CancelOnSignal
      {
      public:
        explicit CancelOnSignal(Tcl_Interp *interp)
          : handler(Tcl_AsyncCreate(cancel, interp))
        {
          marked.store(handler);
          set_interruption_hook(mark);
          if (interruption_requested()) // before the hook was set
            Tcl_AsyncMark(handler);
        }
        ~CancelOnSignal()
        {
          set_interruption_hook(nullptr);
          marked.store(nullptr);
          Tcl_AsyncDelete(handler);
        }
        CancelOnSignal(const CancelOnSignal &)            = delete;
        CancelOnSignal &operator=(const CancelOnSignal &) = delete;

      private:
        static int
        cancel(ClientData interp, Tcl_Interp *, const int code)
        {
          Tcl_CancelEval(static_cast<Tcl_Interp *>(interp), nullptr, nullptr, TCL_CANCEL_UNWIND);
          return code;
        }
        static void
        mark()
        {
          if (const Tcl_AsyncHandler h = marked.load())
            Tcl_AsyncMark(h);
        }
        static inline std::atomic<Tcl_AsyncHandler> marked{nullptr};
        const Tcl_AsyncHandler                      handler;
      };
    } // namespace

    void
    define_commands(Tcl_Interp *interp, Session &session)
    {
      define_model_commands(interp, session);
      define_analysis_commands(interp, session);
      define_section_commands(interp, session);
      define_region_commands(interp, session);
      define_domain_commands(interp, session);
      define_print_commands(interp, session);
      define_unsupported(interp, session);
      define_exit(interp, session);
      define_poundfe_namespace(interp, session);
    }
  } // namespace opensees_tcl

  namespace commands
  {
    int
    opensees(const CommandRun &run)
    {
      using namespace opensees_tcl;
      Assert(!run.arguments.empty(), dealii::ExcMessage("the dispatcher refuses no script"));
      const std::string &script = run.arguments[0];
      if (!std::ifstream(script))
        throw InputError(script, 0, "", "cannot be read");
      Tcl_FindExecutable(nullptr);
      Interpreter interpreter;
      Tcl_Interp *interp = interpreter.interp;
      if (Tcl_Init(interp) != TCL_OK)
        throw InputError(script, 0, "",
                         "Tcl could not start: " + std::string(Tcl_GetStringResult(interp)));
      set_arguments(interp, run.arguments);
      Session session(run.err);
      define_commands(interp, session);
      const int code = [&]() {
        const CancelOnSignal cancel_on_signal(interp);
        return Tcl_EvalFile(interp, script.c_str());
      }();
      if (interruption_requested()) // the recorders' temporaries go with the session
        throw Interrupted();
      if (code != TCL_OK && !session.exited)
        {
          const std::string message = Tcl_GetStringResult(interp);
          const auto [file, line] = error_location(interp, script, code);
          const auto &body = session.body_error; // the message of this error, not a caught one
          if (body.line > 0 && body.message == message)
            {
              // the file as the script named it, when it is the same file
              const bool same =
                std::filesystem::absolute(file).lexically_normal() == body.file;
              throw InputError(same ? file : body.file, body.line, "", message);
            }
          throw InputError(file, line, "", message);
        }
      session.finish_recorders();
      std::cout.flush();
      return session.exit_status;
    }
  } // namespace commands
} // namespace poundfe
