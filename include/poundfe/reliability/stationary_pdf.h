// The stationary probability density of a
// noisy system's response, from long runs (burn-in, then sampling) of
// several independent realizations split over MPI ranks.
//   Each realization r (the noise of seed and r) samples the displacement
//   x and velocity v of one DOF every `Sample interval` after the burn-in and
//   reduces its samples to counts on fixed grids (x, v, amplitude
//   a = sqrt(x^2 + v^2/omega^2), and the joint (x, v)) and to sums of the
//   values and their squares. That row goes through Monte Carlo's machinery
//   (run_realizations: realizations.csv, resume, interruption), and the
//   estimates come from the rows summed in realization order, so one rank
//   and many give the same bytes. Densities: histogram, and the Gaussian
//   kernel density of the binned data with Silverman's bandwidth; peaks
//   above a threshold (density.h). With `Parameter` and `Values`
//   (a SweepParameters, input/sweep.h) the command (commands/stationary_pdf_command.cc)
//   makes it a P-bifurcation study: one such run per value, then the density of x and its peaks against the
//   value. Theory: doc/theory.md §6.5.
#ifndef poundfe_reliability_stationary_pdf_h
#define poundfe_reliability_stationary_pdf_h

#include <poundfe/base/input_file.h>
#include <poundfe/reliability/density.h>
#include <poundfe/reliability/montecarlo.h>
#include <poundfe/reliability/stationary_pdf_parameters.h>

#include <mpi.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace poundfe
{
  struct GroundMotionParameters;

  /// The quantities' names in realizations.csv, pdf.csv and summary.json.
  inline const std::array<const char *, 3> pdf_quantities = {{"x", "v", "a"}};

  /// The DOF sampled (its equation and label) and the steps: first, first +
  /// every, ... <= last.
  struct PdfSampling
  {
    unsigned int  equation = 0;
    std::string   label;
    unsigned long first = 0, every = 1, last = 0; // steps
  };

  /// The grids of x, v and a and where each count goes in a realization's row:
  ///   n, sum x, sum x^2, sum v, sum v^2, sum a, sum a^2,
  ///   for x, v, a: below, bins..., above; then the joint (x, v) bins, x-major.
  struct PdfLayout
  {
    std::array<BinGrid, 3> grids;
    double                 omega = 1;
    std::string            steps; // 'first:every:last', part of the header

    unsigned int histogram(const unsigned int q) const { return 7 + q * (grids[0].n_bins + 2); }
    unsigned int joint() const { return histogram(3); }
    unsigned int size() const { return joint() + grids[0].n_bins * grids[1].n_bins; }
    double amplitude(const double x, const double v) const
    {
      return std::sqrt(x * x + v * v / (omega * omega));
    }

    std::vector<std::string> names() const;
    void accumulate(const std::vector<double> &x, const std::vector<double> &v,
                    std::vector<double> &row) const;
  };

  /// The estimates of one quantity from the summed rows.
  struct QuantityEstimate
  {
    double              mean = 0, variance = 0, outside = 0, bandwidth = 0;
    std::string         rule = "Silverman"; // how the bandwidth was chosen
    bool                widened   = false; // raised to the bin width
    std::vector<double> histogram, kde;
    std::vector<Peak>   peaks;
    std::vector<SupportInterval> support;
  };

  /// The estimates of quantity q (0: x, 1: v, 2: a) from the rows summed
  /// over the realizations, `total`.
  QuantityEstimate estimate_quantity(const PdfLayout &layout, const std::vector<double> &total,
                                     unsigned int q, const StationaryPdfParameters &p);

  /// What every realization of a stationary-PDF analysis shares.
  struct StationaryPdfSetup
  {
    PdfSampling sampling;
    PdfLayout   layout;
  };

  /// The DOF and steps of Stationary PDF/Response, checked against the run's
  /// length (`time_step`, the noise of `ground_motion`), and the grids: the
  /// given Range, or from a pilot realization 0 (the same on every rank).
  /// Throws InputError naming `input`, or NumericalError (pilot failed).
  StationaryPdfSetup setup_stationary_pdf(const Analysis &analysis, RealizationRunner &runner,
                                          const StationaryPdfParameters &parameters,
                                          const InputFile &input, double time_step,
                                          const GroundMotionParameters &ground_motion);

  /// A stationary-PDF analysis: its realizations' table, their rows summed
  /// and the estimates (rank 0; when n_samples > 0).
  struct StationaryPdfResult
  {
    MonteCarloTable                 table;
    std::vector<double>             total;
    unsigned long                   n_samples = 0;
    std::array<QuantityEstimate, 3> estimates;
  };

  /// Runs the realizations of `parameters` over the ranks of `comm`
  /// (run_realizations: `file` holds them, resumed, interruptible; progress
  /// counts from `offset`) and, on rank 0, the estimates.
  StationaryPdfResult run_stationary_pdf(const StationaryPdfSetup &setup, RealizationRunner &runner,
                                         const StationaryPdfParameters &parameters,
                                         const std::string &file, MPI_Comm comm,
                                         const std::string &label, Progress &progress,
                                         unsigned long offset);
} // namespace poundfe

#endif
