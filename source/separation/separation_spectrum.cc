// The response-spectrum route of the `separation` command: modal peaks of
// the Eurocode 8 elastic spectrum combined by SRSS and CQC. Equations and
// sources in include/poundfe/separation/separation_spectrum.h and
// doc/theory.md §7.1b.
#include <poundfe/separation/separation_spectrum.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/output/append_file.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/floor_response.h>
#include <poundfe/output/json_writer.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
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
    modes_for_spectrum(const Analysis &analysis, const unsigned int b, const unsigned int n_wanted)
    {
      const LinearSystem &system    = analysis.system;
      const auto          range     = analysis.model.equation_range(b);
      const SparseMatrix  mass      = block(system.mass, range);
      const SparseMatrix  stiffness = block(system.stiffness, range);
      const Vector        influence = system.influence.segment(range[0], range[1] - range[0]);
      const Eigensolver   solver    = analysis.input.modal.eigensolver;
      const unsigned int  most      = solver == Eigensolver::sparse ?
                                        max_sparse_modes(mass) :
                                        static_cast<unsigned int>(mass.rows());
      if (most == 0)
        analysis.input.fail("Modal analysis/Eigensolver",
                            "the sparse eigensolver finds no mode of building '" +
                              analysis.model.buildings[b].name + "' (" +
                              std::to_string(mass.rows()) +
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
                          const unsigned int n_modes)
  {
    const LinearSystem       &system = analysis.system;
    const SpectrumParameters &target = analysis.input.spectrum;
    const auto                range  = analysis.model.equation_range(b);
    const Modes               modes  = modes_for_spectrum(analysis, b, n_modes);
    const SparseMatrix        mass   = block(system.mass, range);
    const SparseMatrix damping = system.damping.rows() ? block(system.damping, range) : SparseMatrix();
    const Vector       influence = system.influence.segment(range[0], range[1] - range[0]);

    FloorResponse         floors(analysis.model);
    const Vector          zero = Vector::Zero(system.mass.rows());
    SpectrumModalResponse response;
    for (unsigned int i = 0; i < modes.n_modes(); ++i)
      {
        const Eigen::VectorXd phi   = modes.shapes.col(i); // mass-normalised
        const double          omega = modes.omega[i];
        const double          zeta  = modal_damping_ratio(damping, phi, omega);
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
  spectrum_peaks(const Analysis &analysis, const std::vector<AdjacentPair> &pairs)
  {
    const InputParameters &input = analysis.input;
    SpectrumPeaks          peaks;
    for (unsigned int b = 0; b < analysis.model.buildings.size(); ++b)
      peaks.buildings.push_back(
        spectrum_modal_response(analysis, b, input.separation.n_spectrum_modes));
    for (const AdjacentPair &pair : pairs)
      {
        peaks.levels.emplace_back();
        for (const CommonLevel &level : pair.levels)
          peaks.levels.back().push_back(
            {{combined_displacement(peaks.buildings[pair.left], level.sides[0]),
              combined_displacement(peaks.buildings[pair.right], level.sides[1])}});
      }
    const SpectrumParameters &s = input.spectrum;
    peaks.method = "response spectrum: EN 1998-1 " + design_spectrum_names().name(s.target) +
                   ", ground " + ground_type_names().name(s.ground_type) + ", a_g " +
                   number_text(s.design_ground_acceleration) + " g; " +
                   modal_combination_names().name(input.separation.modal_combination) +
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

  void
  write_spectrum_modes(const std::string &directory, const Model &model, const SpectrumPeaks &peaks)
  {
    std::string csv = "building,mode,period_s,damping_ratio,participation_factor,"
                      "effective_mass_ratio,cumulative_mass_ratio,Se_m_s2,Sd_m\n";
    for (unsigned int b = 0; b < peaks.buildings.size(); ++b)
      {
        const SpectrumModalResponse &r   = peaks.buildings[b];
        double                       sum = 0;
        for (unsigned int i = 0; i < r.n_modes(); ++i)
          {
            sum += r.effective_mass_ratio[i];
            csv += model.buildings[b].name + "," + std::to_string(i + 1);
            for (const double x : {2 * M_PI / r.omega[i], r.damping_ratio[i], r.participation[i],
                                   r.effective_mass_ratio[i], sum, r.spectral_acceleration[i],
                                   r.spectral_displacement[i]})
              csv += ',', append_number(csv, x);
            csv += '\n';
          }
      }
    write_file_atomically(directory + "/spectrum_modes.csv", csv);
  }

  void
  write_spectrum_summary(JsonWriter &json, const InputParameters &input, const Model &model,
                         const SpectrumPeaks &peaks)
  {
    const SpectrumParameters &s = input.spectrum;
    json.begin_object("response_spectrum")
      .value("spectrum", design_spectrum_names().name(s.target))
      .value("ground_type", ground_type_names().name(s.ground_type))
      .value("design_ground_acceleration_g", s.design_ground_acceleration)
      .value("modal_combination", modal_combination_names().name(input.separation.modal_combination))
      .begin_array("buildings");
    for (unsigned int b = 0; b < peaks.buildings.size(); ++b)
      {
        const SpectrumModalResponse &r = peaks.buildings[b];
        std::vector<double>          periods;
        for (const double w : r.omega)
          periods.push_back(2 * M_PI / w);
        json.begin_object()
          .value("name", model.buildings[b].name)
          .value("n_modes", r.n_modes())
          .value("cumulative_mass_ratio", r.cumulative_mass_ratio())
          .value("periods_s", periods)
          .value("damping_ratios", r.damping_ratio)
          .value("Sd_m", r.spectral_displacement)
          .end_object();
      }
    json.end_array();
    json.begin_array("pairs");
    for (const auto &pair : peaks.levels)
      {
        json.begin_object().begin_array("levels");
        for (const auto &level : pair)
          json.begin_object()
            .value("u_left_srss_m", level[0].srss)
            .value("u_right_srss_m", level[1].srss)
            .value("u_left_cqc_m", level[0].cqc)
            .value("u_right_cqc_m", level[1].cqc)
            .end_object();
        json.end_array().end_object();
      }
    json.end_array().end_object();
  }
} // namespace poundfe
