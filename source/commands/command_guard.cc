#include <poundfe/dynamics/analysis.h>
#include <poundfe/commands/command_guard.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/output_directory.h>

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
          std::vector<std::string> files = remove_temporaries(c.directory);
          files.erase(std::remove(files.begin(), files.end(), "summary.json"), files.end());
          files.push_back("summary.json");
          JsonWriter json;
          begin_summary(json, c.command, c.input, status);
          if (!message.empty())
            json.value("message", message);
          json.begin_object("output")
            .value("directory", c.directory)
            .value("files", files)
            .end_object()
            .end_object();
          write_file_atomically(c.directory + "/summary.json", json.str());
          return c.directory + "/summary.json says " + status;
        }
      catch (const OutputError &e)
        {
          remove_temporaries(c.directory); // what a full disk allows
          if (e.what() != message) // not the same error (the directory) twice
            std::cerr << "poundfe: error: the summary of the " << status << " " << c.command
                      << " could not be written either: " << e.what() << "\n";
          return "no summary.json";
        }
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
        const Stops stops(c.stops_at_safe_points);
        return body();
      }
    catch (const Interrupted &)
      {
        const std::string said = leave_summary(c, "interrupted", "", false);
        std::cerr << "poundfe: " << c.command << " interrupted"
                  << (said.empty() ? "" : " (" + said + ")") << "\n";
        return interrupted_exit_status();
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
