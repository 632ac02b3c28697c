#pragma once

/// The standard normal distribution's density and distribution function,
///   phi(z) = exp(-z^2/2) / sqrt(2 pi),   Phi(z) = erfc(-z / sqrt 2) / 2,
/// shared by the stochastic ground motion, the reliability methods and the
/// site hazard (Abramowitz and Stegun 1964, eq. 26.2.1 and 26.2.29 with
/// 7.1.2). Its inverse, which needs boost's quantile and the reliability
/// module's clipping of u, is reliability/distribution.h's
/// standard_normal_quantile.
namespace poundfe
{
  double standard_normal_pdf(double z);
  double standard_normal_cdf(double z);
} // namespace poundfe
