// FEMA P-695's collapse margin (assessment/collapse_margin.h): its tables,
// the IDA/Collapse margin section and the margin.
#include <poundfe/assessment/collapse_margin.h>
#include <poundfe/assessment/ida.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace poundfe
{
  namespace
  {
    // FEMA P-695 Tables 7-1a (SDC B, C, D_min) and 7-1b (SDC D_max): SSF by
    // period (rows: T <= 0.5, 0.6, ..., 1.4, >= 1.5 s) and period-based
    // ductility (columns: mu_T = 1.0, 1.1, 1.5, 2, 3, 4, 6, >= 8).
    constexpr std::array<double, 11> ssf_periods{0.5, 0.6, 0.7, 0.8, 0.9, 1.0,
                                                 1.1, 1.2, 1.3, 1.4, 1.5};
    constexpr std::array<double, 8>  ssf_ductilities{1.0, 1.1, 1.5, 2, 3, 4, 6, 8};
    using SsfTable = double[11][8];
    constexpr SsfTable ssf_b_c_d_min{{1.00, 1.02, 1.04, 1.06, 1.08, 1.09, 1.12, 1.14},
                                      {1.00, 1.02, 1.05, 1.07, 1.09, 1.11, 1.13, 1.16},
                                      {1.00, 1.03, 1.06, 1.08, 1.10, 1.12, 1.15, 1.18},
                                      {1.00, 1.03, 1.06, 1.08, 1.11, 1.14, 1.17, 1.20},
                                      {1.00, 1.03, 1.07, 1.09, 1.13, 1.15, 1.19, 1.22},
                                      {1.00, 1.04, 1.08, 1.10, 1.14, 1.17, 1.21, 1.25},
                                      {1.00, 1.04, 1.08, 1.11, 1.15, 1.18, 1.23, 1.27},
                                      {1.00, 1.04, 1.09, 1.12, 1.17, 1.20, 1.25, 1.30},
                                      {1.00, 1.05, 1.10, 1.13, 1.18, 1.22, 1.27, 1.32},
                                      {1.00, 1.05, 1.10, 1.14, 1.19, 1.23, 1.30, 1.35},
                                      {1.00, 1.05, 1.11, 1.15, 1.21, 1.25, 1.32, 1.37}};
    constexpr SsfTable ssf_d_max{{1.00, 1.05, 1.10, 1.13, 1.18, 1.22, 1.28, 1.33},
                                  {1.00, 1.05, 1.11, 1.14, 1.20, 1.24, 1.30, 1.36},
                                  {1.00, 1.06, 1.11, 1.15, 1.21, 1.25, 1.32, 1.38},
                                  {1.00, 1.06, 1.12, 1.16, 1.22, 1.27, 1.35, 1.41},
                                  {1.00, 1.06, 1.13, 1.17, 1.24, 1.29, 1.37, 1.44},
                                  {1.00, 1.07, 1.13, 1.18, 1.25, 1.31, 1.39, 1.46},
                                  {1.00, 1.07, 1.14, 1.19, 1.27, 1.32, 1.41, 1.49},
                                  {1.00, 1.07, 1.15, 1.20, 1.28, 1.34, 1.44, 1.52},
                                  {1.00, 1.08, 1.16, 1.21, 1.29, 1.36, 1.46, 1.55},
                                  {1.00, 1.08, 1.16, 1.22, 1.31, 1.38, 1.49, 1.58},
                                  {1.00, 1.08, 1.17, 1.23, 1.32, 1.40, 1.51, 1.61}};

    /// Where x falls in `grid`: the index i of the interval [grid[i], grid[i+1]]
    /// and the weight of grid[i + 1]; x outside takes the edge.
    template <std::size_t n>
    std::pair<std::size_t, double>
    ssf_bracket(const std::array<double, n> &grid, const double x)
    {
      if (x <= grid.front())
        return {0, 0.0};
      if (x >= grid.back())
        return {n - 2, 1.0};
      std::size_t i = 0;
      while (grid[i + 1] < x)
        ++i;
      return {i, (x - grid[i]) / (grid[i + 1] - grid[i])};
    }

    // Phi^-1(0.90) and Phi^-1(0.80): Table 7-3's 10 % and 20 % columns
    constexpr double z_90 = 1.2815515655446004, z_80 = 0.8416212335729143;
  } // namespace

  const NameTable<DesignCategory> &
  design_category_names()
  {
    static const NameTable<DesignCategory> table(
      {{DesignCategory::d_max, "D_max"}, {DesignCategory::b_c_d_min, "B/C/D_min"}});
    return table;
  }

  const NameTable<QualityRating> &
  quality_rating_names()
  {
    static const NameTable<QualityRating> table({{QualityRating::superior, "superior"},
                                                 {QualityRating::good, "good"},
                                                 {QualityRating::fair, "fair"},
                                                 {QualityRating::poor, "poor"}});
    return table;
  }

  double
  spectral_shape_factor(const double period, const double ductility,
                        const DesignCategory category)
  {
    const SsfTable &table = category == DesignCategory::d_max ? ssf_d_max : ssf_b_c_d_min;
    const auto [i, s] = ssf_bracket(ssf_periods, period);
    const auto [j, t] = ssf_bracket(ssf_ductilities, ductility);
    return (1 - s) * ((1 - t) * table[i][j] + t * table[i][j + 1]) +
           s * ((1 - t) * table[i + 1][j] + t * table[i + 1][j + 1]);
  }

  double
  quality_uncertainty(const QualityRating rating)
  {
    switch (rating)
      {
        case QualityRating::superior:
          return 0.10;
        case QualityRating::good:
          return 0.20;
        case QualityRating::fair:
          return 0.35;
        case QualityRating::poor:
          return 0.50;
      }
    return 0.50;
  }

  double
  acceptable_acmr(const double beta_total, const double collapse_probability)
  {
    Assert(collapse_probability == 0.1 || collapse_probability == 0.2,
           dealii::ExcMessage("Table 7-3's 10 % or 20 % column"));
    return std::exp((collapse_probability == 0.1 ? z_90 : z_80) * beta_total);
  }

  double
  median_collapse_intensity(std::vector<double> collapse, const unsigned int n_censored)
  {
    collapse.insert(collapse.end(), n_censored, std::numeric_limits<double>::infinity());
    if (collapse.empty())
      return std::numeric_limits<double>::infinity();
    return empirical_quantile(collapse, 0.5);
  }

  CollapseMargin
  collapse_margin(const CollapseMarginParameters &p, const double s_ct, const bool lower_bound,
                  const double period)
  {
    CollapseMargin m;
    m.s_ct        = s_ct;
    m.s_mt        = p.mce_spectral_acceleration;
    m.period      = period;
    m.ductility   = p.ductility;
    m.lower_bound = lower_bound;
    m.cmr         = s_ct / m.s_mt;
    m.ssf         = spectral_shape_factor(period, p.ductility, p.category);
    m.acmr        = m.ssf * m.cmr;
    m.beta_rtr    = p.record_to_record > 0 ? p.record_to_record :
                                             std::min(0.4, 0.1 + 0.1 * p.ductility);
    double sum = m.beta_rtr * m.beta_rtr;
    for (const QualityRating q : {p.design_requirements, p.test_data, p.modeling})
      sum += std::pow(quality_uncertainty(q), 2);
    m.beta_total_exact = std::sqrt(sum);
    m.beta_total       = std::round(m.beta_total_exact / 0.025) * 0.025;
    m.acceptable_10    = acceptable_acmr(m.beta_total, 0.1);
    m.acceptable_20    = acceptable_acmr(m.beta_total, 0.2);
    m.passes_10        = m.acmr >= m.acceptable_10;
    m.passes_20        = m.acmr >= m.acceptable_20;
    return m;
  }

  void
  CollapseMarginParameters::declare(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Double;
    prm.enter_subsection("Collapse margin");
    prm.add_parameter("MCE spectral acceleration", mce_spectral_acceleration,
                      "S_MT, the MCE spectral acceleration at IDA/Period: with it, ida "
                      "reports FEMA P-695's collapse margin ratio, spectral shape factor, "
                      "ACMR, beta_TOT and the acceptable ACMRs (IDA/Intensity measure = Sa); "
                      "0: none. Unit: g.", Double(0));
    prm.add_parameter("Period-based ductility", ductility,
                      "mu_T of FEMA P-695 (eq. 6-6: ultimate roof drift over the effective "
                      "yield roof drift of a pushover): enters SSF and beta_RTR. Unit: -.",
                      Double(1));
    add_choice(prm, "Seismic design category", category,
               "Table 7-1b (SDC D_max) or Table 7-1a (SDC B, C or D_min: B/C/D_min) of "
               "the spectral shape factor. Unit: -.", design_category_names());
    add_choice(prm, "Design requirements rating", design_requirements,
               "Quality of the design requirements (beta_DR, FEMA P-695 section 3.6). Unit: -.",
               quality_rating_names());
    add_choice(prm, "Test data rating", test_data,
               "Quality of the test data (beta_TD, section 3.7). Unit: -.",
               quality_rating_names());
    add_choice(prm, "Modeling rating", modeling,
               "Quality of the nonlinear model (beta_MDL, section 5.7). Unit: -.",
               quality_rating_names());
    prm.add_parameter("Record-to-record uncertainty", record_to_record,
                      "beta_RTR; 0: 0.1 + 0.1 mu_T, at most 0.4 (eq. 7-2). Unit: -.",
                      Double(0, 1));
    prm.leave_subsection();
  }

  void
  CollapseMarginParameters::check(const InputFile &input, const IntensityMeasure measure) const
  {
    if (requested() && measure != IntensityMeasure::sa)
      input.fail("IDA/Collapse margin/MCE spectral acceleration",
                 "FEMA P-695's collapse margin is a ratio of Sa(T): it needs IDA/Intensity "
                 "measure = Sa, not " + intensity_measure_names().name(measure));
  }
} // namespace poundfe
