// printf's %.{p}g text (opensees/opensees_recorder.h), which OpenSees's
// recorders write with setprecision(p): write_precision_text gives
// std::to_chars(general, p)'s text exactly, and that text is printf's
// (glibc's snprintf, the reference: correctly rounded, ties to even on the
// exact binary value). Drawn so that every branch is taken: normal numbers
// over 60 decades, short decimals (k / 1000, whose scaled value is near an
// integer), dyadic numbers with exact ties at some precision (k / 2^j),
// integers, numbers next to powers of ten (the exponent's estimate and the
// carry to 10^p), both signs, each precision from 1 to 17 and, every seventh
// number, -1, 9 or 19 (outside 1-17 to_chars decides), and the non-finite values and zeros. Any
// difference is a bug: the comparison is of the texts.
#include <poundfe/opensees/opensees_recorder.h>

#include <boost/test/unit_test.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

using namespace poundfe::opensees;

namespace
{
  /// Numbers of the kinds above, 4 * 10^5 of them.
  std::vector<double>
  numbers_to_write()
  {
    std::mt19937_64                  random(46);
    std::normal_distribution<double> normal;
    std::vector<double> x{0.0, -0.0, INFINITY, -INFINITY, std::nan(""), 5e-324, 1e-310,
                          1.7976931348623157e308, 0.5, 2.5, 0.125, 1e22, 1e23, 9.3, 0.3};
    for (int i = 0; x.size() < 400000; ++i)
      {
        const double sign = random() % 2 ? 1.0 : -1.0;
        switch (i % 5)
          {
            case 0:
              x.push_back(sign * normal(random) * std::pow(10.0, int(random() % 60) - 30));
              break;
            case 1:
              x.push_back(sign * double(random() % 100000) / 1000);
              break;
            case 2:
              x.push_back(sign * std::ldexp(double(random() % (1u << 20)), -int(random() % 40)));
              break;
            case 3:
              x.push_back(sign * double(random() % 100000000000ull));
              break;
            default:
              {
                const double p = std::pow(10.0, int(random() % 50) - 25);
                const double s = std::nextafter(p, random() % 2 ? 0.0 : INFINITY);
                x.push_back(sign * (random() % 3 == 0 ? s : random() % 2 ? 0.95 * p : 9.5 * p));
              }
          }
      }
    return x;
  }
} // namespace

BOOST_AUTO_TEST_CASE(precision_text_is_printf_text)
{
  std::size_t to_chars_differs = 0, printf_differs = 0, checked = 0;
  const std::vector<double> x = numbers_to_write();
  for (std::size_t i = 0; i < x.size(); ++i)
    for (const int p : {int(i % 17) + 1, int(i % 7) == 0 ? int(i % 3) * 10 - 1 : 16})
      {
        char       got[64], expected[64], printed[64];
        const auto end = write_precision_text(got, x[i], p);
        BOOST_REQUIRE(std::size_t(end - got) <= precision_text_room(p));
        const std::string text(got, end);
        const auto e = std::to_chars(expected, expected + sizeof expected, x[i],
                                     std::chars_format::general, p);
        to_chars_differs += text != std::string(expected, e.ptr);
        if (p >= 0 && std::isfinite(x[i]))
          {
            std::snprintf(printed, sizeof printed, "%.*g", p, x[i]);
            printf_differs += text != printed;
          }
        ++checked;
      }
  BOOST_TEST_MESSAGE(checked << " texts compared");
  BOOST_TEST(to_chars_differs == 0u);
  BOOST_TEST(printf_differs == 0u);
}
