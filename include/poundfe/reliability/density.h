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
//   Sheather & Jones's plug-in bandwidth, "solve-the-equation" (S.J. Sheather
//     & M.C. Jones, J. R. Statist. Soc. B 53 (1991) 683-690, §5; M.P. Wand &
//     M.C. Jones, Kernel Smoothing, Chapman & Hall 1995, §3.6), for
//     multimodal densities, which Silverman's rule oversmooths:
//       h = [R(K) / (N S(alpha(h)))]^(1/5),  R(K) = 1/(2 sqrt(pi)),
//       alpha(h) = 1.357 [S(a) / T(b)]^(1/7) h^(5/7),
//       a = 0.920 IQR N^(-1/7),  b = 0.912 IQR N^(-1/9),
//       S(g) = sum_{i != j} phi4((X_i - X_j)/g) / (N (N-1) g^5),
//       T(g) = -sum_{i != j} phi6((X_i - X_j)/g) / (N (N-1) g^7),
//     phi4, phi6 the 4th and 6th derivatives of the normal density; on
//     binned data the pairs are those of the bin centres, the diagonal
//     (each sample with itself) taken out.
//   Peaks: local maxima of f whose height and whose prominence (the drop to
//     the higher of the lowest points between it and a higher maximum on
//     either side, or the range's end) are both at least `threshold` times
//     the global maximum, so sampling noise on a flank is no peak. An
//     interior peak is located between grid points by the parabola through
//     it and its two neighbours (vertex offset d = (f- - f+) / (2 (f- - 2 f0
//     + f+)) grid widths, height f0 - (f- - f+) d / 4).
//   Support: the x where the kernel density is at least `threshold` times its
//     maximum, as intervals (maximal runs of such grid points, each end
//     placed between its point and the next by linear interpolation of f).
//     A change in their number from one parameter value to the next is a
//     change of support, the "hard" bifurcation of a stationary measure
//     (L. Arnold, Random Dynamical Systems, Springer 1998, §9.2; thesis §3.2,
//     Fig. 3.3(a)). For a uniform density on [a, b] and a Gaussian kernel of
//     bandwidth h, f(b + d) = f(b - ∞) Φ(-d/h): the support ends at
//     b + h Φ⁻¹(1 - threshold) (3.09 h for 1e-3), its closed form.
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

  /// Sheather and Jones's bandwidth of the binned data (see the header;
  /// `iqr` the interquartile range): NaN when the equation has no root
  /// between 1e-3 and 10 times the normal-reference bandwidth, or the
  /// counts are too few (< 3) or the IQR is 0.
  double sheather_jones_bandwidth(const BinGrid &grid, const std::vector<double> &counts,
                                  double iqr);

  struct Peak
  {
    unsigned int index;    // bin
    double       location; // vertex of the parabola through the bin and its neighbours
    double       height;   // density there
  };

  struct SupportInterval
  {
    double low, high;
  };

  /// The support of `density` on `grid` (see the header), in ascending x.
  std::vector<SupportInterval> density_support(const BinGrid &grid, const std::vector<double> &density,
                                               double threshold);

  /// Peaks of `density` on `grid` (see the header), in ascending location.
  std::vector<Peak> find_peaks(const BinGrid &grid, const std::vector<double> &density,
                               double threshold);
} // namespace poundfe

#endif
