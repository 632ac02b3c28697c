// The `stationary-pdf` command: the stationary probability density of a
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
//   above a threshold (reliability/density.h). With `Parameter` and `Values`
//   (a SweepParameters, input/sweep.h) it is a P-bifurcation study: one
//   such run per value, then the density of x and its peaks against the
//   value. Theory: doc/theory.md §6.5.
#ifndef poundfe_reliability_stationary_pdf_h
#define poundfe_reliability_stationary_pdf_h

#include <poundfe/input/input_parameters.h>

#include <mpi.h>

#include <string>

namespace poundfe
{
  /// The `stationary-pdf` command, on every rank of `comm`. With a sampling
  /// time the runs end at burn-in + sampling time.
  int stationary_pdf_command(const InputParameters &input, const std::string &output_directory,
                             MPI_Comm comm);
} // namespace poundfe

#endif
