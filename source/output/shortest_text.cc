// std::to_chars's shortest round-trip text of a double from Dragonbox's
// digits (shortest_text.h). libfmt is compiled into this file alone
// (FMT_HEADER_ONLY, CMakeLists.txt), so that the digits are an inlined call
// and no other file's command line changes.
#include <poundfe/output/shortest_text.h>

#include <fmt/format.h>

#include <charconv>
#include <cstdint>
#include <cstring>

namespace poundfe
{
  namespace
  {
    /// Writes the two digits of n < 100 at out.
    void
    two_digits(char *out, const unsigned int n)
    {
      std::memcpy(out, fmt::detail::digits2(n), 2);
    }

    /// Writes the four digits of n < 10^4 at out.
    void
    four_digits(char *out, const unsigned int n)
    {
      two_digits(out, n / 100);
      two_digits(out + 2, n % 100);
    }

    /// Writes the eight digits of n < 10^8 at out.
    void
    eight_digits(char *out, const unsigned int n)
    {
      four_digits(out, n / 10000);
      four_digits(out + 4, n % 10000);
    }

    /// Writes n < 10^17 as 17 digits, leading zeros included, at out: no
    /// loop, no branch.
    void
    seventeen_digits(char *out, const std::uint64_t n)
    {
      const std::uint64_t high = n / 100000000; // < 10^9
      out[0]                   = char('0' + high / 100000000);
      eight_digits(out + 1, unsigned(high % 100000000));
      eight_digits(out + 9, unsigned(n % 100000000));
    }

    /// Writes "e", the sign and the exponent (two digits at least) and
    /// returns the end.
    char *
    exponent_text(char *out, const int exponent)
    {
      *out++                   = 'e';
      *out++                   = exponent < 0 ? '-' : '+';
      const unsigned int magnitude = exponent < 0 ? -exponent : exponent;
      if (magnitude < 100)
        {
          two_digits(out, magnitude);
          return out + 2;
        }
      *out = char('0' + magnitude / 100);
      two_digits(out + 1, magnitude % 100);
      return out + 3;
    }
  } // namespace

  char *
  shortest_text(char *out, const double x)
  {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    if ((bits << 1) == 0) // ±0, a common cell
      {
        std::memcpy(out, "-0", 2);
        return bits >> 63 ? out + 2 : (*out = '0', out + 1);
      }
    if (((bits >> 52) & 0x7ff) == 0x7ff) // infinities, NaN
      return std::to_chars(out, out + shortest_text_room, x).ptr;

    const auto decimal = fmt::detail::dragonbox::to_decimal(x);
    const int  k       = fmt::detail::count_digits(decimal.significand); // 1 to 17
    const int  e       = decimal.exponent; // x = ±significand 10^e
    const int  scientific_exponent = e + k - 1;
    const int  scientific_length =
      k + (k > 1) + 2 + (scientific_exponent <= -100 || scientific_exponent >= 100 ? 3 : 2);
    const int plain_length = e >= 0 ? k + e : (-e < k ? k + 1 : 2 - e);
    const bool plain       = plain_length <= scientific_length;
    if (plain && e > 0 && k + e > 15)
      return std::to_chars(out, out + shortest_text_room, x).ptr; // may exceed 2^53: exact integer

    // digits[0, k) the significand; the blocks below copy 24 bytes of it
    char all_digits[48];
    seventeen_digits(all_digits, decimal.significand);
    const char *const digits = all_digits + 17 - k;
    char  text[80];
    char *p = text;
    if (bits >> 63)
      *p++ = '-';
    if (!plain)
      {
        p[0] = digits[0];
        p[1] = '.';
        std::memcpy(p + 2, digits + 1, 24);
        p = exponent_text(p + (k > 1 ? k + 1 : 1), scientific_exponent);
      }
    else if (e >= 0) // digits, then e <= 5 zeros
      {
        std::memcpy(p, digits, 24);
        std::memcpy(p + k, "00000000", 8);
        p += k + e;
      }
    else if (-e < k) // digits, point, digits
      {
        std::memcpy(p, digits, 24);
        std::memcpy(p + k + e + 1, digits + k + e, 24);
        p[k + e] = '.';
        p += k + 1;
      }
    else // "0.", -e - k <= 3 zeros, digits
      {
        std::memcpy(p, "0.000000", 8);
        std::memcpy(p + 2 - e - k, digits, 24);
        p += 2 - e;
      }
    std::memcpy(out, text, shortest_text_room);
    return out + (p - text);
  }
} // namespace poundfe
