// The OpenSees commands of `poundfe opensees` called one at a time with
// values instead of read from a script: the engine of the Python module
// poundfe.opensees (OpenSeesPy's calling conventions). Each call hands its
// values to the same Tcl command procedures as a script's line (the words
// a Tcl script would give: an integer, a real, a text, or a list as one
// word), on one domain that lives until `wipe` clears it; the command's
// Tcl result comes back with its type (a real, an integer, a list of them,
// nothing). Tcl stays behind the implementation (source/commands/
// opensees_interpreter.cc): this header does not include <tcl.h>.
//
// Where OpenSeesPy differs from Tcl by having no script bodies, the
// commands follow OpenSeesPy: `pattern Plain` without a body makes the
// pattern the one later `load` and `eleLoad` calls fill (until the next
// Plain pattern or `wipe`), and `section Fiber` without a body is filled by
// the `patch`, `layer` and `fiber` calls after it (the section is made at
// the next other command).
#ifndef poundfe_commands_opensees_interpreter_h
#define poundfe_commands_opensees_interpreter_h

#include <iosfwd>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace poundfe
{
  /// One argument or result of a command: nothing, an integer, a real, a
  /// text, or a list of values.
  struct OpenSeesValue
  {
    enum class Kind
    {
      none,
      integer,
      real,
      text,
      list
    };
    Kind                       kind    = Kind::none;
    long long                  integer = 0;
    double                     real    = 0.0;
    std::string                text;
    std::vector<OpenSeesValue> items;
  };

  /// A command's refusal: its message starts with the command's name
  /// ("node: expected a number for ..."), as in a script's error.
  class OpenSeesCommandError : public std::runtime_error
  {
  public:
    OpenSeesCommandError(std::string command, const std::string &message)
      : std::runtime_error(message)
      , command(std::move(command))
    {}
    const std::string command;
  };

  /// One Tcl interpreter with the OpenSees commands and the domain they
  /// fill. Tcl binds an interpreter to the thread that made it: every call
  /// must come from that thread (OpenSeesCommandError otherwise).
  class OpenSeesInterpreter
  {
  public:
    /// `warnings`: where the commands' warnings go (a short Path file, ...).
    explicit OpenSeesInterpreter(std::ostream &warnings);
    ~OpenSeesInterpreter();

    /// The OpenSees commands a caller may call, each with whether poundfe
    /// implements it (a command it lacks refuses with its name); the
    /// script-only commands (`exit`, `poundfe::...`) are not among them.
    std::vector<std::pair<std::string, bool>> commands() const;

    /// Runs command `name` on `arguments`; its result (Kind::none when it
    /// has none). OpenSeesCommandError when the command refuses or `name`
    /// is not one of commands().
    OpenSeesValue call(const std::string &name, const std::vector<OpenSeesValue> &arguments);

    /// Every recorder's file written and closed (as `wipe` and the end of
    /// a script do), the domain kept.
    void finish_recorders();

  private:
    struct Implementation;
    std::unique_ptr<Implementation> implementation;
  };
} // namespace poundfe

#endif
