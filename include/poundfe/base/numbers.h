// Numbers in input and in messages, one way everywhere.
//
// Reading: a field is a number only if the whole field is one (strtod's
// syntax: "15mm", "0.02.5", "2e-2e" and "1e-2x" are refused, not read as
// their numeric prefix) and it is finite. AT2 headers written by Fortran
// programs use a D exponent ("2.0D-02", ".2D-01"); the readers of such
// files ask for it.
//
// Writing: the shortest text that reads back to the same double
// (std::to_chars), so a message shows -1e-300, 0.99999999999 and 1e+308,
// never "-0.000000", "1.000000" or 309 digits (std::to_string's %f).
#ifndef poundfe_base_numbers_h
#define poundfe_base_numbers_h

#include <istream>
#include <optional>
#include <string>
#include <string_view>

namespace poundfe
{
  /// The largest size a stiffness, damping, mass or force of the model may
  /// have: the eigensolvers and Newton's norms square such numbers, so past
  /// 1e150 they overflow to inf (an absurd 1e308 came out as a damping-modes
  /// problem or a NaN in Newton); no structure comes near it.
  inline constexpr double largest_model_value = 1e150;

  /// The largest length of a building's part (a storey height, a bay
  /// width, a slab side): 10 km is beyond any building, and a model's
  /// coordinates, lengths cubed and areas stay far from overflow below it.
  inline constexpr double largest_building_length = 1e4;

  /// The largest coordinate of a building's plan position on the site:
  /// site coordinates (e.g. UTM northings, below 1e7 m) stay below it.
  inline constexpr double largest_site_coordinate = 1e7;

  /// The fewest steps of a double (ulps) of the largest coordinate that a
  /// gap between buildings must span: below that, rounding the positions
  /// closes or opens the gap by a visible fraction of it.
  inline constexpr double fewest_gap_ulps = 1e6;

  enum class Exponent
  {
    e,         // 1.5e-3
    e_or_fortran_d // also 1.5D-3 and 1.5d-3
  };

  /// The whole of `text` (blanks around it allowed) as a finite double;
  /// nothing if any character is not part of the number or it overflows.
  std::optional<double> parse_number(std::string_view text, Exponent exponent = Exponent::e);

  /// The whole of `text` as a whole number in [0, max]; nothing otherwise.
  std::optional<unsigned long> parse_count(std::string_view text, unsigned long max);

  /// The next blank-separated field of `in` as a number (parse_number):
  /// like `in >> x`, but a field that is not wholly a finite number fails
  /// the stream instead of being read up to its first bad character.
  std::istream &read_number(std::istream &in, double &x);
  /// The same for a whole number >= 0 (no sign, no fraction, no trailing text).
  std::istream &read_number(std::istream &in, unsigned int &n);

  /// Shortest round-trip text of x: "0.015", "-1e-300", "1e+308", "inf", "nan".
  std::string number_text(double x);

  /// x to `digits` significant digits, for the console ("0.0151", "2.5e-05").
  std::string rounded(double x, int digits = 3);

  /// A count that may be huge: "100000000" below 10^15, "1e+311" above,
  /// "unboundedly many" when infinite.
  std::string count_text(double n);
} // namespace poundfe

#endif
