// Histogram, binned Gaussian kernel density, Silverman's bandwidth and peaks
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
          peaks.push_back({static_cast<unsigned int>(j), grid.center(j), f[j]});
      }
    return peaks;
  }
} // namespace poundfe
