#include <poundfe/base/interruption.h>
#include <poundfe/excitation/response_spectrum.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <utility>
#include <sstream>
#include <stdexcept>

namespace poundfe
{
  namespace
  {
    /// Below this omega h the closed forms lose more than ~1e-13 to
    /// cancellation and the series converges in a few terms.
    constexpr double series_limit = 0.2;

    using Matrix2 = std::array<double, 4>; // row-major

    Matrix2
    multiply(const Matrix2 &x, const Matrix2 &y)
    {
      return {{x[0] * y[0] + x[1] * y[2], x[0] * y[1] + x[1] * y[3],
               x[2] * y[0] + x[3] * y[2], x[2] * y[1] + x[3] * y[3]}};
    }
  } // namespace

  OscillatorStep
  nigam_jennings_closed_form(const double omega, const double zeta, const double h)
  {
    Assert(omega > 0 && zeta >= 0 && zeta < 1 && h > 0, dealii::ExcMessage("bad oscillator"));
    const double root    = std::sqrt(1 - zeta * zeta);
    const double omega_d = omega * root;
    const double E       = std::exp(-zeta * omega * h);
    const double S       = std::sin(omega_d * h);
    const double C       = std::cos(omega_d * h);
    const double r       = zeta / root;
    const double w2      = omega * omega, w3 = w2 * omega;
    // Nigam & Jennings (1969), eq. 9, for u'' + 2 zeta omega u' + omega^2 u = -a
    const double p = (2 * zeta * zeta - 1) / (w2 * h); // the recurring groups
    const double q = 2 * zeta / (w3 * h);
    OscillatorStep s;
    s.A = {{E * (r * S + C), E * S / omega_d, -omega / root * E * S, E * (C - r * S)}};
    const double c_minus = C - r * S;
    const double w_plus  = omega_d * S + zeta * omega * C;
    s.B = {{E * ((p + zeta / omega) * S / omega_d + (q + 1 / w2) * C) - q,
            -E * (p * S / omega_d + q * C) - 1 / w2 + q,
            E * ((p + zeta / omega) * c_minus - (q + 1 / w2) * w_plus) + 1 / (w2 * h),
            -E * (p * c_minus - q * w_plus) - 1 / (w2 * h)}};
    return s;
  }

  OscillatorStep
  nigam_jennings_series(const double omega, const double zeta, const double h)
  {
    Assert(omega > 0 && zeta >= 0 && zeta < 1 && h > 0, dealii::ExcMessage("bad oscillator"));
    // In the scaled state y = [u, u'/omega], Z' = omega h [[0, 1], [-1, -2 zeta]]
    // has a norm below 3 omega h whatever omega: exp, phi1, phi2 of Z' by
    // their Taylor series (30 terms: (3 omega h)^30 / 30! < 1e-16 for omega h < 1).
    const double  x = omega * h;
    const Matrix2 z{{0, x, -x, -2 * zeta * x}};
    Matrix2       term{{1, 0, 0, 1}}; // Z'^k / k!
    Matrix2       phi0{}, phi1{}, phi2{};
    for (unsigned int k = 0; k < 30; ++k)
      {
        for (unsigned int j = 0; j < 4; ++j)
          {
            phi0[j] += term[j];
            phi1[j] += term[j] / (k + 1);
            phi2[j] += term[j] / ((k + 1.0) * (k + 2.0));
          }
        term = multiply(term, z);
        for (double &t : term)
          t /= k + 1;
      }
    OscillatorStep s;
    s.A = {{phi0[0], phi0[1] / omega, phi0[2] * omega, phi0[3]}};
    // B = -h [(phi1 - phi2) e, phi2 e] with e = [0, 1], back in [u, u']
    s.B = {{-h * (phi1[1] - phi2[1]) / omega, -h * phi2[1] / omega, -h * (phi1[3] - phi2[3]),
            -h * phi2[3]}};
    return s;
  }

  OscillatorStep
  nigam_jennings_step(const double omega, const double zeta, const double h)
  {
    return omega * h < series_limit ? nigam_jennings_series(omega, zeta, h) :
                                      nigam_jennings_closed_form(omega, zeta, h);
  }

  SpectralOscillators::SpectralOscillators(std::vector<double> periods,
                                           std::vector<double> damping_ratios)
    : period(std::move(periods))
    , damping(std::move(damping_ratios))
  {
    for (const double z : damping)
      for (const double T : period)
        {
          Assert(T > 0 && z >= 0 && z < 1, dealii::ExcMessage("bad period or damping ratio"));
          omega.push_back(2 * M_PI / T);
          zeta.push_back(z);
        }
    const std::size_t n = omega.size();
    steps.resize(n);
    n_substeps.assign(n, 1);
    for (auto *x : {&u, &v, &max_u, &max_v, &max_a})
      x->assign(n, 0.0);
  }

  void
  SpectralOscillators::start(const double t, const double a)
  {
    for (auto *x : {&u, &v, &max_u, &max_v, &max_a})
      std::fill(x->begin(), x->end(), 0.0);
    time   = t;
    last_a = a;
  }

  void
  SpectralOscillators::prepare(const double h)
  {
    for (std::size_t j = 0; j < omega.size(); ++j)
      {
        const double per_period = h * omega[j] / (2 * M_PI) * spectrum_samples_per_period;
        n_substeps[j] = std::max(1u, static_cast<unsigned int>(std::ceil(per_period - 1e-9)));
        steps[j]      = nigam_jennings_step(omega[j], zeta[j], h / n_substeps[j]);
      }
    prepared_h = h;
  }

  void
  SpectralOscillators::advance(const double h, const double a0, const double a1)
  {
    Assert(h > 0, dealii::ExcMessage("a step must be positive"));
    if (std::abs(h - prepared_h) > 1e-12 * h)
      prepare(h);
    for (std::size_t j = 0; j < omega.size(); ++j)
      {
        throw_if_interrupted(); // a spectrum of many periods and a long step is a long loop
        const OscillatorStep &s  = steps[j];
        const unsigned int    m  = n_substeps[j];
        const double          da = (a1 - a0) / m;
        const double          w2 = omega[j] * omega[j], c = 2 * zeta[j] * omega[j];
        double                x = u[j], y = v[j];
        double                peak_u = max_u[j], peak_v = max_v[j], peak_a = max_a[j];
        for (unsigned int k = 0; k < m; ++k)
          {
            const double b0 = a0 + k * da, b1 = (k + 1 == m) ? a1 : a0 + (k + 1) * da;
            const double x1 = s.A[0] * x + s.A[1] * y + s.B[0] * b0 + s.B[1] * b1;
            const double y1 = s.A[2] * x + s.A[3] * y + s.B[2] * b0 + s.B[3] * b1;
            x = x1, y = y1;
            peak_u = std::max(peak_u, std::abs(x));
            peak_v = std::max(peak_v, std::abs(y));
            peak_a = std::max(peak_a, std::abs(w2 * x + c * y)); // |u'' + a|
            if ((k & 0xfffffu) == 0xfffffu) // a long free vibration: ~1e6 sub-steps a check
              throw_if_interrupted();
          }
        u[j] = x, v[j] = y;
        max_u[j] = peak_u, max_v[j] = peak_v, max_a[j] = peak_a;
      }
    time += h;
    last_a = a1;
  }

  void
  SpectralOscillators::advance_to(const double t, const double a)
  {
    const double h = t - time;
    if (h <= 1e-12 * std::max(1.0, std::abs(t))) // the end of a sub-step seen again
      {
        last_a = a;
        return;
      }
    advance(h, last_a, a);
  }

  void
  SpectralOscillators::add_free_vibration()
  {
    if (period.empty())
      return;
    advance(*std::max_element(period.begin(), period.end()), 0, 0);
  }

  double
  ResponseSpectrum::omega(const unsigned int i) const
  {
    return 2 * M_PI / periods[i];
  }

  ResponseSpectrum
  response_spectrum(const GroundMotion &motion, const std::vector<double> &periods,
                    const std::vector<double> &damping_ratios)
  {
    SpectralOscillators bank(periods, damping_ratios);
    const std::vector<double> &a  = motion.samples();
    const double               dt = motion.time_step();
    bank.start(0, a.empty() ? 0 : a[0]);
    if (motion.is_held()) // each value over [t_k, t_k + dt)
      for (std::size_t k = 0; k < a.size(); ++k)
        bank.advance(dt, a[k], a[k]);
    else
      for (std::size_t k = 0; k + 1 < a.size(); ++k)
        bank.advance(dt, a[k], a[k + 1]);
    bank.add_free_vibration();
    ResponseSpectrum spectrum;
    spectrum.periods               = periods;
    spectrum.damping_ratios        = damping_ratios;
    spectrum.displacement          = bank.peak_displacement();
    spectrum.relative_velocity     = bank.peak_velocity();
    spectrum.absolute_acceleration = bank.peak_absolute_acceleration();
    return spectrum;
  }

  namespace
  {
    /// int_0^s (a0 + (a1 - a0) x / h)^2 dx.
    double
    partial_energy(const double a0, const double a1, const double h, const double s)
    {
      const double slope = (a1 - a0) / h;
      return a0 * a0 * s + a0 * slope * s * s + slope * slope * s * s * s / 3;
    }

    /// The time at which the cumulative int a^2 reaches `level` (linear
    /// a: bisection of the cubic inside the step that crosses it).
    double
    husid_time(const std::vector<double> &a, const double dt, const bool held,
               const double level)
    {
      const std::size_t n_intervals = held ? a.size() : a.size() - 1;
      double            cumulative  = 0;
      for (std::size_t k = 0; k < n_intervals; ++k)
        {
          const double a1   = held ? a[k] : a[k + 1];
          const double step = partial_energy(a[k], a1, dt, dt);
          if (cumulative + step >= level && step > 0)
            {
              double low = 0, high = dt;
              for (unsigned int i = 0; i < 60; ++i)
                {
                  const double mid = 0.5 * (low + high);
                  (cumulative + partial_energy(a[k], a1, dt, mid) < level ? low : high) = mid;
                }
              return k * dt + 0.5 * (low + high);
            }
          cumulative += step;
        }
      return n_intervals * dt;
    }
  } // namespace

  namespace
  {
    /// max |v| and max |d| over a step of h from (v0, d0) under a0 -> a1
    /// (linear): the ends and the interior extrema, where a = 0 (of v) and
    /// v = 0 (of d).
    std::pair<double, double>
    step_peaks(const double v0, const double d0, const double a0, const double a1, const double h)
    {
      const double slope = (a1 - a0) / h;
      auto v = [&](const double s) { return v0 + a0 * s + slope * s * s / 2; };
      auto d = [&](const double s) { return d0 + v0 * s + a0 * s * s / 2 + slope * s * s * s / 6; };
      double peak_v = std::max(std::abs(v(0)), std::abs(v(h)));
      double peak_d = std::max(std::abs(d(0)), std::abs(d(h)));
      if (slope != 0 && a0 * a1 < 0) // a = 0 inside
        peak_v = std::max(peak_v, std::abs(v(-a0 / slope)));
      // v(s) = slope/2 s^2 + a0 s + v0 = 0 inside the step
      std::array<double, 2> roots{{-1, -1}};
      if (slope == 0)
        roots[0] = a0 != 0 ? -v0 / a0 : -1;
      else
        {
          const double discriminant = a0 * a0 - 2 * slope * v0;
          if (discriminant >= 0)
            {
              const double q = -0.5 * (a0 + std::copysign(std::sqrt(discriminant), a0));
              roots      = {{q != 0 ? v0 / q : -1, q / (slope / 2)}};
            }
        }
      for (const double s : roots)
        if (s > 0 && s < h)
          peak_d = std::max(peak_d, std::abs(d(s)));
      return {peak_v, peak_d};
    }
  } // namespace

  GroundMotionIntensity
  ground_motion_intensity(const GroundMotion &motion)
  {
    GroundMotionIntensity      result;
    const std::vector<double> &a    = motion.samples();
    const double               h    = motion.time_step();
    const bool                 held = motion.is_held();
    if (a.empty())
      return result;
    result.pga       = motion.peak();
    const std::size_t n_intervals = held ? a.size() : a.size() - 1;
    result.duration  = n_intervals * h;
    double velocity = 0, displacement = 0, energy = 0;
    for (std::size_t k = 0; k < n_intervals; ++k)
      {
        const double a1    = held ? a[k] : a[k + 1];
        const auto   peaks = step_peaks(velocity, displacement, a[k], a1, h);
        result.pgv         = std::max(result.pgv, peaks.first);
        result.pgd         = std::max(result.pgd, peaks.second);
        displacement += h * velocity + h * h * (2 * a[k] + a1) / 6;
        velocity += 0.5 * h * (a[k] + a1);
        energy += partial_energy(a[k], a1, h, h);
        const double p0 = std::abs(a[k]), p1 = std::abs(a1);
        result.cumulative_absolute_velocity +=
          a[k] * a1 >= 0 ? 0.5 * h * (p0 + p1) : 0.5 * h * (p0 * p0 + p1 * p1) / (p0 + p1);
      }
    result.arias_intensity = M_PI / (2 * standard_gravity) * energy;
    if (energy > 0)
      {
        result.t5  = husid_time(a, h, held, 0.05 * energy);
        result.t75 = husid_time(a, h, held, 0.75 * energy);
        result.t95 = husid_time(a, h, held, 0.95 * energy);
      }
    result.significant_duration      = result.t95 - result.t5;
    result.significant_duration_5_75 = result.t75 - result.t5;
    return result;
  }

  Ec8GroundParameters
  ec8_ground_parameters(const DesignSpectrum type, const GroundType ground)
  {
    // EN 1998-1:2004 Table 3.2 (type 1) and Table 3.3 (type 2): S, TB, TC, TD
    static const Ec8GroundParameters type_1[] = {{1.00, 0.15, 0.4, 2.0},
                                                 {1.20, 0.15, 0.5, 2.0},
                                                 {1.15, 0.20, 0.6, 2.0},
                                                 {1.35, 0.20, 0.8, 2.0},
                                                 {1.40, 0.15, 0.5, 2.0}};
    static const Ec8GroundParameters type_2[] = {{1.00, 0.05, 0.25, 1.2},
                                                 {1.35, 0.05, 0.25, 1.2},
                                                 {1.50, 0.10, 0.25, 1.2},
                                                 {1.80, 0.10, 0.30, 1.2},
                                                 {1.60, 0.05, 0.25, 1.2}};
    const unsigned int g = static_cast<unsigned int>(ground);
    if (type == DesignSpectrum::ec8_type_1)
      return type_1[g];
    if (type == DesignSpectrum::ec8_type_2)
      return type_2[g];
    throw std::logic_error("ec8_ground_parameters: not a Eurocode 8 spectrum");
  }

  double
  ec8_damping_correction(const double zeta)
  {
    return std::max(0.55, std::sqrt(10 / (5 + 100 * zeta)));
  }

  double
  ec8_elastic_spectrum(const DesignSpectrum type, const GroundType ground, const double ag,
                       const double zeta, const double T)
  {
    const Ec8GroundParameters p   = ec8_ground_parameters(type, ground);
    const double              eta = ec8_damping_correction(zeta);
    const double              top = 2.5 * ag * p.S * eta; // the plateau
    if (T <= p.TB)
      return ag * p.S * (1 + T / p.TB * (2.5 * eta - 1));
    if (T <= p.TC)
      return top;
    if (T <= p.TD)
      return top * p.TC / T;
    return top * p.TC * p.TD / (T * T);
  }

  std::string
  damping_label(const double zeta)
  {
    std::ostringstream label;
    label << std::setprecision(4) << 100 * zeta << "pct";
    return label.str();
  }

  std::vector<double>
  period_grid(const double t_min, const double t_max, const unsigned int n, const bool logarithmic)
  {
    std::vector<double> periods;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double f = n > 1 ? double(i) / (n - 1) : 0.0;
        periods.push_back(logarithmic ? t_min * std::pow(t_max / t_min, f) :
                                        t_min + f * (t_max - t_min));
      }
    return periods;
  }
} // namespace poundfe
