// Density estimation of a stationary response from binned samples.
//   Histogram: p_i = c_i / (N w), c_i samples in bin i of width w, N every
//     sample (also those outside the range).
//   Gaussian kernel density on the bin centres from the binned data
//     (Silverman 1986, Density Estimation, Chapman & Hall, §3.5):
//       f(x_j) = 1/(N h) sum_i c_i phi((x_j - x_i) / h), phi the standard
//     normal density; the binning moves each sample by at most w/2, and
//     the sum is a quadrature of the kernel on the grid, exact to ~1e-8 when
//     h >= w (Poisson summation): callers keep h at least the bin width.
//   Silverman's rule of thumb (ibid., eq. 3.31):
//       h = 0.9 min(sigma, IQR / 1.34) N^(-1/5).
//   Peaks: local maxima of f whose height and whose prominence (the drop to
//     the higher of the lowest points between it and a higher maximum on
//     either side, or the range's end) are both at least `threshold` times
//     the global maximum, so sampling noise on a flank is no peak.
#ifndef poundfe_reliability_density_h
#define poundfe_reliability_density_h

#include <vector>

namespace poundfe
{
  /// n_bins equal bins over [low, high].
  struct BinGrid
  {
    double       low = 0, high = 1;
    unsigned int n_bins = 1;

    double width() const { return (high - low) / n_bins; }
    double center(unsigned int i) const { return low + (i + 0.5) * width(); }
    /// The bin of x: -1 below low, n_bins at or above high.
    int bin(double x) const;
  };

  /// Histogram density c_i / (n_total w).
  std::vector<double> histogram_density(const BinGrid &grid, const std::vector<double> &counts,
                                        double n_total);

  /// Gaussian kernel density of the binned data at `points`.
  std::vector<double> kernel_density(const BinGrid &grid, const std::vector<double> &counts,
                                     double n_total, double bandwidth,
                                     const std::vector<double> &points);
  /// The same at the bin centres.
  std::vector<double> kernel_density(const BinGrid &grid, const std::vector<double> &counts,
                                     double n_total, double bandwidth);

  /// Quantile p of the binned data (linear within a bin); `below` samples
  /// lie under the grid.
  double binned_quantile(const BinGrid &grid, const std::vector<double> &counts, double below,
                         double n_total, double p);

  /// 0.9 min(sigma, iqr / 1.34) n^(-1/5) (sigma alone when iqr is 0).
  double silverman_bandwidth(double sigma, double iqr, double n);

  struct Peak
  {
    unsigned int index;    // bin
    double       location; // bin centre
    double       height;   // density
  };

  /// Peaks of `density` on `grid` (see the header), in ascending location.
  std::vector<Peak> find_peaks(const BinGrid &grid, const std::vector<double> &density,
                               double threshold);
} // namespace poundfe

#endif
