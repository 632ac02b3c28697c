// The text of every input file poundfe reads (parameter files, records,
// catalogues, hazard and fragility files, meshes), checked before a parser
// sees it, so that no file can crash a reader or be silently misread:
//  - only a regular file is read, of at most max_input_bytes: a directory,
//    a FIFO or a device (/dev/zero) is refused before it is opened (opening
//    a FIFO waits for a writer; a device never ends);
//  - no NUL byte (a binary file), no line longer than max_line_length;
//  - line ends: LF, CR LF (and CR CR LF), and a lone CR (old Mac files); a
//    UTF-8 byte-order mark at the start is dropped;
//  - JSON: brackets balanced outside strings, nested at most max_json_depth
//    deep (boost's recursive JSON reader overflows the stack at about
//    30,000 levels).
// For parameter files also:
//  - comments ('#' to the end of the line) are removed here, so a backslash
//    in a comment does not join the next line to it (ParameterHandler joins
//    a line ending in '\' with the next before it strips comments);
//  - 'subsection'/'end' must balance: the message names the line;
//  - a file that sets nothing (empty, only comments) is refused: it would
//    run the built-in default model; a JSON one must be an object.
// Everything is a hand-written scan, linear in the file's length (no
// std::regex, whose matcher recurses once per character and overflows the
// stack on lines of ~26,000 characters).
#ifndef poundfe_base_input_text_h
#define poundfe_base_input_text_h

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>

namespace poundfe
{
  /// Largest input file, bytes (1 GiB: a record of 10^7 samples is ~150 MB).
  constexpr std::uintmax_t max_input_bytes = std::uintmax_t(1) << 30;

  /// Longest line of an input file, characters (1 MiB: a list of ~10^5
  /// values on one line).
  constexpr std::size_t max_line_length = std::size_t(1) << 20;

  /// Throws InputError (naming `file` and `parameter`, calling the file
  /// `what`) unless `file` is a regular file of at most max_input_bytes.
  /// Nothing is opened.
  void check_input_file(const std::string &file, const std::string &what,
                        const std::string &parameter = "");

  /// The file's text: checked by check_input_file, without a NUL byte or a
  /// line longer than max_line_length, a byte-order mark dropped, every line
  /// end ("\r\n", "\r\r\n" or "\r") made "\n". Throws InputError.
  std::string read_input_text(const std::string &file, const std::string &what = "parameter file",
                              const std::string &parameter = "");

  /// What identifies the contents of an input file named by a parameter
  /// file (a record, a mesh, a force table, ...): "<size> bytes, FNV-1a
  /// <16 hex digits>" of its bytes, read as read_input_text reads them (a
  /// regular file of at most max_input_bytes, nothing else opened), or
  /// "(...)" saying why there are none (no such file, a FIFO, ...). Never
  /// throws: the reader that uses the file reports its faults.
  std::string input_file_digest(const std::string &file);

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

  /// Deepest nesting of objects and arrays a JSON file may have.
  constexpr unsigned int max_json_depth = 64;

  /// Brackets balanced outside strings, nested at most max_json_depth.
  /// Throws InputError naming `file`, the line and `parameter`.
  void check_json_structure(const std::string &file, const std::string &text,
                            const std::string &parameter = "");

  /// read_input_text and check_json_structure: a JSON file safe to parse.
  std::string read_json_text(const std::string &file, const std::string &what,
                             const std::string &parameter = "");

  /// Check a JSON parameter file's text: a non-empty object at the top, and
  /// check_json_structure. Throws InputError naming `file` and the line.
  void check_json_text(const std::string &file, const std::string &text);
} // namespace poundfe

#endif
