// Multiple-stripe and cloud analysis of a record suite (Jalayer & Cornell
// 2009; Baker 2015), their fragilities, and the annual rates of exceedance
// on a hazard curve.
//
// Stripes: every record of the suite scaled to each intensity x_j
// (IdaRunner::run); at stripe j, k_j of its n_j runs exceed a limit state (a
// demand above its threshold, or collapse: a collapsed run exceeds every
// limit state). The lognormal fragility P(LS | x) = Phi(ln(x / theta) /
// beta) maximises the binomial likelihood (Baker 2015, eq. 11)
//   ln L = sum_j [ k_j ln p_j + (n_j - k_j) ln(1 - p_j) ],  p_j = P(LS | x_j),
// over (ln theta, ln beta): the fit of the fragility command
// (reliability/statistics.h, Nelder-Mead).
//
// Cloud: the records unscaled, the demand D regressed on the intensity
// (Jalayer & Cornell 2009): ln D = ln a + b ln x + e, least squares, with
// the dispersion s^2 = sum e^2 / (n - 2); collapsed runs are left out. Its
// fragility of a demand threshold d is lognormal with theta = (d / a)^(1/b),
// beta = s / b.
//
// Annual rate of exceedance of a limit state on a hazard curve lambda(x)
// (the annual rate of IM > x, decreasing):
//   lambda_LS = int P(LS | x) |d lambda(x)|,
// the curve interpolated linearly in (ln x, ln lambda) on 64 sub-intervals
// per interval of the table, P by the trapezoid rule on each, plus the
// rate above the last intensity times P there (the rate below the first
// intensity is left out: a curve starts where P is negligible). For a
// power-law hazard lambda = k0 x^-k and a lognormal fragility it is
// k0 theta^-k exp(k^2 beta^2 / 2) (Cornell et al. 2002, eq. 11).
//   Jalayer, F. & Cornell, C. A. (2009). Alternative non-linear demand
//     estimation methods for probability-based seismic assessments.
//     Earthquake Engng Struct. Dyn. 38, 951-972.
//   Baker, J. W. (2015). Efficient analytical fragility function fitting
//     using dynamic structural analysis. Earthquake Spectra 31(1), 579-599.
//   Cornell, C. A., Jalayer, F., Hamburger, R. O. & Foutch, D. A. (2002).
//     Probabilistic basis for 2000 SAC FEMA steel moment frame guidelines.
//     J. Struct. Eng. 128(4), 526-533.
#ifndef poundfe_assessment_msa_h
#define poundfe_assessment_msa_h

#include <poundfe/assessment/ida.h>
#include <poundfe/reliability/statistics.h>

#include <string>
#include <vector>

namespace poundfe
{
  /// A stripe's count: n runs at `intensity`, `exceeded` of them beyond the limit state.
  struct StripeCount
  {
    double       intensity = 0;
    unsigned int runs = 0, exceeded = 0;
  };

  /// The binomial maximum-likelihood fit (above) of the stripes' counts:
  /// the fragility command's fit (reliability/statistics.h); no fit when
  /// every stripe exceeded nothing or everything, or there is one stripe.
  LognormalFragility fit_stripe_fragility(const std::vector<StripeCount> &stripes);
  /// P(LS | x) of a fit (0 when there is none).
  double exceedance_probability(const LognormalFragility &fit, double intensity);

  /// ln D = ln a + b ln x, with the dispersion s of the residuals.
  struct CloudFit
  {
    double       a = 0, b = 0, dispersion = 0;
    unsigned int points = 0;
    bool         fitted = false;
    std::string  note;
    /// The fragility of the demand threshold d: theta = (d / a)^(1/b), beta = s / b.
    LognormalFragility fragility(double threshold) const;
  };
  /// Least squares on the pairs with x > 0 and D > 0 (at least three).
  CloudFit fit_cloud(const std::vector<double> &intensities, const std::vector<double> &demands);

  /// A hazard curve: intensities ascending, annual rates of exceedance (> 0).
  struct HazardCurve
  {
    std::vector<double> intensity, rate;
    /// lambda(x), interpolated in (ln x, ln lambda); clamped at the ends.
    double rate_at(double x) const;
    /// The intensity of annual rate 1 / return_period, interpolated alike;
    /// NaN outside the curve's rates.
    double intensity_of_return_period(double return_period) const;
  };
  /// The column `column` (the intensity) and annual_rate_per_year of the
  /// CSV file `path` (the site-hazard command's hazard_curve.csv, or a
  /// user's table with these columns); rows with a rate or intensity <= 0
  /// are left out. InputError (file, line, column) if the file cannot be
  /// read, lacks a column, or the intensities do not ascend or the rates
  /// increase; `parameter` names the entry that gave the file.
  HazardCurve read_hazard_curve(const std::string &path, const std::string &column);

  /// lambda_LS on the curve (above).
  double exceedance_rate(const HazardCurve &curve, const LognormalFragility &fragility);

  /// A limit state: the run collapsed (column < 0), or demand `column` of
  /// IdaRunner::demand_names() above `threshold` (or collapse).
  struct LimitState
  {
    std::string name;
    int         column    = -1;
    double      threshold = 0;
    bool exceeded(const IdaPoint &point) const;
  };

  /// Nested limit states. A limit state B is nested in A over a set of runs
  /// when every run that exceeds B exceeds A (a collapse exceeds every state;
  /// gap1_peak_impact_force_N > 2e4 is nested in gap1_impacts > 0): B is a
  /// subset event, and its true annual rate is at most A's. Each state's
  /// fragility is fitted on its own counts (the maximum of its own
  /// likelihood), and two lognormal curves of different beta cross, so the
  /// fitted rates can come out in the wrong order. They are not refitted
  /// under a constraint: P(B | x) <= P(A | x) at every x holds for two
  /// lognormal curves only with a common beta, which would bend both fits
  /// away from their data; instead each inversion is reported (a warning)
  /// with the bound the nesting gives, lambda_B <= min over A of lambda_A.
  struct NestedRate
  {
    std::vector<std::vector<unsigned int>> within; // [B]: the states A that B is nested in
    std::vector<double>                    bound;  // [B]: min(lambda_B, lambda_A over A)
    std::vector<std::string>               warnings; // one per inverted pair
  };

  /// For each state (of `points`, the runs done: a point without demands
  /// was not run) the states it is nested in; states exceeded by exactly
  /// the same runs are nested in each other; a state no run exceeds is
  /// nested in none (nothing to order).
  std::vector<std::vector<unsigned int>>
  nested_limit_states(const std::vector<LimitState> &states,
                      const std::vector<const IdaPoint *> &points);

  /// The bounds and warnings of `rates` (NaN: no rate) given the nesting.
  NestedRate order_nested_rates(const std::vector<LimitState> &states,
                                const std::vector<std::vector<unsigned int>> &within,
                                const std::vector<double> &rates);

  /// Every stripe's run of every record, and the cloud's.
  struct MsaResult
  {
    std::vector<double>                stripes;
    std::vector<std::vector<IdaPoint>> runs;  // [stripe][record]
    std::vector<IdaPoint>              cloud; // [record]; empty: no cloud
    IdaResult                          counters; // n_runs, n_run_now, interrupted, wall time
  };

  /// Runs every record at every stripe (and, with `cloud`, at its own
  /// intensity, unscaled) over the ranks of `comm` (each calls it), through
  /// run_ida_tasks: each run dealt to whichever rank is free, as ida's, so
  /// that ranks with longer runs (collapses, pounding) do not hold back the
  /// others; journaled in journal/stripes and journal/cloud: a run
  /// started again resumes. InputError if a journal holds other runs than
  /// these (another suite or other stripes). The result is on every rank.
  /// An empty `journal`: no file, the journals' texts in
  /// counters.journals (stripes/realizations.csv, cloud/realizations.csv).
  MsaResult run_msa(IdaRunner &runner, const std::vector<double> &stripes, bool cloud,
                    const std::string &journal, MPI_Comm comm, Progress *progress = nullptr);
} // namespace poundfe

#endif
