#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/excitation/stochastic.h>

#include <Eigen/Dense>
#include <unsupported/Eigen/FFT>
#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>
#include <complex>
#include <cmath>
#include <stdexcept>

namespace poundfe
{
  namespace
  {
    using Matrix4 = Eigen::Matrix4d;
    using Vector4 = Eigen::Vector4d;

    /// State [xf, xf', xh, xh']: s' = A s + B w, output a = c^T s.
    void
    state_space(const FilterParameters &f, Matrix4 &a, Vector4 &b, Vector4 &c)
    {
      const double g1 = 2 * f.zeta_g * f.omega_g, g0 = f.omega_g * f.omega_g;
      const double h1 = 2 * f.zeta_f * f.omega_f, h0 = f.omega_f * f.omega_f;
      a.setZero();
      b.setZero();
      a(0, 1) = 1;
      a(1, 0) = -g0;
      a(1, 1) = -g1;
      b(1)    = -1;
      // KT output a_kt = -(g1 xf' + g0 xf)
      Vector4 kt(-g0, -g1, 0, 0);
      if (!f.clough_penzien)
        {
          c = kt;
          return;
        }
      a(2, 3)       = 1;
      a.row(3)      = kt.transpose();
      a(3, 2)       = -h0;
      a(3, 3)       = -h1;
      c             = a.row(3).transpose(); // xh'' = a_kt - h1 xh' - h0 xh
    }

    std::uint64_t
    splitmix64(std::uint64_t &x)
    {
      std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
      z               = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
      z               = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
      return z ^ (z >> 31);
    }

    std::uint64_t
    rotl(const std::uint64_t x, const int k)
    {
      return (x << k) | (x >> (64 - k));
    }
  } // namespace

  FilterParameters
  soil_preset(const Soil soil, const bool clough_penzien)
  {
    FilterParameters f;
    f.clough_penzien = clough_penzien;
    if (soil == Soil::firm)
      f.omega_g = 15, f.zeta_g = 0.6;
    else if (soil == Soil::medium)
      f.omega_g = 10, f.zeta_g = 0.4;
    else if (soil == Soil::soft)
      f.omega_g = 5, f.zeta_g = 0.2;
    f.omega_f = f.omega_g / 10;
    f.zeta_f  = 0.6;
    return f;
  }

  double
  filter_psd(const FilterParameters &f, const double w)
  {
    const double wg2 = f.omega_g * f.omega_g, w2 = w * w;
    const double z   = 4 * f.zeta_g * f.zeta_g * wg2 * w2;
    double       s   = (wg2 * wg2 + z) / ((wg2 - w2) * (wg2 - w2) + z);
    if (f.clough_penzien)
      {
        const double wf2 = f.omega_f * f.omega_f;
        s *= w2 * w2 / ((wf2 - w2) * (wf2 - w2) + 4 * f.zeta_f * f.zeta_f * wf2 * w2);
      }
    return s;
  }

  double
  stationary_variance_per_unit_s0(const FilterParameters &f)
  {
    Matrix4 a;
    Vector4 b, c;
    state_space(f, a, b, c);
    const int n = f.clough_penzien ? 4 : 2;
    // A P + P A^T + q B B^T = 0 with q = 2 pi (unit S0), as a Kronecker system.
    const Eigen::MatrixXd an = a.topLeftCorner(n, n);
    const Eigen::MatrixXd id = Eigen::MatrixXd::Identity(n, n);
    Eigen::MatrixXd       kron(n * n, n * n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        kron.block(i * n, j * n, n, n) = an(i, j) * id + (i == j ? an : Eigen::MatrixXd::Zero(n, n));
    // vec(P) column-major: (I (x) A + A (x) I) vec(P) = -q vec(B B^T)
    const Eigen::VectorXd bn = b.head(n);
    Eigen::MatrixXd       q  = 2 * M_PI * bn * bn.transpose();
    Eigen::VectorXd       rhs(n * n);
    for (int j = 0; j < n; ++j)
      rhs.segment(j * n, n) = -q.col(j);
    // kron above is A (x) I + I (x) A in block form for column-major vec.
    const Eigen::VectorXd p = kron.fullPivLu().solve(rhs);
    Eigen::MatrixXd       pm(n, n);
    for (int j = 0; j < n; ++j)
      pm.col(j) = p.segment(j * n, n);
    const Eigen::VectorXd cn = c.head(n);
    return cn.dot(pm * cn);
  }

  double
  intensity_from_pga(const FilterParameters &filter, const double pga, const double peak_factor)
  {
    return pga * pga / (peak_factor * peak_factor * stationary_variance_per_unit_s0(filter));
  }

  double
  Envelope::operator()(const double t) const
  {
    if (t < 0)
      return 0;
    if (kind == EnvelopeKind::jennings)
      {
        if (t < rise_end)
          return (t / rise_end) * (t / rise_end);
        if (t <= plateau_end)
          return 1;
        return std::exp(-decay * (t - plateau_end));
      }
    if (kind == EnvelopeKind::saragoni_hart)
      {
        const double t_peak = b / c;
        return std::pow(t / t_peak, b) * std::exp(-c * (t - t_peak));
      }
    if (kind == EnvelopeKind::shinozuka_sato)
      {
        const double t_peak = std::log(beta / alpha) / (beta - alpha);
        const double peak   = std::exp(-alpha * t_peak) - std::exp(-beta * t_peak);
        return (std::exp(-alpha * t) - std::exp(-beta * t)) / peak;
      }
    return 1;
  }

  NormalStream::NormalStream(const std::uint64_t seed, const std::uint64_t realization)
  {
    std::uint64_t x = seed ^ (0xd1b54a32d192ed03ULL * (realization + 1));
    for (auto &s : state)
      s = splitmix64(x);
  }

  std::uint64_t
  NormalStream::uniform_bits()
  {
    const std::uint64_t result = rotl(state[1] * 5, 7) * 9;
    const std::uint64_t t      = state[1] << 17;
    state[2] ^= state[0];
    state[3] ^= state[1];
    state[1] ^= state[2];
    state[0] ^= state[3];
    state[2] ^= t;
    state[3] = rotl(state[3], 45);
    return result;
  }

  double
  NormalStream::next()
  {
    if (has_spare)
      {
        has_spare = false;
        return spare;
      }
    // uniform in (0, 1]: never log(0)
    const double u1 = ((uniform_bits() >> 11) + 1) * 0x1.0p-53;
    const double u2 = (uniform_bits() >> 11) * 0x1.0p-53;
    const double r  = std::sqrt(-2 * std::log(u1));
    spare           = r * std::sin(2 * M_PI * u2);
    has_spare       = true;
    return r * std::cos(2 * M_PI * u2);
  }

  unsigned int
  n_samples(const double duration, const double interval)
  {
    return static_cast<unsigned int>(std::ceil(duration / interval - 1e-9)) + 1;
  }

  void
  standard_normals(const std::uint64_t seed, const std::uint64_t realization,
                   std::vector<double> &xi)
  {
    NormalStream normal(seed, realization);
    for (double &x : xi)
      x = normal.next();
  }

  MotionGenerator::MotionGenerator(const StochasticMotion &motion)
    : settings(motion)
  {
    const double dt = motion.sample_interval;
    n_points = poundfe::n_samples(motion.duration, dt);
    envelope_values.resize(n_points);
    for (unsigned int k = 0; k < n_points; ++k)
      envelope_values[k] = motion.envelope(k * dt);
    cutoff = M_PI / dt;
    switch (motion.method)
      {
        case StochasticMethod::white_noise:
          n_random    = n_points;
          noise_scale = std::sqrt(2 * M_PI * motion.spectral_intensity / dt);
          break;
        case StochasticMethod::filtered_white_noise:
          {
            Matrix4 a;
            Vector4 b, c;
            state_space(motion.filter, a, b, c);
            // exp([[A, B], [0, 0]] dt) = [[Phi, Gamma], [0, 1]]: exact for held input.
            Eigen::Matrix<double, 5, 5> augmented = Eigen::Matrix<double, 5, 5>::Zero();
            augmented.topLeftCorner<4, 4>()       = a * dt;
            augmented.topRightCorner<4, 1>()      = b * dt;
            const Eigen::Matrix<double, 5, 5> e   = augmented.exp();
            n_states = motion.filter.clough_penzien ? 4 : 2;
            for (unsigned int i = 0; i < 4; ++i)
              {
                noise_gain[i] = e(i, 4);
                output[i]     = c[i];
                for (unsigned int j = 0; j < 4; ++j)
                  propagator[4 * i + j] = e(i, j);
              }
            // the noise of the last sample would only act after the motion ends
            n_random    = n_points - 1;
            noise_scale = std::sqrt(2 * M_PI * motion.spectral_intensity / dt);
            break;
          }
        case StochasticMethod::spectral_representation:
          {
            cutoff = motion.cutoff_frequency > 0 ? motion.cutoff_frequency :
                                                   std::min(M_PI / dt, 25 * motion.filter.omega_g);
            if (cutoff > M_PI / dt * (1 + 1e-12))
              throw std::invalid_argument("spectral representation needs dt <= pi / w_u");
            // period 2 pi / dw of at least twice the duration: no repetition
            n_random = motion.n_frequencies > 0 ?
                         motion.n_frequencies :
                         static_cast<unsigned int>(std::ceil(cutoff * motion.duration / M_PI));
            const double dw = cutoff / n_random;
            omegas.resize(n_random);
            amplitudes.resize(n_random);
            for (unsigned int k = 0; k < n_random; ++k)
              {
                omegas[k]     = (k + 0.5) * dw;
                amplitudes[k] = 2 * std::sqrt(target_psd(omegas[k]) * dw);
              }
            break;
          }
      }
  }

  double
  MotionGenerator::target_psd(const double omega) const
  {
    if (settings.method == StochasticMethod::white_noise)
      return settings.spectral_intensity;
    return settings.spectral_intensity * filter_psd(settings.filter, omega);
  }

  std::string
  MotionGenerator::description() const
  {
    std::string kind;
    switch (settings.method)
      {
        case StochasticMethod::white_noise:
          kind = "white noise";
          break;
        case StochasticMethod::filtered_white_noise:
          kind = "filtered white noise";
          break;
        case StochasticMethod::spectral_representation:
          kind = "spectral representation";
          break;
      }
    const std::string process =
      settings.method == StochasticMethod::white_noise ?
        "" :
        std::string(settings.filter.clough_penzien ? "Clough-Penzien " : "Kanai-Tajimi ");
    return process + kind + " sample (seed " + std::to_string(settings.seed) + ", realization " +
           std::to_string(settings.realization) + ")";
  }

  void
  MotionGenerator::generate(const double *normals, std::vector<double> &values) const
  {
    values.resize(n_points);
    switch (settings.method)
      {
        case StochasticMethod::white_noise:
          for (unsigned int k = 0; k < n_points; ++k)
            values[k] = envelope_values[k] * noise_scale * normals[k];
          return;
        case StochasticMethod::filtered_white_noise:
          {
            double state[4] = {0, 0, 0, 0}, next[4];
            for (unsigned int k = 0; k < n_points; ++k)
              {
                double a = 0;
                for (unsigned int i = 0; i < n_states; ++i)
                  a += output[i] * state[i];
                values[k] = envelope_values[k] * a;
                if (k + 1 == n_points)
                  break;
                const double w = noise_scale * normals[k];
                for (unsigned int i = 0; i < n_states; ++i)
                  {
                    double x = noise_gain[i] * w;
                    for (unsigned int j = 0; j < n_states; ++j)
                      x += propagator[4 * i + j] * state[j];
                    next[i] = x;
                  }
                std::copy(next, next + n_states, state);
              }
            return;
          }
        case StochasticMethod::spectral_representation:
          {
            std::fill(values.begin(), values.end(), 0.0);
            const double dt = settings.sample_interval;
            for (unsigned int k = 0; k < n_random; ++k)
              {
                // cos(w t + phi) by rotating a unit phasor: no trigonometry per sample
                const double phase = 2 * M_PI * standard_normal_cdf(normals[k]);
                double       re = amplitudes[k] * std::cos(phase), im = amplitudes[k] * std::sin(phase);
                const double c = std::cos(omegas[k] * dt), s = std::sin(omegas[k] * dt);
                for (unsigned int n = 0; n < n_points; ++n)
                  {
                    values[n] += re;
                    const double r = re * c - im * s;
                    im             = re * s + im * c;
                    re             = r;
                  }
              }
            for (unsigned int n = 0; n < n_points; ++n)
              values[n] *= envelope_values[n];
            return;
          }
      }
  }

  GroundMotion
  MotionGenerator::ground_motion() const
  {
    std::vector<double> xi(n_random), values;
    standard_normals(settings.seed, settings.realization, xi);
    generate(xi.data(), values);
    return GroundMotion(settings.sample_interval, std::move(values), description(), held());
  }

  GroundMotion
  generate_ground_motion(const StochasticMotion &motion)
  {
    return MotionGenerator(motion).ground_motion();
  }

  MotionSamples
  sample_realizations(const MotionGenerator &generator, const unsigned int n_realizations,
                      const double scale)
  {
    MotionSamples samples;
    samples.realizations.resize(n_realizations);
    std::vector<double> xi(generator.n_variables());
    for (unsigned int r = 0; r < n_realizations; ++r)
      {
        throw_if_interrupted();
        standard_normals(generator.motion().seed, r, xi);
        generator.generate(xi.data(), samples.realizations[r]);
        for (double &a : samples.realizations[r])
          a *= scale,
            samples.mean_square += a * a / (n_realizations * generator.n_samples());
      }
    return samples;
  }

  EnsemblePsd
  ensemble_psd(const MotionGenerator &generator, const unsigned int n_realizations,
               const unsigned int band, const double max_omega)
  {
    const StochasticMotion &motion = generator.motion();
    const double            dt     = motion.sample_interval;
    const unsigned int      n      = generator.n_samples();
    double                  envelope_square = 0;
    for (unsigned int k = 0; k < n; ++k)
      envelope_square += motion.envelope(k * dt) * motion.envelope(k * dt) / n;
    std::vector<double>               xi(generator.n_variables()), values, power(n / 2 + 1, 0.0);
    std::vector<std::complex<double>> spectrum;
    Eigen::FFT<double>                fft;
    for (unsigned int r = 0; r < n_realizations; ++r)
      {
        throw_if_interrupted(); // minutes for 10^4 realizations: a safe point each
        standard_normals(motion.seed, r, xi);
        generator.generate(xi.data(), values);
        fft.fwd(spectrum, values);
        for (unsigned int k = 0; k <= n / 2; ++k)
          power[k] += std::norm(spectrum[k]) * dt / (2 * M_PI * n) /
                      (n_realizations * envelope_square);
      }
    EnsemblePsd  psd;
    const double dw = 2 * M_PI / (n * dt);
    for (unsigned int k = 1; k + band <= n / 2 + 1; k += band) // skip the mean (k = 0)
      {
        double w = 0, p = 0;
        for (unsigned int i = k; i < k + band; ++i)
          w += i * dw / band, p += power[i] / band;
        if (w > std::min(max_omega, generator.cutoff_frequency()))
          break;
        psd.omega.push_back(w);
        psd.estimate.push_back(p);
        psd.target.push_back(generator.target_psd(w));
      }
    return psd;
  }
} // namespace poundfe
