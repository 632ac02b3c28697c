// The response-spectrum route of the `separation` command: modal peaks of
// the Eurocode 8 elastic spectrum combined by SRSS and CQC. Equations and
// sources in include/poundfe/separation/separation_spectrum.h and
// doc/theory.md §7.1b.
#include <poundfe/separation/separation_spectrum.h>
#include <poundfe/assembly/modal_damping.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/output/floor_response.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <limits>
#include <cmath>
#include <numeric>

namespace poundfe
{
  double
  spectral_displacement(const SpectrumParameters &spectrum, const double period,
                        const double zeta)
  {
    const double t = period / (2 * M_PI);
    return spectrum.target_psa(zeta, period) * t * t;
  }

  double
  modal_damping_ratio(const SparseMatrix &damping, const Eigen::VectorXd &phi, const double omega)
  {
    if (damping.rows() == 0) // no damping assembled
      return 0;
    return phi.dot(damping * phi) / (2 * omega);
  }

  double
  modal_damping_ratio(const LinearSystem &system, const std::array<unsigned int, 2> range,
                      const Eigen::VectorXd &phi, const double omega)
  {
    const double sparse =
      system.damping.rows() ? modal_damping_ratio(block(system.damping, range), phi, omega) : 0;
    if (system.modal_damping.empty())
      return sparse;
    Vector x = Vector::Zero(system.n_equations()), modal = Vector::Zero(system.n_equations());
    x.segment(range[0], range[1] - range[0]) = phi;
    add_low_rank_damping_product(system.modal_damping, x, modal);
    return sparse + x.dot(modal) / (2 * omega);
  }

  unsigned int
  modes_for_mass(const std::vector<double> &ratio, const double mass_fraction,
                 const double single_mode_fraction)
  {
    const double total = std::accumulate(ratio.begin(), ratio.end(), 0.0);
    // a mode left out could carry up to the mass that is left
    if (total < mass_fraction || 1 - total > single_mode_fraction)
      return 0;
    unsigned int n   = 0;
    double       sum = 0;
    while (sum < mass_fraction)
      sum += ratio[n++];
    for (unsigned int i = n; i < ratio.size(); ++i)
      if (ratio[i] > single_mode_fraction)
        n = i + 1;
    return n;
  }

  double
  srss_combination(const std::vector<double> &u)
  {
    double sum = 0;
    for (const double x : u)
      sum += x * x;
    return std::sqrt(sum);
  }

  double
  cqc_combination(const std::vector<double> &u, const std::vector<double> &omega,
                  const std::vector<double> &zeta)
  {
    Assert(u.size() == omega.size() && u.size() == zeta.size(),
           dealii::ExcMessage("one peak, frequency and damping ratio per mode"));
    double sum = 0;
    for (std::size_t i = 0; i < u.size(); ++i)
      {
        sum += u[i] * u[i];
        for (std::size_t j = i + 1; j < u.size(); ++j)
          sum += 2 * modal_correlation(omega[i], zeta[i], omega[j], zeta[j]) * u[i] * u[j];
      }
    // rho_ij of Der Kiureghian's formula form a positive semi-definite
    // matrix; max() guards the rounding
    return std::sqrt(std::max(0.0, sum));
  }

  double
  SpectrumModalResponse::cumulative_mass_ratio() const
  {
    return std::accumulate(effective_mass_ratio.begin(), effective_mass_ratio.end(), 0.0);
  }

  namespace
  {
    /// The modes of building b the route combines: `n_wanted`, or by
    /// EN 1998-1 §4.3.3.3.1(3), doubling the count asked of the solver
    /// until the mass rule can tell (the dense solver gives every mode at once).
    Modes
    modes_for_spectrum(const Analysis &analysis, const unsigned int b, const unsigned int n_wanted,
                       const Eigensolver solver, const InputFile &input)
    {
      const LinearSystem &system    = analysis.system;
      const auto          range     = analysis.model.equation_range(b);
      const SparseMatrix  mass      = block(system.mass, range);
      const SparseMatrix  stiffness = block(system.stiffness, range);
      const Vector        influence = system.influence.segment(range[0], range[1] - range[0]);
      const unsigned int  most      = solver == Eigensolver::sparse ?
                                        max_sparse_modes(mass) :
                                        static_cast<unsigned int>(mass.rows());
      if (most == 0)
        input.fail("Modal analysis/Eigensolver",
                   "the sparse eigensolver finds no mode of building '" +
                     analysis.model.buildings[b].name + "' (" + std::to_string(mass.rows()) +
                     " equations) for the response spectrum; use dense or auto");
      if (n_wanted > 0)
        return compute_modes(mass, stiffness, influence, std::min(n_wanted, most), solver);
      for (unsigned int n = std::min(12u, most);; n = std::min(2 * n, most))
        {
          Modes modes = compute_modes(mass, stiffness, influence, n, solver);
          const unsigned int needed = modes_for_mass(modes.participating_mass_ratio);
          if (needed > 0 || modes.n_modes() < n || n == most)
            {
              const unsigned int keep = needed > 0 ? needed : modes.n_modes();
              modes.omega.resize(keep);
              modes.participating_mass_ratio.resize(keep);
              modes.shapes.conservativeResize(Eigen::NoChange, keep);
              return modes;
            }
        }
    }
  } // namespace

  SpectrumModalResponse
  spectrum_modal_response(const Analysis &analysis, const unsigned int b,
                          const unsigned int n_modes, const SpectrumParameters &target,
                          const Eigensolver eigensolver, const InputFile &input)
  {
    const LinearSystem &system = analysis.system;
    const auto          range  = analysis.model.equation_range(b);
    const Modes         modes  = modes_for_spectrum(analysis, b, n_modes, eigensolver, input);
    const SparseMatrix        mass   = block(system.mass, range);
    const Vector       influence = system.influence.segment(range[0], range[1] - range[0]);

    FloorResponse         floors(analysis.model);
    const Vector          zero = Vector::Zero(system.mass.rows());
    SpectrumModalResponse response;
    for (unsigned int i = 0; i < modes.n_modes(); ++i)
      {
        const Eigen::VectorXd phi   = modes.shapes.col(i); // mass-normalised
        const double          omega = modes.omega[i];
        const double          zeta  = modal_damping_ratio(system, range, phi, omega);
        const double          gamma = phi.dot(mass * influence);
        const double          sd    = spectral_displacement(target, 2 * M_PI / omega, zeta);
        response.omega.push_back(omega);
        response.damping_ratio.push_back(zeta);
        response.participation.push_back(gamma);
        response.effective_mass_ratio.push_back(modes.participating_mass_ratio[i]);
        response.spectral_acceleration.push_back(target.target_psa(zeta, 2 * M_PI / omega));
        response.spectral_displacement.push_back(sd);
        // the model's displacement in this mode's peak: the floors' mean ux
        Vector u = zero;
        u.segment(range[0], range[1] - range[0]) = gamma * sd * phi;
        floors.evaluate(0, u, zero, zero, 0);
        response.floor_displacement.push_back(floors.displacement());
      }
    return response;
  }

  CombinedDisplacement
  combined_displacement(const SpectrumModalResponse &response, const LevelInterpolation &where)
  {
    std::vector<double> u;
    for (const std::vector<double> &floors : response.floor_displacement)
      u.push_back(value_at(floors, where));
    return {srss_combination(u), cqc_combination(u, response.omega, response.damping_ratio)};
  }

  SpectrumPeaks
  spectrum_peaks(const Analysis &analysis, const std::vector<AdjacentPair> &pairs,
                 const SpectrumParameters &s, const SeparationParameters &separation,
                 const Eigensolver eigensolver, const InputFile &input)
  {
    SpectrumPeaks peaks;
    for (unsigned int b = 0; b < analysis.model.buildings.size(); ++b)
      peaks.buildings.push_back(spectrum_modal_response(analysis, b, separation.n_spectrum_modes,
                                                        s, eigensolver, input));
    for (const AdjacentPair &pair : pairs)
      {
        peaks.levels.emplace_back();
        for (const CommonLevel &level : pair.levels)
          peaks.levels.back().push_back(
            {{combined_displacement(peaks.buildings[pair.left], level.sides[0]),
              combined_displacement(peaks.buildings[pair.right], level.sides[1])}});
      }
    peaks.method = "response spectrum: EN 1998-1 " + design_spectrum_names().name(s.target) +
                   ", ground " + ground_type_names().name(s.ground_type) + ", a_g " +
                   number_text(s.design_ground_acceleration) + " g; " +
                   modal_combination_names().name(separation.modal_combination) +
                   " of the modes (";
    for (unsigned int b = 0; b < peaks.buildings.size(); ++b)
      {
        const unsigned int n = peaks.buildings[b].n_modes();
        peaks.method += (b ? "; " : "") + analysis.model.buildings[b].name + ": " +
                        std::to_string(n) + (n == 1 ? " mode, " : " modes, ") +
                        rounded(100 * peaks.buildings[b].cumulative_mass_ratio()) +
                        " % of the mass";
      }
    peaks.method += ")";
    return peaks;
  }

  /// The response-spectrum route's peaks, by `combination`, into the
  /// levels (no time-history value).
  void
  fill_from_spectrum(const SpectrumPeaks &spectrum, const ModalCombination combination,
                     std::vector<PairResult> &results)
  {
    for (std::size_t p = 0; p < results.size(); ++p)
      for (std::size_t l = 0; l < results[p].levels.size(); ++l)
        {
          LevelResult &level = results[p].levels[l];
          level.u_left       = spectrum.levels[p][l][0].of(combination);
          level.u_right      = spectrum.levels[p][l][1].of(combination);
          level.time_history = std::numeric_limits<double>::quiet_NaN();
        }
  }

} // namespace poundfe
