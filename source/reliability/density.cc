// Histogram, binned Gaussian kernel density, Silverman's and Sheather-Jones's
// bandwidths and peaks
// (equations and source in include/poundfe/reliability/density.h).
#include <poundfe/reliability/density.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  int
  BinGrid::bin(const double x) const
  {
    if (x < low)
      return -1;
    if (!(x < high))
      return n_bins;
    return std::min<int>(n_bins - 1, static_cast<int>((x - low) / width()));
  }

  std::vector<double>
  histogram_density(const BinGrid &grid, const std::vector<double> &counts, const double n_total)
  {
    std::vector<double> p(counts.size(), 0.0);
    if (n_total > 0)
      for (std::size_t i = 0; i < counts.size(); ++i)
        p[i] = counts[i] / (n_total * grid.width());
    return p;
  }

  std::vector<double>
  kernel_density(const BinGrid &grid, const std::vector<double> &counts, const double n_total,
                 const double bandwidth, const std::vector<double> &points)
  {
    const double        norm = 1 / (n_total * bandwidth * std::sqrt(2 * M_PI));
    std::vector<double> f(points.size(), 0.0);
    if (!(n_total > 0))
      return f;
    for (std::size_t j = 0; j < points.size(); ++j)
      {
        double sum = 0;
        for (unsigned int i = 0; i < grid.n_bins; ++i)
          {
            const double u = (points[j] - grid.center(i)) / bandwidth;
            sum += counts[i] * std::exp(-0.5 * u * u);
          }
        f[j] = norm * sum;
      }
    return f;
  }

  std::vector<double>
  kernel_density(const BinGrid &grid, const std::vector<double> &counts, const double n_total,
                 const double bandwidth)
  {
    std::vector<double> centers(grid.n_bins);
    for (unsigned int i = 0; i < grid.n_bins; ++i)
      centers[i] = grid.center(i);
    return kernel_density(grid, counts, n_total, bandwidth, centers);
  }

  double
  binned_quantile(const BinGrid &grid, const std::vector<double> &counts, const double below,
                  const double n_total, const double p)
  {
    double       cumulative = below;
    const double target     = p * n_total;
    if (target <= cumulative)
      return grid.low;
    for (unsigned int i = 0; i < grid.n_bins; ++i)
      {
        if (counts[i] > 0 && cumulative + counts[i] >= target)
          return grid.low + (i + (target - cumulative) / counts[i]) * grid.width();
        cumulative += counts[i];
      }
    return grid.high;
  }

  double
  silverman_bandwidth(const double sigma, const double iqr, const double n)
  {
    const double spread = iqr > 0 ? std::min(sigma, iqr / 1.34) : sigma;
    return 0.9 * spread * std::pow(n, -0.2);
  }

  namespace
  {
    /// Pair counts of the binned data by bin distance m = |k - l|:
    /// D[m] = sum over ordered pairs of bins (k, l) at that distance of
    /// c_k c_l, the diagonal pairs of samples (a sample with itself) out.
    std::vector<double>
    pair_counts(const std::vector<double> &c, const double n)
    {
      std::vector<double> d(c.size(), 0.0);
      for (std::size_t k = 0; k < c.size(); ++k)
        for (std::size_t l = k; l < c.size(); ++l)
          d[l - k] += (l == k ? 1.0 : 2.0) * c[k] * c[l];
      d[0] -= n;
      return d;
    }

    /// sum_{i != j} phi_r(x_ij / g) / (N (N - 1) g^(r+1)), r = 4 or 6, from
    /// the pair counts at bin distances m w.
    double
    density_functional(const std::vector<double> &pairs, const double w, const double n,
                       const double g, const unsigned int r)
    {
      double sum = 0;
      for (std::size_t m = 0; m < pairs.size(); ++m)
        {
          const double u2 = (m * w / g) * (m * w / g);
          if (u2 > 80) // phi's factor e^(-40): nothing more to add
            break;
          const double polynomial = r == 4 ? (u2 - 6) * u2 + 3 : ((u2 - 15) * u2 + 45) * u2 - 15;
          sum += pairs[m] * polynomial * std::exp(-0.5 * u2);
        }
      return sum / (std::sqrt(2 * M_PI) * n * (n - 1) * std::pow(g, r + 1));
    }
  } // namespace

  double
  sheather_jones_bandwidth(const BinGrid &grid, const std::vector<double> &counts, const double iqr)
  {
    double n = 0, mean = 0, square = 0;
    for (unsigned int i = 0; i < grid.n_bins; ++i)
      n += counts[i], mean += counts[i] * grid.center(i),
        square += counts[i] * grid.center(i) * grid.center(i);
    if (!(n >= 3) || !(iqr > 0))
      return std::nan("");
    mean /= n;
    const double              sigma  = std::sqrt(std::max(0.0, square / n - mean * mean));
    const std::vector<double> pairs  = pair_counts(counts, n);
    const double              w      = grid.width();
    const double              a      = 0.920 * iqr * std::pow(n, -1.0 / 7);
    const double              b      = 0.912 * iqr * std::pow(n, -1.0 / 9);
    const double              s_a    = density_functional(pairs, w, n, a, 4);
    const double              t_b    = -density_functional(pairs, w, n, b, 6);
    const double              r_k    = 1 / (2 * std::sqrt(M_PI));
    if (!(s_a > 0) || !(t_b > 0))
      return std::nan("");
    const double ratio    = 1.357 * std::pow(s_a / t_b, 1.0 / 7);
    const auto   residual = [&](const double h) {
      const double s = density_functional(pairs, w, n, ratio * std::pow(h, 5.0 / 7), 4);
      return s > 0 ? h - std::pow(r_k / (n * s), 0.2) : h; // S <= 0: h too large
    };
    // bisection between 1e-3 and 10 times the normal reference 1.06 sigma N^(-1/5)
    const double reference = 1.06 * std::max(sigma, w) * std::pow(n, -0.2);
    double       low = 1e-3 * reference, high = 10 * reference;
    if (!(residual(low) < 0) || !(residual(high) > 0))
      return std::nan("");
    for (int k = 0; k < 100 && high - low > 1e-12 * high; ++k)
      {
        const double middle = 0.5 * (low + high);
        (residual(middle) < 0 ? low : high) = middle;
      }
    return 0.5 * (low + high);
  }

  namespace
  {
    /// The lowest value between j and the first value above f[j] in
    /// direction `step` (or the end of the range).
    double
    lowest_before_higher(const std::vector<double> &f, const int j, const int step)
    {
      double lowest = f[j];
      for (int k = j + step; k >= 0 && k < static_cast<int>(f.size()); k += step)
        {
          if (f[k] > f[j])
            break;
          lowest = std::min(lowest, f[k]);
        }
      return lowest;
    }

    /// A local maximum: higher than its left neighbour, and the next
    /// different value to the right (after a plateau) is lower.
    bool
    is_local_maximum(const std::vector<double> &f, const int j)
    {
      if (j > 0 && !(f[j] > f[j - 1]))
        return false;
      int k = j + 1;
      while (k < static_cast<int>(f.size()) && f[k] == f[j])
        ++k;
      return k == static_cast<int>(f.size()) || f[k] < f[j];
    }

    /// The peak at grid point j, moved to the vertex of the parabola
    /// through j and its neighbours (an end point, or a plateau, stays).
    Peak
    refined_peak(const BinGrid &grid, const std::vector<double> &f, const int j)
    {
      Peak peak{static_cast<unsigned int>(j), grid.center(j), f[j]};
      if (j == 0 || j + 1 == static_cast<int>(f.size()))
        return peak;
      const double left = f[j - 1], right = f[j + 1];
      const double curvature = left - 2 * f[j] + right;
      if (!(curvature < 0))
        return peak;
      const double offset = 0.5 * (left - right) / curvature; // in [-1/2, 1/2] at a maximum
      peak.location += offset * grid.width();
      peak.height = f[j] - 0.25 * (left - right) * offset;
      return peak;
    }
  } // namespace

  std::vector<Peak>
  find_peaks(const BinGrid &grid, const std::vector<double> &f, const double threshold)
  {
    std::vector<Peak> peaks;
    if (f.empty())
      return peaks;
    const double top = *std::max_element(f.begin(), f.end());
    if (!(top > 0))
      return peaks;
    for (int j = 0; j < static_cast<int>(f.size()); ++j)
      {
        if (!is_local_maximum(f, j) || f[j] < threshold * top)
          continue;
        const double base =
          std::max(lowest_before_higher(f, j, -1), lowest_before_higher(f, j, +1));
        if (f[j] - base >= threshold * top)
          peaks.push_back(refined_peak(grid, f, j));
      }
    return peaks;
  }

  std::vector<SupportInterval>
  density_support(const BinGrid &grid, const std::vector<double> &f, const double threshold)
  {
    std::vector<SupportInterval> support;
    if (f.empty())
      return support;
    const double level = threshold * *std::max_element(f.begin(), f.end());
    if (!(level > 0))
      return support;
    // where f crosses `level` between points j and j + 1 (linear in between)
    const auto crossing = [&](const unsigned int j) {
      return grid.center(j) + grid.width() * (level - f[j]) / (f[j + 1] - f[j]);
    };
    const unsigned int n = f.size();
    for (unsigned int j = 0; j < n; ++j)
      {
        if (f[j] < level)
          continue;
        const unsigned int first = j;
        while (j + 1 < n && f[j + 1] >= level)
          ++j;
        support.push_back({first > 0 ? crossing(first - 1) : grid.low,
                           j + 1 < n ? crossing(j) : grid.high});
      }
    return support;
  }
} // namespace poundfe
