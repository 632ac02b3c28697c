// Target spectra of record selection besides EC8's (response_spectrum.h):
//  - ASCE 7-16 (Sect. 11.4.6) design spectrum: Sa = SDS (0.4 + 0.6 T / T0)
//    for T < T0, SDS up to TS, SD1 / T up to TL, SD1 TL / T^2 beyond;
//    T0 = 0.2 SD1 / SDS, TS = SD1 / SDS;
//  - the ground-motion model of Boore, Stewart, Seyhan & Atkinson (2014,
//    BSSA14) for RotD50 PSA (g, 5 % damping) of shallow crustal
//    earthquakes, without the basin term (dz1 = 0) and with the global
//    anelastic attenuation (dc3 = 0):
//      ln Y = F_E(M, mech) + F_P(R_JB, M) + F_S(V_S30, R_JB, M),
//      F_E = e_mech + e4 (M - Mh) + e5 (M - Mh)^2 (M <= Mh), e_mech + e6 (M - Mh) (M > Mh),
//      F_P = [c1 + c2 (M - 4.5)] ln(R / 1) + c3 (R - 1),  R = sqrt(R_JB^2 + h^2),
//      F_S = c ln(min(V_S30, Vc) / 760) + f2 ln((PGA_r + 0.1) / 0.1),
//      f2 = f4 [exp(f5 (min(V_S30, 760) - 360)) - exp(f5 400)],
//    PGA_r the median PGA (g) on V_S30 = 760 m/s (F_E + F_P of PGA's
//    coefficients); sigma = sqrt(phi^2 + tau^2), tau and phi (eq. 13-17)
//    by magnitude, distance and V_S30. Coefficients: the authors' table of
//    2014-07-15 (PEER report 2013/05's electronic supplement), 105 periods
//    from 0.01 to 10 s; between them ln Y and sigma are interpolated
//    linearly in ln T;
//  - the correlation of epsilons at two periods of Baker & Jayaram (2008,
//    eq. 7-10);
//  - the conditional mean spectrum (Baker 2011) given Sa(T*) at epsilon
//    eps*: ln Sa(T) = mu(T) + rho(T, T*) eps* sigma(T), with the
//    conditional standard deviation sigma(T) sqrt(1 - rho^2).
//   American Society of Civil Engineers (2017). ASCE/SEI 7-16, Sect. 11.4.6.
//   Boore, D. M., Stewart, J. P., Seyhan, E. & Atkinson, G. M. (2014).
//     NGA-West2 equations for predicting PGA, PGV, and 5 % damped PSA for
//     shallow crustal earthquakes. Earthquake Spectra 30(3), 1057-1085.
//   Baker, J. W. & Jayaram, N. (2008). Correlation of spectral acceleration
//     values from NGA ground motion models. Earthquake Spectra 24(1), 299-317.
//   Baker, J. W. (2011). Conditional mean spectrum: tool for ground-motion
//     selection. J. Struct. Eng. 137(3), 322-331.
#ifndef poundfe_excitation_target_spectrum_h
#define poundfe_excitation_target_spectrum_h

#include <poundfe/base/choices.h>

#include <vector>

namespace poundfe
{
  /// ASCE 7-16's design Sa(T) (in the unit of SDS and SD1, e.g. g).
  double asce7_design_spectrum(double sds, double sd1, double tl, double period);

  enum class FaultMechanism
  {
    unspecified,
    strike_slip,
    normal,
    reverse
  };
  const NameTable<FaultMechanism> &fault_mechanism_names();

  struct Scenario
  {
    double         magnitude = 7, rjb_km = 10, vs30_m_s = 760;
    FaultMechanism mechanism = FaultMechanism::unspecified;
  };

  /// BSSA14's median (g) and total log standard deviation at `period` (s).
  struct LogNormalValue
  {
    double median = 0, sigma = 0;
  };
  LogNormalValue bssa14(const Scenario &scenario, double period);
  /// The shortest and longest period of BSSA14's table (s).
  double bssa14_min_period();
  double bssa14_max_period();

  /// Baker & Jayaram's (2008) correlation of epsilons at periods t1, t2
  /// (0.01 to 10 s).
  double baker_jayaram_correlation(double t1, double t2);

  /// The conditional mean spectrum at `periods`: medians (g) and
  /// conditional log standard deviations, given epsilon at t_star.
  std::vector<LogNormalValue> conditional_mean_spectrum(const Scenario &scenario, double t_star,
                                                        double epsilon,
                                                        const std::vector<double> &periods);
} // namespace poundfe

#endif
