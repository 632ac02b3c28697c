// What the reader says of a path that names no declared entry or
// subsection, in the same words whether the path was written in a parameter
// file (`set Tim step = 1` inside `subsection Time integration`) or given
// as an override (`--set "Time integration/Tim step=1"`, Python's
// overrides=):
//   No entry with name <Tim step> in 'Time integration' (did you mean 'Time step'?)
//   There is no such subsection to be entered: Buildin 1 (did you mean 'Building 1'?)
// The suggestions are the declared names of the same subsection closest to
// the written one by Levenshtein's edit distance (case ignored), at most
// max(1, length / 3) edits apart, best first; failing those, for an entry,
// the paths of the other subsections that declare an entry of that very
// name (`Model/Time step` -> 'Time integration/Time step').
#ifndef poundfe_input_unknown_path_h
#define poundfe_input_unknown_path_h

#include <string>
#include <vector>

namespace poundfe
{
  /// The problem with `path` ("A/B/Entry", or "A/B" when
  /// `names_subsection`) given the paths of every declared entry
  /// ("A/B/Entry", in declaration order).
  std::string unknown_path_problem(const std::vector<std::string> &declared, const std::string &path,
                                   bool names_subsection);

  /// Levenshtein's edit distance between `a` and `b`, case ignored.
  std::size_t edit_distance(const std::string &a, const std::string &b);
} // namespace poundfe

#endif
