#include <poundfe/dynamics/analysis.h>
#include <poundfe/commands/command.h>
#include <poundfe/commands/command_guard.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/plots.h>

#include <deal.II/base/exceptions.h>

#include <fstream>
#include <stdexcept>
#include <sstream>

#include <algorithm>
#include <iostream>

namespace poundfe
{
  namespace
  {
    /// summary.json of a command that stopped early ("interrupted" or
    /// "failed" with `message`), after removing its temporaries; prepares
    /// the directory first when the command had not (so the earlier run's
    /// files do not stay beside it) unless `only_if_begun`. Says on stderr
    /// when even this cannot be written (unless for the very error being
    /// reported: the directory). Returns what it wrote, for the
    /// console ("summary.json", or why not).
    std::string
    leave_summary(const GuardedCommand &c, const std::string &status,
                  const std::string &message, const bool only_if_begun)
    {
      if (!c.writes || (only_if_begun && !output_directory_prepared(c.directory)))
        return "";
      try
        {
          if (!output_directory_prepared(c.directory))
            prepare_output_directory(c.directory);
          const std::string       &summary = c.command.summary;
          std::vector<std::string> files   = remove_temporaries(c.directory);
          files.erase(std::remove(files.begin(), files.end(), summary), files.end());
          files.push_back(summary);
          JsonWriter json;
          begin_summary(json, c.command.name, c.input, status);
          if (!message.empty())
            json.value("message", message);
          json.begin_object("output")
            .value("directory", c.directory)
            .value("files", files)
            .end_object()
            .end_object();
          write_file_atomically(c.directory + "/" + summary, json.str());
          return c.directory + "/" + summary + " says " + status;
        }
      catch (const OutputError &e)
        {
          remove_temporaries(c.directory); // what a full disk allows
          if (e.what() != message) // not the same error (the directory) twice
            std::cerr << "poundfe: error: the summary of the " << status << " " << c.command.name
                      << " could not be written either: " << e.what() << "\n";
          return "no summary.json";
        }
    }

    /// A command that finished but whose figures (some or all) were not
    /// drawn: its summary.json says "completed with warnings" instead of
    /// "completed" and lists them under "missing_figures" with the reason.
    /// The one place for every command (plots.h remembers the figures).
    void
    note_missing_figures(const GuardedCommand &c)
    {
      std::vector<std::string> figures;
      for (const MissingFigure &f : missing_figures())
        figures.push_back(f.file + ": " + f.reason);
      forget_missing_figures();
      const std::string summary = c.directory + "/" + c.command.summary;
      std::ifstream     in(summary);
      if (!c.writes || figures.empty() || !in)
        return;
      std::ostringstream text;
      text << in.rdbuf();
      std::string       json   = text.str();
      const std::string status = "\n  \"status\": \"";
      const std::size_t at     = json.find(status); // the top level's (begin_summary)
      if (at == std::string::npos)
        return;
      std::size_t end = json.find('"', at + status.size());
      if (json.compare(at + status.size(), end - at - status.size(), "completed") == 0)
        json.insert(end, " with warnings"), end += 14;
      JsonWriter list; // the array alone, in the summary's layout
      list.begin_object().value("missing_figures", figures).end_object();
      const std::string array = list.str();
      const std::size_t from  = array.find('\n');
      json.insert(end + 1, "," + array.substr(from, array.rfind("\n}") - from));
      write_file_atomically(summary, json);
    }
  } // namespace

  int
  guard_command(const GuardedCommand &c, const std::function<int()> &body)
  {
    struct Stops // off again however the body ends: the summary must not stop
    {
      explicit Stops(const bool on) { set_stop_at_safe_points(on); }
      ~Stops() { set_stop_at_safe_points(false); }
    };
    try
      {
        Assert(!c.command.summary.empty(),
               dealii::ExcMessage("a guarded command's row names its summary"));
        const Stops stops(!c.command.has(CommandRule::own_interruption));
        forget_missing_figures();
        if (c.writes) // one rule for every command: its first file clears the earlier run's
          expect_output_directory(c.directory, resume_inputs(c.input, c.command.name),
                                  named_input_files(c.input));
        const int status = body();
        expect_output_directory("");
        note_missing_figures(c);
        return status;
      }
    catch (const Interrupted &)
      {
        const std::string said = leave_summary(c, "interrupted", "", false);
        std::cerr << "poundfe: " << c.command.name << " interrupted"
                  << (said.empty() ? "" : " (" + said + ")") << "\n";
        return interrupted_exit_status();
      }
    catch (const InputError &)
      {
        // refused after the first write: bad input writes nothing
        if (c.writes)
          discard_output_directory(c.directory);
        throw;
      }
    catch (const std::invalid_argument &)
      {
        // a sample refused when its realization is built (mu_k > mu_s, a
        // bumper thicker than its gap: model_parameter.h), which main reports
        // as bad input, exit 1: nothing written either
        if (c.writes)
          discard_output_directory(c.directory);
        throw;
      }
    catch (const OutputError &e)
      {
        leave_summary(c, "failed", e.what(), false);
        throw;
      }
    catch (const NumericalError &e)
      {
        leave_summary(c, "failed", e.what(), true);
        throw;
      }
  }
} // namespace poundfe
