// Where parameters came from, for messages and relative paths, and the few
// checks every section needs (positive, non-negative, "one or one per").
// Each module checks its own section with these (deal.II step-33 style);
// the aggregate (input/input_parameters.h) fills the line index.
#ifndef poundfe_base_input_file_h
#define poundfe_base_input_file_h

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace poundfe
{
  /// An input file a parameter file names: the entry that names it
  /// ("Ground motion/Record/File"), what it is ("record file") and its
  /// name as written there (relative to the parameter file). Each module
  /// lists those of its section beside the declaration of the entries
  /// (`input_files()`), so that results can be tied to their contents
  /// (output/output_directory.h: resume_file).
  struct NamedInputFile
  {
    std::string entry;
    std::string what;
    std::string name;
    std::string path; // `name` resolved (InputFile::resolve); empty until then
  };

  struct InputFile
  {
    std::string file;
    std::string directory; // relative input paths are resolved against it
    /// Line of "set <section/.../entry>" of each entry written (0: a JSON key, a --set).
    std::map<std::string, int> lines;

    /// Line of "set <path>" in the file (0 when unknown, e.g. JSON input).
    int line_of(const std::string &path) const;
    /// Path of an input file named in the parameter file.
    std::string resolve(const std::string &relative) const;

    /// InputError naming the file, the line of `path` and `path`.
    [[noreturn]] void fail(const std::string &path, const std::string &problem) const;
    /// The text fail() would throw, for a warning: where a run still makes
    /// sense, an entry without effect is reported rather than refused.
    std::string warning(const std::string &path, const std::string &problem) const;
    void positive(const std::string &path, double value) const;
    void non_negative(const std::string &path, double value) const;
    /// |value| <= bound, else an InputError that says why the bound is
    /// there (`why`: what lies beyond it, e.g. "beyond any building").
    void at_most(const std::string &path, double value, double bound, const std::string &unit,
                 const std::string &why) const;
    /// One value for all or n values, each positive (or >= 0 with allow_zero).
    void list(const std::string &path, const std::vector<double> &values, std::size_t n,
              bool allow_zero, const std::string &what) const;
    /// A list of levels, ratios or periods: a value given twice is refused
    /// (it would be run or reported twice, or mean a typo).
    void distinct(const std::string &path, const std::vector<double> &values) const;
  };

  /// `text` without its leading and trailing blanks (every character `>>`
  /// skips: space, tab, CR, LF, vertical tab, form feed).
  std::string trimmed(const std::string &text);
} // namespace poundfe

#endif
