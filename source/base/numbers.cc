#include <poundfe/base/numbers.h>

#include <sstream>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace poundfe
{
  namespace
  {
    std::string_view
    trimmed(std::string_view text)
    {
      const auto first = text.find_first_not_of(" \t\r\n");
      if (first == std::string_view::npos)
        return {};
      return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
    }
  } // namespace

  std::optional<double>
  parse_number(std::string_view text, const Exponent exponent)
  {
    text = trimmed(text);
    // strtod needs a terminated string; a number longer than this is not one
    // a person wrote, and the copy keeps long fields (26,000 characters) safe.
    if (text.empty() || text.size() > 64)
      return std::nullopt;
    char buffer[65];
    for (std::size_t i = 0; i < text.size(); ++i)
      {
        const char c = text[i];
        if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.' ||
              c == 'e' || c == 'E' ||
              (exponent == Exponent::e_or_fortran_d && (c == 'd' || c == 'D'))))
          return std::nullopt; // also no "inf", "nan", hexadecimal or locale forms
        buffer[i] = (c == 'd' || c == 'D') ? 'e' : c;
      }
    buffer[text.size()] = '\0';
    char        *end = nullptr;
    const double x   = std::strtod(buffer, &end); // overflow: inf, refused below
    if (end != buffer + text.size() || !std::isfinite(x))
      return std::nullopt;
    return x;
  }

  std::optional<unsigned long>
  parse_count(std::string_view text, const unsigned long max)
  {
    text = trimmed(text);
    unsigned long n = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || n > max)
      return std::nullopt;
    return n;
  }

  std::istream &
  read_number(std::istream &in, double &x)
  {
    std::string field;
    if (in >> field)
      {
        const std::optional<double> value = parse_number(field);
        if (value)
          x = *value;
        else
          in.setstate(std::ios::failbit);
      }
    return in;
  }

  std::istream &
  read_number(std::istream &in, unsigned int &n)
  {
    std::string field;
    if (in >> field)
      {
        const std::optional<unsigned long> value =
          parse_count(field, std::numeric_limits<unsigned int>::max());
        if (value)
          n = *value;
        else
          in.setstate(std::ios::failbit);
      }
    return in;
  }

  std::string
  count_text(const double n)
  {
    if (!std::isfinite(n))
      return "unboundedly many";
    if (std::abs(n) < 1e15)
      return std::to_string(static_cast<long long>(std::llround(n)));
    return number_text(n);
  }

  std::string
  number_text(const double x)
  {
    char buffer[32];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, x).ptr);
  }
  std::string
  rounded(const double x, const int digits)
  {
    std::ostringstream s;
    s.precision(digits);
    s << x;
    return s.str();
  }
} // namespace poundfe
