// The text of a parameter file checked before deal.II's ParameterHandler
// reads it, so that no file can crash the reader or be silently misread:
//  - line ends: LF, CR LF (and CR CR LF), and a lone CR (old Mac files);
//  - comments ('#' to the end of the line) are removed here, so a backslash
//    in a comment does not join the next line to it (ParameterHandler joins
//    a line ending in '\' with the next before it strips comments);
//  - 'subsection'/'end' must balance: the message names the line;
//  - a file that sets nothing (empty, only comments) is refused: it would
//    run the built-in default model;
//  - JSON: the top level must be a non-empty object, nested at most
//    max_json_depth deep (boost's recursive JSON reader overflows the stack
//    at about 30,000 levels).
// Everything is a hand-written scan, linear in the file's length (no
// std::regex, whose matcher recurses once per character and overflows the
// stack on lines of ~26,000 characters).
#ifndef poundfe_base_input_text_h
#define poundfe_base_input_text_h

#include <map>
#include <string>

namespace poundfe
{
  /// The file's bytes with every line end ("\r\n", "\r\r\n" or "\r") made "\n".
  /// Throws InputError, calling the file `what`, when it cannot be read.
  std::string read_input_text(const std::string &file, const std::string &what = "parameter file");

  /// A .prm file prepared for ParameterHandler.
  struct PrmText
  {
    /// The file without comments, one line per line of the file (so
    /// ParameterHandler's line numbers stay the file's).
    std::string text;
    /// Line of "set <Section/.../Entry>" (the first line of a continued one).
    std::map<std::string, int> lines;
  };

  /// Strip comments, check subsection/end balance and that something is
  /// set, index the set lines. Throws InputError naming `file` and the line.
  PrmText prepare_prm_text(const std::string &file, const std::string &text);

  /// Deepest nesting of objects and arrays a JSON parameter file may have.
  constexpr unsigned int max_json_depth = 64;

  /// Check a JSON parameter file's text: a non-empty object at the top,
  /// brackets balanced outside strings, nested at most max_json_depth.
  /// Throws InputError naming `file` and the line.
  void check_json_text(const std::string &file, const std::string &text);
} // namespace poundfe

#endif
