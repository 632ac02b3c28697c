// The shortest text of a double that reads back to it, in exactly the bytes
// of std::to_chars(char*, char*, double) (C++17 [charconv.to.chars]: the
// fewest significant digits that round-trip, the nearest such digits to the
// value, then plain or scientific form, whichever is shorter, plain on a
// tie; exponents of two digits at least), but about twice as fast as
// libstdc++'s Ryu.
//
// The digits are Dragonbox's (Jeon, "Dragonbox: A new floating-point
// binary-to-decimal conversion algorithm", 2020), through libfmt 9
// (fmt::detail::dragonbox::to_decimal), which gives the same shortest, nearest
// digits as Ryu (Adams, PLDI 2018); the layout here copies them in fixed-size
// blocks. Infinities, NaN and plain integers of 16 digits and more
// (whose plain text is the exact integer, not the shortest digits padded
// with zeros) go to std::to_chars itself.
#ifndef poundfe_output_shortest_text_h
#define poundfe_output_shortest_text_h

#include <cstddef>

namespace poundfe
{
  /// Room `shortest_text` needs after `out`: the longest text is 24
  /// characters ("-2.2250738585072014e-308"), and the text is moved in a
  /// block of this size.
  constexpr std::size_t shortest_text_room = 32;

  /// Writes std::to_chars's text of x at `out`, which has shortest_text_room
  /// characters of room (those after the text are overwritten), and returns
  /// the end of the text.
  char *
  shortest_text(char *out, double x);
} // namespace poundfe

#endif
