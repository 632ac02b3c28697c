// The collapse margin of FEMA P-695 (2009, "Quantification of building
// seismic performance factors", chapter 7) from an IDA on Sa(T):
//   CMR   = S_CT / S_MT                                   (eq. 7-1)
//     S_CT the median collapse intensity of the records (the intensity at
//     which half of them collapse: the empirical median of the records'
//     collapse intensities, a record that did not collapse below the upper
//     intensity counted above it; more than half such: S_CT is only known
//     to exceed the upper intensity, and CMR is a lower bound);
//     S_MT the MCE spectral acceleration at the period T;
//   ACMR  = SSF CMR                                       (eq. 7-3)
//     SSF the spectral shape factor of Table 7-1a (SDC B, C and D_min) or
//     Table 7-1b (SDC D_max) at T and the period-based ductility mu_T; T
//     below 0.5 s or above 1.5 s and mu_T above 8 take the table's edge,
//     between its entries linear interpolation in T and in mu_T;
//   beta_TOT = sqrt(beta_RTR^2 + beta_DR^2 + beta_TD^2 + beta_MDL^2)  (eq. 7-5)
//     beta_RTR = 0.1 + 0.1 mu_T, at most 0.4 (eq. 7-2) unless given,
//     beta_DR, beta_TD, beta_MDL from the quality ratings of the design
//     requirements, test data and model: superior 0.10, good 0.20, fair
//     0.35, poor 0.50 (sections 3.6, 3.7, 5.7); rounded to the nearest
//     0.025 as in Table 7-2;
//   acceptable ACMR_p = exp(-Phi^-1(p) beta_TOT)  (Table 7-3) for a
//     collapse probability p at the MCE of 10 % (every performance group's
//     mean) and 20 % (each archetype).
#ifndef poundfe_assessment_collapse_margin_h
#define poundfe_assessment_collapse_margin_h

#include <poundfe/base/choices.h>
#include <poundfe/base/input_file.h>
#include <poundfe/excitation/intensity_measures.h>

#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  enum class DesignCategory
  {
    d_max,    // Table 7-1b
    b_c_d_min // Table 7-1a
  };
  const NameTable<DesignCategory> &design_category_names();

  enum class QualityRating
  {
    superior,
    good,
    fair,
    poor
  };
  const NameTable<QualityRating> &quality_rating_names();

  /// IDA/Collapse margin: what the margin needs beyond the IDA.
  struct CollapseMarginParameters
  {
    double         mce_spectral_acceleration = 0; // S_MT, g; 0: no margin
    double         ductility                 = 3; // mu_T (pushover: delta_u / delta_y,eff)
    DesignCategory category                  = DesignCategory::d_max;
    QualityRating  design_requirements = QualityRating::good, test_data = QualityRating::good,
                  modeling = QualityRating::good;
    double         record_to_record = 0; // beta_RTR; 0: eq. 7-2

    bool requested() const { return mce_spectral_acceleration > 0; }
    void declare(dealii::ParameterHandler &prm);
    /// The margin needs Sa (g): `measure` is IDA/Intensity measure.
    void check(const InputFile &input, IntensityMeasure measure) const;
  };

  /// SSF of Table 7-1a/7-1b at period T (s) and ductility mu_T (>= 1).
  double spectral_shape_factor(double period, double ductility, DesignCategory category);
  /// beta of a quality rating (superior 0.10 ... poor 0.50).
  double quality_uncertainty(QualityRating rating);
  /// The acceptable ACMR at collapse probability 0.10 or 0.20 (Table 7-3).
  double acceptable_acmr(double beta_total, double collapse_probability);

  struct CollapseMargin
  {
    double s_ct = 0, s_mt = 0, period = 0, ductility = 0;
    bool   lower_bound = false; // S_CT above the upper intensity: CMR, ACMR at least
    double cmr = 0, ssf = 0, acmr = 0;
    double beta_rtr = 0, beta_total_exact = 0, beta_total = 0; // beta_total: Table 7-2's rounding
    double acceptable_10 = 0, acceptable_20 = 0;
    bool   passes_10 = false, passes_20 = false;
  };

  /// S_CT: the empirical median of `collapse` (the records' collapse
  /// intensities) with `n_censored` records that did not collapse counted
  /// above every one; +inf when those are half or more.
  double median_collapse_intensity(std::vector<double> collapse, unsigned int n_censored);

  /// The margin from the median collapse intensity `s_ct` (a lower bound
  /// when `lower_bound`) of an IDA on Sa(`period`).
  CollapseMargin collapse_margin(const CollapseMarginParameters &parameters, double s_ct,
                                 bool lower_bound, double period);
} // namespace poundfe

#endif
