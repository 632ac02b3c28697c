// Site hazard (hazard/site_hazard.h) against independent references:
//   - Cornell's intensity and Trifunac-Brady's acceleration of the thesis's
//     three historical events near the Memve'ele site, against values worked
//     out by hand to one decimal (the precision of the thesis's table);
//   - the haversine central angle against the worked example of Williams'
//     Aviation Formulary (LAX to JFK, 0.623585 rad = 2144 nm);
//   - the Gumbel maximum-likelihood fit recovering the parameters of a large
//     synthetic Gumbel sample within 3 asymptotic standard errors (closed
//     form: Var u = 1.1087 s^2/n, Var s = 0.6079 s^2/n), also with the lower
//     40 % of the sample censored;
//   - Aki's b of a synthetic exponential sample within 3 standard errors;
//   - return periods against their definitions (F(x_T) = 1 - 1/T; 1/rate);
//   - the fragility x hazard integral against the closed form of a power-law
//     hazard and a lognormal fragility (Cornell et al. 2002);
//   - the catalogue reader's messages (file, line) on bad rows, and the
//     fragility summary reader on the format `poundfe fragility` writes.
#include <poundfe/input/input_parameters.h>
#include <poundfe/hazard/site_hazard.h>
#include <poundfe/hazard/catalogue.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/excitation/ground_motion.h>
#include <poundfe/output/json_writer.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "test_utilities.h"

using namespace poundfe;
using poundfe_test::temporary_file;

namespace
{
  const double pi = 3.14159265358979323846;

  /// The line an InputError from reading `contents` as a catalogue names.
  int
  catalogue_error_line(const std::string &contents)
  {
    const std::string file = temporary_file("bad.csv", contents);
    try
      {
        read_catalogue(file);
      }
    catch (const InputError &e)
      {
        BOOST_TEST(e.file() == file);
        BOOST_TEST_MESSAGE("catalogue error: " << e.what());
        std::remove(file.c_str());
        return e.line();
      }
    std::remove(file.c_str());
    return -1;
  }
} // namespace

BOOST_AUTO_TEST_CASE(thesis_historical_events)
{
  // Worked by hand (the thesis's table gives one decimal):
  //   M 4.4, r 79.4 km:  ln r = 4.3745; I = 8 + 6.60 - 10.936 = 3.664 -> 3.7;
  //                      log10 A = 0.014 + 1.0991 = 1.1131 -> A = 12.98 -> 13.0 cm/s^2
  //   M 5.7, r 119.3 km: ln r = 4.7816; I = 8 + 8.55 - 11.954 = 4.596 -> 4.6;
  //                      log10 A = 0.014 + 1.3788 = 1.3928 -> A = 24.70 -> 24.7 cm/s^2
  //   M 5.1, r 280 km:   ln r = 5.6348; I = 8 + 7.65 - 14.087 = 1.563 -> 1.6;
  //                      log10 A = 0.014 + 0.4689 = 0.4829 -> A = 3.04 -> 3.0 cm/s^2
  // Tolerance 0.05: half a unit of the table's last digit.
  struct Row
  {
    double magnitude, distance, intensity, acceleration;
  };
  for (const Row &row : {Row{4.4, 79.4, 3.7, 13.0}, Row{5.7, 119.3, 4.6, 24.7},
                         Row{5.1, 280.0, 1.6, 3.0}})
    {
      const double I = cornell_intensity(row.magnitude, row.distance);
      BOOST_TEST(std::abs(I - row.intensity) <= 0.05, "M " << row.magnitude << ": I = " << I);
      const double A = trifunac_brady_acceleration(I);
      BOOST_TEST(std::abs(A - row.acceleration) <= 0.05, "M " << row.magnitude << ": A = " << A);
      BOOST_TEST(trifunac_brady_intensity(A) == I, boost::test_tools::tolerance(1e-12));
    }
}

BOOST_AUTO_TEST_CASE(great_circle_lax_jfk)
{
  // Ed Williams, Aviation Formulary V1.46, worked example: LAX (33 57'N,
  // 118 24'W) to JFK (40 38'N, 73 47'W), d = 0.623585 rad = 2144 nm on a
  // sphere. Tolerance 5e-7 rad: half a unit of the printed sixth decimal.
  const GeographicPoint lax{33 + 57 / 60.0, -(118 + 24 / 60.0)};
  const GeographicPoint jfk{40 + 38 / 60.0, -(73 + 47 / 60.0)};
  const double          d = central_angle(lax, jfk);
  BOOST_TEST(std::abs(d - 0.623585) <= 5e-7, "d = " << d);
  BOOST_TEST(std::round(d * 180 * 60 / pi) == 2144.0); // nautical miles (1' of arc)
  BOOST_TEST(great_circle_distance_km(lax, jfk) == 6371.0 * d, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(great_circle_distance_km(jfk, lax) == great_circle_distance_km(lax, jfk),
             boost::test_tools::tolerance(1e-15));
  // one degree of a meridian, and a short distance (where the cosine rule
  // loses its digits): the arc length R * angle
  BOOST_TEST(great_circle_distance_km({2.0, 10.4}, {3.0, 10.4}) == 6371.0 * pi / 180,
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(great_circle_distance_km({2.4, 10.4}, {2.4, 10.4 + 1e-6}) ==
               6371.0 * std::cos(2.4 * pi / 180) * 1e-6 * pi / 180,
             boost::test_tools::tolerance(1e-8));
}

BOOST_AUTO_TEST_CASE(gumbel_fit_recovers_a_synthetic_sample)
{
  const double       u = 5.0, s = 0.8;
  const unsigned int n = 20000;
  std::mt19937_64                        random(20261123);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<double>                    sample;
  for (unsigned int i = 0; i < n; ++i)
    sample.push_back(u - s * std::log(-std::log(uniform(random)))); // inverse of F
  const GumbelFit fit = fit_gumbel(sample);
  // asymptotic standard errors of the maximum-likelihood estimators
  // (Var u = s^2 (1 + 6 (1 - gamma)^2 / pi^2) / n, Var s = 6 s^2 / (pi^2 n))
  const double gamma = 0.5772156649015329;
  const double se_u  = s * std::sqrt((1 + 6 * std::pow(1 - gamma, 2) / (pi * pi)) / n);
  const double se_s  = s * std::sqrt(6 / (pi * pi) / n);
  BOOST_TEST_MESSAGE("Gumbel: u = " << fit.location << " (" << u << " +- " << se_u
                                    << "), s = " << fit.scale << " (" << s << " +- " << se_s << ")");
  BOOST_TEST(std::abs(fit.location - u) <= 3 * se_u);
  BOOST_TEST(std::abs(fit.scale - s) <= 3 * se_s);
  // the observed information agrees with the expected one (10 %: n is large)
  BOOST_TEST(fit.location_standard_error == se_u, boost::test_tools::tolerance(0.1));
  BOOST_TEST(fit.scale_standard_error == se_s, boost::test_tools::tolerance(0.1));

  // The lower 40 % censored at their largest value, as the years without an
  // event above the minimum intensity are: the same parameters within 3 of
  // the (larger) standard errors of the censored fit.
  std::vector<double> sorted = sample;
  std::sort(sorted.begin(), sorted.end());
  const unsigned int  n_censored = 0.4 * n;
  const double        level      = sorted[n_censored];
  const std::vector<double> upper(sorted.begin() + n_censored, sorted.end());
  const GumbelFit censored = fit_gumbel(upper, n_censored, level);
  BOOST_TEST_MESSAGE("censored: u = " << censored.location << " +- "
                                      << censored.location_standard_error
                                      << ", s = " << censored.scale << " +- "
                                      << censored.scale_standard_error);
  BOOST_TEST(censored.n_censored == n_censored);
  BOOST_TEST(std::abs(censored.location - u) <= 3 * censored.location_standard_error);
  BOOST_TEST(std::abs(censored.scale - s) <= 3 * censored.scale_standard_error);
  BOOST_TEST(censored.scale_standard_error > fit.scale_standard_error);

  BOOST_CHECK_THROW(fit_gumbel({4.0}), std::invalid_argument);
  BOOST_CHECK_THROW(fit_gumbel({4.0, 4.0, 4.0}), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(exponential_recurrence_recovers_b)
{
  const double       b = 1.3, threshold = 2.0, years = 400;
  const unsigned int n = 10000;
  std::mt19937_64                    random(7);
  std::exponential_distribution<double> excess(b);
  std::vector<double>                values{1.0, 0.5}; // below the threshold: not counted
  for (unsigned int i = 0; i < n; ++i)
    values.push_back(threshold + excess(random));
  const ExponentialRecurrence fit = fit_exponential_recurrence(values, threshold, years);
  BOOST_TEST(fit.n_events == n);
  BOOST_TEST(fit.rate_above_threshold == n / years);
  BOOST_TEST(std::abs(fit.b - b) <= 3 * b / std::sqrt(double(n)), "b = " << fit.b);
  BOOST_CHECK_THROW(fit_exponential_recurrence({1.0}, 2.0, 10), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(return_periods_against_their_definitions)
{
  IntensityHazard gumbel;
  gumbel.gumbel.location = 3.1;
  gumbel.gumbel.scale    = 0.7;
  IntensityHazard poisson;
  poisson.model                        = IntensityHazard::Model::poisson;
  poisson.poisson.threshold            = 1.0;
  poisson.poisson.rate_above_threshold = 0.25;
  poisson.poisson.b                    = 1.4;
  for (const double T : {100.0, 144.0, 250.0, 475.0, 2475.0})
    {
      // Gumbel: the annual maximum exceeds x_T with probability 1/T
      const double x = gumbel.intensity_for_return_period(T);
      BOOST_TEST(gumbel_cdf(gumbel.gumbel, x) == 1 - 1 / T, boost::test_tools::tolerance(1e-13));
      BOOST_TEST(gumbel.return_period(x) == T, boost::test_tools::tolerance(1e-10));
      BOOST_TEST(gumbel.annual_rate(x) == -std::log(1 - 1 / T), boost::test_tools::tolerance(1e-12));
      // Poisson: the rate of exceeding x_T is 1/T
      const double y = poisson.intensity_for_return_period(T);
      BOOST_TEST(0.25 * std::exp(-1.4 * (y - 1.0)) == 1 / T, boost::test_tools::tolerance(1e-12));
      BOOST_TEST(poisson.return_period(y) == T, boost::test_tools::tolerance(1e-12));
      BOOST_TEST(poisson.annual_exceedance_probability(y) == 1 - std::exp(-1 / T),
                 boost::test_tools::tolerance(1e-12));
    }
}

BOOST_AUTO_TEST_CASE(fragility_times_power_law_hazard)
{
  // lambda(a) = k0 a^-k, P(F | a) = Phi(ln(a/theta)/beta):
  // lambda_F = k0 theta^-k exp(k^2 beta^2 / 2) (Cornell et al. 2002, eq. 11).
  // Tolerance 1e-8: Simpson's error with steps beta/40 on a Gaussian
  // integrand, and the tail cut 12 beta below the integrand's peak, are far
  // smaller.
  struct Case
  {
    double k0, k, theta, beta;
  };
  for (const Case c : {Case{1e-4, 2.5, 0.4, 0.5}, Case{3e-3, 3.0, 0.25, 0.3},
                       Case{1e-5, 1.2, 1.1, 0.7}})
    {
      const auto   hazard = [&c](const double a) { return c.k0 * std::pow(a, -c.k); };
      const double a_min  = c.theta * std::exp(c.beta * (-c.k * c.beta - 12));
      const double numerical = annual_failure_rate(hazard, a_min, {c.theta, c.beta});
      const double exact = c.k0 * std::pow(c.theta, -c.k) * std::exp(c.k * c.k * c.beta * c.beta / 2);
      BOOST_TEST(numerical == exact, boost::test_tools::tolerance(1e-8));
    }
  // Through the Trifunac-Brady map: a Poisson recurrence in intensity is a
  // power law in PGA, k = b / (0.3 ln 10), k0 = nu0 e^(b x0 + 0.014 b/0.3) (100 g)^-k.
  IntensityHazard poisson;
  poisson.model                        = IntensityHazard::Model::poisson;
  poisson.poisson.threshold            = 1.0;
  poisson.poisson.rate_above_threshold = 0.3;
  poisson.poisson.b                    = 1.5;
  const auto rate_of_pga = [&poisson](const double a_g) { return annual_rate_of_pga(poisson, a_g); };
  const double k  = 1.5 / (0.3 * std::log(10.0));
  const double k0 = 0.3 * std::exp(1.5 * 1.0 + 0.014 * 1.5 / 0.3) *
                    std::pow(100 * standard_gravity, -k);
  const double minimum_pga = trifunac_brady_acceleration(1.0) / 100 / standard_gravity;
  const double numerical   = annual_failure_rate(rate_of_pga, minimum_pga, {0.3, 0.5});
  BOOST_TEST(numerical == k0 * std::pow(0.3, -k) * std::exp(k * k * 0.25 / 2),
             boost::test_tools::tolerance(1e-7));
  BOOST_TEST(probability_in_years(1e-3, 50) == 1 - std::exp(-0.05),
             boost::test_tools::tolerance(1e-14));
}

BOOST_AUTO_TEST_CASE(catalogue_reader)
{
  const std::string good = temporary_file(
    "good.csv", "# illustrative\n"
                "magnitude, date, longitude, latitude, place\n"
                "4.4, 1974-05-12, 10.9, 2.9, somewhere\n"
                "\n"
                "5.7, 1987, 11.3, 1.7, elsewhere\n");
  const std::vector<CatalogueEvent> events = read_catalogue(good);
  std::remove(good.c_str());
  BOOST_TEST(events.size() == 2u);
  BOOST_TEST(events[0].year == 1974);
  BOOST_TEST(events[0].magnitude == 4.4);
  BOOST_TEST(events[0].epicentre.latitude == 2.9);
  BOOST_TEST(events[0].epicentre.longitude == 10.9);
  BOOST_TEST(events[1].line == 5);
  BOOST_TEST(events[1].year == 1987);

  const std::string header = "date,latitude,longitude,magnitude\n";
  BOOST_TEST(catalogue_error_line("date,latitude,magnitude\n1990,2,4\n") == 1); // no longitude
  BOOST_TEST(catalogue_error_line(header + "1990-01-01,2,10,4\n1990-13-01,2,10,4\n") == 3);
  BOOST_TEST(catalogue_error_line(header + "#\n1990,95,10,4\n") == 3);       // latitude
  BOOST_TEST(catalogue_error_line(header + "1990,2,east,4\n") == 2);         // longitude
  BOOST_TEST(catalogue_error_line(header + "1990,2,10\n") == 2);             // a field short
  BOOST_TEST(catalogue_error_line(header + "1990,2,10,12\n") == 2);          // magnitude
  BOOST_TEST(catalogue_error_line(header) == 0);                             // no events
}

BOOST_AUTO_TEST_CASE(fragility_summary_reader)
{
  // The keys `poundfe fragility` writes (reliability/montecarlo.cc, fragility_command).
  JsonWriter json;
  json.begin_object().value("program", "poundfe").value("command", "fragility");
  json.begin_array("curves");
  json.begin_object().value("name", "pounding").value("fitted", true).value("theta_g", 0.31)
    .value("beta", 0.42).end_object();
  json.begin_object().value("name", "drift_0.01").value("fitted", false)
    .value("note", "no failures").end_object();
  json.end_array().end_object();
  const std::string file = temporary_file("fragility.json", json.str());
  const LognormalCurve c = read_fragility_summary(file, "pounding");
  BOOST_TEST(c.theta == 0.31);
  BOOST_TEST(c.beta == 0.42);
  BOOST_CHECK_THROW(read_fragility_summary(file, "drift_0.01"), InputError); // not fitted
  BOOST_CHECK_THROW(read_fragility_summary(file, "drift_0.02"), InputError); // no such curve
  std::remove(file.c_str());
  const std::string bad = temporary_file("bad.json", "{ \"command\": ");
  BOOST_CHECK_THROW(read_fragility_summary(bad, "pounding"), InputError);
  std::remove(bad.c_str());
}

BOOST_AUTO_TEST_CASE(fit_choice_names)
{
  // the help lists the choices; the names read back (summary.json uses them)
  for (const std::string &name : hazard_model_names().names())
    BOOST_TEST(hazard_model_names().name(hazard_model_names().value(name)) == name);
  std::ostringstream out;
  print_parameters(out);
  BOOST_TEST(out.str().find("Allowed: gumbel, poisson.") != std::string::npos);
  BOOST_TEST(out.str().find("subsection Site hazard") != std::string::npos);
}
