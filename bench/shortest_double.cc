// The shortest round-trip text of a double, four ways, on the same numbers:
// libstdc++'s std::to_chars(double) (Ryu; what the CSV writers use,
// output/number_text.h), libfmt's fmt::format_to("{}") (Dragonbox, Jeon 2020,
// with fmt's own choice of fixed or exponent form) and libfmt's Dragonbox
// digits laid out by std::to_chars's rule (C++17 [charconv.to.chars]: the
// fewer characters of plain and scientific, plain on a tie; exponents of at
// least two digits), which is what the CSV writer would have to do to keep
// every byte of its files, and poundfe::shortest_text (output/shortest_text.h:
// the same rule with the copies in fixed-size blocks), which the CSV writers
// use. It counts the texts that differ from std::to_chars's and times each
// way, best of the repeats.
//
//   build/poundfe-bench-shortest [repeats [to_chars|fmt|dragonbox|digits|poundfe]]
//   build/poundfe-bench-shortest --check N
//   build/poundfe-bench-shortest --help
//
// Anything else (a count that is not a whole number above 0, an unknown way,
// more arguments) prints the usage and exits 1.
//
// --check compares poundfe::shortest_text's text with std::to_chars's on N
// doubles of random bits (every exponent, subnormals, NaNs and infinities)
// and on edge values (zeros, powers of 2 and 10 and their neighbours, the
// integers around 2^53, the limits), and exits 1 on the first difference.
//
// With a way named, it only times that one (for valgrind --tool=callgrind:
// the inclusive count of best_ns_per_number over the numbers is the
// instructions a number).
//
// The numbers: the times of a run's rows (i * 5e-4: short texts), responses
// (sums of sines with 17 significant digits) and values of every magnitude
// from 1e-12 to 1e6, both signs, and zeros, as in a run's CSV files.
#include <poundfe/output/shortest_text.h>

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace
{
  std::vector<double>
  sample_numbers(const std::size_t n)
  {
    std::vector<double> x(n);
    std::uint64_t       state = 88172645463325252ull; // xorshift64
    auto next = [&state]() {
      state ^= state << 13;
      state ^= state >> 7;
      state ^= state << 17;
      return state;
    };
    for (std::size_t i = 0; i < n; ++i)
      switch (i % 4)
        {
          case 0: x[i] = (i / 4) * 5e-4; break;
          case 1: x[i] = 0.0123 * std::sin(0.37 * i) + 0.004 * std::sin(2.9 * i); break;
          case 2:
            {
              const double mantissa = double(next() >> 11) / double(1ull << 53);
              const int    exponent = int(next() % 19) - 12;
              x[i] = (next() & 1 ? -1 : 1) * mantissa * std::pow(10.0, exponent);
              break;
            }
          default: x[i] = (i % 16 == 3) ? 0.0 : -1.5e3 * std::cos(0.011 * i); break;
        }
    return x;
  }

  /// Dragonbox's shortest digits in std::to_chars's plain or scientific form.
  char *
  dragonbox_as_to_chars(char *out, const double x)
  {
    if (x == 0)
      {
        if (std::signbit(x))
          *out++ = '-';
        *out++ = '0';
        return out;
      }
    const auto decimal = fmt::detail::dragonbox::to_decimal(x);
    if (x < 0)
      *out++ = '-';
    char      digits[20];
    const int k = std::to_chars(digits, digits + 20, decimal.significand).ptr - digits;
    const int e = decimal.exponent, scientific_exponent = e + k - 1;
    const int exponent_digits = std::abs(scientific_exponent) >= 100 ? 3 : 2;
    const int scientific = k + (k > 1) + 2 + exponent_digits;
    const int plain      = e >= 0 ? k + e : (-e < k ? k + 1 : 2 - e);
    if (plain <= scientific)
      {
        if (e >= 0)
          {
            out = std::copy(digits, digits + k, out);
            return std::fill_n(out, e, '0');
          }
        if (-e < k)
          {
            out    = std::copy(digits, digits + k + e, out);
            *out++ = '.';
            return std::copy(digits + k + e, digits + k, out);
          }
        *out++ = '0';
        *out++ = '.';
        out    = std::fill_n(out, -e - k, '0');
        return std::copy(digits, digits + k, out);
      }
    *out++ = digits[0];
    if (k > 1)
      {
        *out++ = '.';
        out    = std::copy(digits + 1, digits + k, out);
      }
    *out++ = 'e';
    *out++ = scientific_exponent < 0 ? '-' : '+';
    const int magnitude = std::abs(scientific_exponent);
    if (magnitude < 10)
      *out++ = '0';
    return std::to_chars(out, out + 4, magnitude).ptr;
  }

  /// Dragonbox's digits alone (significand and exponent as binary, no
  /// text): what the layout above adds to them.
  char *
  dragonbox_digits_only(char *out, const double x)
  {
    const auto decimal = fmt::detail::dragonbox::to_decimal(x == 0 ? 1.0 : x);
    std::memcpy(out, &decimal.significand, 8);
    std::memcpy(out + 8, &decimal.exponent, 4);
    return out + 12;
  }

  char *
  with_to_chars(char *out, const double x)
  {
    return std::to_chars(out, out + 32, x).ptr;
  }

  char *
  with_fmt(char *out, const double x)
  {
    return fmt::format_to(out, "{}", x);
  }

  char *
  with_poundfe(char *out, const double x)
  {
    return poundfe::shortest_text(out, x);
  }

  /// The edge values of --check: zeros, the limits, powers of 2 and 10 and
  /// the doubles next to them, integers around 2^53 and 10^15..10^17.
  std::vector<double>
  edge_numbers()
  {
    std::vector<double> x{0.0,
                          std::numeric_limits<double>::denorm_min(),
                          std::numeric_limits<double>::min(),
                          std::numeric_limits<double>::max(),
                          std::numeric_limits<double>::epsilon(),
                          std::numeric_limits<double>::infinity(),
                          std::numeric_limits<double>::quiet_NaN()};
    for (int p = -1074; p <= 1023; ++p)
      x.push_back(std::ldexp(1.0, p));
    for (int p = -324; p <= 308; ++p)
      x.push_back(std::strtod(("1e" + std::to_string(p)).c_str(), nullptr));
    for (double base : {std::ldexp(1.0, 53), 1e15, 1e16, 1e17, 1e21, 1e22, 1e23})
      for (int i = -1000; i <= 1000; ++i)
        x.push_back(base + i * (base / 1e15));
    const std::size_t n = x.size();
    for (std::size_t i = 0; i < n; ++i)
      {
        x.push_back(std::nextafter(x[i], 0.0));
        x.push_back(std::nextafter(x[i], HUGE_VAL));
      }
    for (std::size_t i = 0, m = x.size(); i < m; ++i)
      x.push_back(-x[i]);
    return x;
  }

  /// std::to_chars's text against shortest_text's for x; prints a
  /// difference.
  bool
  same_text(const double x)
  {
    char       a[64], b[64];
    const auto end_a = std::to_chars(a, a + sizeof a, x).ptr;
    const auto end_b = poundfe::shortest_text(b, x);
    if (end_a - a == end_b - b && std::memcmp(a, b, end_a - a) == 0)
      return true;
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    std::printf("bits %016llx: shortest_text %.*s, to_chars %.*s\n", (unsigned long long)bits,
                int(end_b - b), b, int(end_a - a), a);
    return false;
  }

  int
  check(const unsigned long long n_random)
  {
    const std::vector<double> edges = edge_numbers();
    for (const double x : edges)
      if (!same_text(x))
        return 1;
    std::uint64_t state = 0x9e3779b97f4a7c15ull; // splitmix64
    for (unsigned long long i = 0; i < n_random; ++i)
      {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z               = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z               = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        z ^= z >> 31;
        double x;
        std::memcpy(&x, &z, sizeof x);
        if (!same_text(x))
          return 1;
      }
    std::printf("shortest_text = std::to_chars on %zu edge values and %llu of random bits\n",
                edges.size(), n_random);
    return 0;
  }

  template <typename Format>
  std::string
  all_text(const std::vector<double> &x, Format format)
  {
    std::string text(x.size() * 32, '\0');
    char       *out = text.data();
    for (const double value : x)
      {
        out    = format(out, value);
        *out++ = ',';
      }
    text.resize(out - text.data());
    return text;
  }

  template <typename Format>
  double
  best_ns_per_number(const std::vector<double> &x, Format format, const int repeats)
  {
    std::vector<char> buffer(x.size() * 32);
    double            best = 1e300;
    for (int r = 0; r < repeats; ++r)
      {
        const auto start = std::chrono::steady_clock::now();
        char      *out   = buffer.data();
        for (const double value : x)
          {
            out    = format(out, value);
            *out++ = ',';
          }
        const auto stop = std::chrono::steady_clock::now();
        if (out == buffer.data()) // keeps the loop
          std::abort();
        best = std::min(best, std::chrono::duration<double, std::nano>(stop - start).count());
      }
    return best / x.size();
  }

  std::size_t
  differing_texts(const std::vector<double> &x, char *(*format)(char *, double))
  {
    std::size_t n = 0;
    for (const double value : x)
      {
        char a[32], b[32];
        const std::string reference(a, with_to_chars(a, value));
        const std::string other(b, format(b, value));
        if (reference != other)
          {
            if (n < 3)
              std::printf("  e.g. %s against to_chars's %s\n", other.c_str(), reference.c_str());
            ++n;
          }
      }
    return n;
  }
  constexpr const char *usage =
    "usage: poundfe-bench-shortest [REPEATS [WAY]]\n"
    "       poundfe-bench-shortest --check N\n"
    "Times the shortest text of 2^20 doubles, best of REPEATS runs (default 20),\n"
    "every way or only WAY: to_chars, fmt, dragonbox, digits or poundfe.\n"
    "--check N compares poundfe::shortest_text with std::to_chars on N doubles\n"
    "of random bits and on edge values; exit 1 on the first difference.\n";
  constexpr unsigned long long max_repeats = 1000000;

  using Format = char *(*)(char *, double);

  /// The whole of `text` as a whole number above 0, or 0 when it is not one
  /// (a sign, other characters, nothing or too large).
  unsigned long long
  positive_count(const std::string &text)
  {
    unsigned long long n   = 0;
    const char *const  end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, n);
    return error == std::errc() && stop == end ? n : 0;
  }

  int
  refuse(const std::string &why)
  {
    std::fprintf(stderr, "poundfe-bench-shortest: %s\n%s", why.c_str(), usage);
    return 1;
  }

  /// The way called `way`, or nullptr.
  Format
  way_named(const std::string &way)
  {
    return way == "to_chars"  ? with_to_chars :
           way == "fmt"       ? with_fmt :
           way == "dragonbox" ? dragonbox_as_to_chars :
           way == "digits"    ? dragonbox_digits_only :
           way == "poundfe"   ? with_poundfe :
                                nullptr;
  }

  /// Every way on the sample: how many texts differ from std::to_chars's,
  /// that the texts read back, and the best time a number of each.
  int
  compare_all(const int repeats)
  {
    const std::vector<double> x = sample_numbers(1 << 20);
    std::printf("%zu numbers, best of %d\n", x.size(), repeats);
    std::printf("fmt::format_to(\"{}\"): %zu texts differ from std::to_chars's\n",
                differing_texts(x, with_fmt));
    std::printf("Dragonbox in to_chars's layout: %zu texts differ from std::to_chars's\n",
                differing_texts(x, dragonbox_as_to_chars));
    std::printf("poundfe::shortest_text: %zu texts differ from std::to_chars's\n",
                differing_texts(x, with_poundfe));
    // every text must read back to its double
    for (const double value : x)
      {
        char         text[32];
        char *const  end  = dragonbox_as_to_chars(text, value);
        double       back = 0;
        std::from_chars(text, end, back);
        if (std::memcmp(&back, &value, sizeof back) != 0)
          {
            std::printf("round trip failed\n");
            return 1;
          }
      }
    if (all_text(x, with_to_chars) != all_text(x, dragonbox_as_to_chars))
      std::printf("the texts of the whole sample differ\n");
    std::printf("std::to_chars                  %6.1f ns a number\n",
                best_ns_per_number(x, with_to_chars, repeats));
    std::printf("fmt::format_to(\"{}\")           %6.1f ns a number\n",
                best_ns_per_number(x, with_fmt, repeats));
    std::printf("Dragonbox in to_chars's layout %6.1f ns a number\n",
                best_ns_per_number(x, dragonbox_as_to_chars, repeats));
    std::printf("poundfe::shortest_text         %6.1f ns a number\n",
                best_ns_per_number(x, with_poundfe, repeats));
    return 0;
  }
} // namespace

int
main(int argc, char **argv)
{
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h"))
    {
      std::fputs(usage, stdout);
      return 0;
    }
  if (!args.empty() && args[0] == "--check")
    {
      if (args.size() != 2 || positive_count(args[1]) == 0)
        return refuse("--check needs one count of random doubles, a whole number above 0");
      return check(positive_count(args[1]));
    }
  if (args.size() > 2)
    return refuse("at most two arguments, REPEATS and WAY");
  const unsigned long long repeats = args.empty() ? 20 : positive_count(args[0]);
  if (repeats == 0 || repeats > max_repeats)
    return refuse("REPEATS must be a whole number from 1 to " + std::to_string(max_repeats) +
                  ", not \"" + args[0] + "\"");
  if (args.size() < 2)
    return compare_all(int(repeats));
  const Format format = way_named(args[1]);
  if (format == nullptr)
    return refuse("no way \"" + args[1] + "\"");
  std::printf("%s %.1f ns a number\n", args[1].c_str(),
              best_ns_per_number(sample_numbers(1 << 20), format, int(repeats)));
  return 0;
}
