// The probability of pounding over an exposure time against the gap width,
// from a site hazard and the responses WITHOUT contact at several PGA levels
// (the `separation` command with a Separation/Site hazard):
//
//   demand model   D = the pair's largest relative approach in one event;
//                  ln D | a ~ N(ln c + b ln a, beta_D^2): a power-law median
//                  c a^b with a lognormal scatter (Cornell, Jalayer,
//                  Hamburger & Foutch 2002, J. Struct. Eng. 128(4) 526-533,
//                  eq. 6), c, b, beta_D by least squares of ln D on ln a over
//                  the realizations of every level;
//   fragility      P(D > g | a) = Phi(ln(a / theta(g)) / beta),
//                  theta(g) = (g / c)^(1/b), beta = beta_D / b;
//   hazard         lambda(a), the annual rate of events of PGA > a: a power
//                  law k0 a^-k (Cornell 1968, Engineering seismic risk
//                  analysis, BSSA 58(5) 1583-1606), the hazard_curve.csv of
//                  `poundfe site-hazard` interpolated linearly in log-log
//                  (extrapolated along its last segment), or its fit;
//   rate           lambda(g) = int_{a_min}^inf P(D > g | a) |d lambda/da| da
//                  (Cornell et al. 2002; hazard/site_hazard.h's
//                  annual_failure_rate), closed form for the power law
//                  without a lower limit: k0 theta(g)^-k exp(k^2 beta^2 / 2);
//   over T years   P_T(g) = 1 - exp(-T lambda(g)) (Poisson events);
//   gap            the g with P_T(g) = p (lambda decreases with g: toms748
//                  on ln lambda(g) - ln lambda*, lambda* = -ln(1 - p) / T;
//                  Alefeld, Potra & Shi 1995, ACM TOMS 21(3) 327-344).
// The one lognormal model over all levels, rather than a fit per gap, keeps
// lambda(g) smooth and decreasing in g (the root is unique) and reaches the
// gaps no realization exceeded; for a linear pair it is exact in the median
// (D scales with a, b = 1), and the empirical P(D > g | a_k) is written beside
// it to judge the fit.
#ifndef poundfe_hazard_pounding_hazard_h
#define poundfe_hazard_pounding_hazard_h

#include <poundfe/base/input_file.h>
#include <poundfe/hazard/pounding_hazard_parameters.h>
#include <poundfe/hazard/site_hazard.h>

#include <mpi.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace poundfe
{
  /// A site hazard in PGA.
  struct PgaHazard
  {
    /// lambda(a): annual rate of events of PGA > a (g), 1/year, decreasing.
    std::function<double(double)> annual_rate;
    double                        minimum_pga = 0; // g: smaller events are not counted
    double                        lowest_pga  = 0; // g: where a table starts; 0: any a > 0
    std::string                   source;          // for the reports
  };

  /// lambda(a) = k0 a^-k above minimum_pga.
  PgaHazard power_law_hazard(double k0, double k, double minimum_pga);

  /// The curve through (pga[i], rate[i]), linear in (ln a, ln lambda), along
  /// its last segment beyond the last point; minimum_pga = pga[0]. Throws
  /// std::invalid_argument unless there are two or more points, the PGAs
  /// increase, and the rates are positive and decrease.
  PgaHazard tabulated_hazard(const std::vector<double> &pga, const std::vector<double> &rate);

  /// The hazard of a file `poundfe site-hazard` wrote: its hazard_curve.csv
  /// or its summary.json (the fit; minimum_pga: the PGA of its minimum
  /// intensity). Throws InputError naming `file` and `parameter`.
  PgaHazard read_pga_hazard(const std::string &file, const std::string &parameter);

  /// Median D = c a^b, dispersion beta_D of ln D given a.
  struct PowerLawDemand
  {
    double        median_at_1g = 0, exponent = 0, dispersion = 0; // c (m), b, beta_D
    unsigned long n = 0;
  };

  /// Least squares of ln demand[i] on ln pga[i] (beta_D with n - 2 degrees of
  /// freedom). Throws std::invalid_argument for a demand <= 0, fewer than two
  /// distinct PGAs, or a median that does not grow with the PGA (b <= 0).
  PowerLawDemand fit_power_law_demand(const std::vector<double> &pga,
                                      const std::vector<double> &demand);

  /// P(D > gap | a) = Phi(ln(a / theta) / beta) of the demand model.
  LognormalCurve pounding_fragility(const PowerLawDemand &demand, double gap);

  /// lambda(gap), 1/year; a gap <= 0: every counted event, lambda(a_min).
  double annual_pounding_rate(const PgaHazard &hazard, const PowerLawDemand &demand, double gap);

  /// The gap whose probability of pounding in `years` is `probability` in
  /// (0, 1); 0 when even lambda(a_min) (every counted event pounding) meets it.
  double gap_for_probability_in_years(const PgaHazard &hazard, const PowerLawDemand &demand,
                                      double years, double probability);

  /// The Monte Carlo without contact at each PGA level and its results.
  struct PoundingHazard
  {
    PgaHazard           hazard;
    double              reference_pga = 0; // g, of the input's motion (amplitude factor 1)
    std::vector<double> pga_levels;        // g
    /// [pair][level]: the largest approach of each completed realization.
    std::vector<std::vector<std::vector<double>>> largest_approach;
    std::vector<PowerLawDemand> demand;         // per pair
    std::vector<double>         gap_for_target; // per pair, m
    bool                        interrupted = false;
    std::string                 failure; // why the demand fit or the gap failed ("" if not)
    /// What makes the results doubtful (a demand fit without scatter), for
    /// the console and summary.json's "warnings".
    std::vector<std::string> warnings;
  };

  /// The hazard of Separation/Site hazard (`parameters`, paths relative to
  /// `input`) and the input motion's PGA `reference_pga` (g), read and
  /// checked before anything is run or written. Throws InputError (a
  /// missing or bad hazard file, a Minimum PGA below the curve).
  PoundingHazard prepare_pounding_hazard(const PoundingHazardParameters &parameters,
                                         const InputFile &input, double reference_pga);

  /// One realization of the demand without contact: the largest approach of
  /// each pair (m, in the order of pair_names) under the noise of (seed,
  /// realization) with its amplitudes times amplitude_factor; `run` returns
  /// false when the integration failed.
  struct ApproachJob
  {
    std::vector<std::string> pair_names; // "A3-B2"
    std::uint64_t            seed = 1;
    std::function<bool(std::uint64_t realization, double amplitude_factor,
                       std::vector<double> &largest_approach)>
      run;
  };

  /// Runs `n_realizations` realizations of `job` at each level on every rank
  /// of `comm` (realizations.csv in directory/pga_<a>g/, resumed as
  /// `fragility` does; an empty `directory`: no file, results in memory; the
  /// same realizations at every level) and, on rank 0,
  /// fits the demand of each pair and finds the gap for the target of
  /// `parameters`. A fit or a gap that fails leaves `failure` (the
  /// realizations stay on disk and the per-event results are still written).
  void run_pounding_hazard(const ApproachJob &job, unsigned long n_realizations,
                           const PoundingHazardParameters &parameters,
                           const std::string &directory, MPI_Comm comm, PoundingHazard &result);
} // namespace poundfe

#endif
