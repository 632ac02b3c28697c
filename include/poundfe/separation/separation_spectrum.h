// The response-spectrum route of the `separation` command
// (`Separation/Peak displacements = response spectrum`): the peak floor
// displacements of each building by modal combination of the Eurocode 8
// elastic spectrum, no time history.
//
//   Modes of building b on its own equations (K phi = w^2 M phi, phi
//   mass-normalised, dynamics/modal.h), r = 1 on every ux equation:
//     Gamma_i = phi_i^T M r / phi_i^T M phi_i = phi_i^T M r,
//     effective mass ratio Gamma_i^2 / r^T M r,
//     zeta_i  = phi_i^T C phi_i / (2 w_i)  (the modal damping of the assembled C),
//     Sd_i    = Se(T_i, zeta_i) (T_i / 2 pi)^2                 (EN 1998-1 eq. 3.7),
//       Se the horizontal elastic spectrum (eq. 3.2-3.5) with its damping
//       correction eta(zeta_i) = sqrt(10 / (5 + 100 zeta_i)) >= 0.55 (eq. 3.6)
//       at the mode's own damping ratio;
//     u_i(y)  = Gamma_i phi_i(y) Sd_i, phi_i(y) the mean ux of the floor's
//       joints (output/floor_response.h), interpolated linearly in height to a
//       common level as the time-history route does (LevelInterpolation).
//   Combination at each floor or level:
//     SRSS u = sqrt(sum_i u_i^2)                          (EN 1998-1 eq. 4.16)
//     CQC  u = sqrt(sum_i sum_j rho_ij u_i u_j), rho_ij the correlation of
//          modes i and j (Der Kiureghian 1981; modal_correlation()).
//   Modes: a given number, or the fewest whose effective masses sum to at
//   least 90 % of the mass and that include every mode above 5 % (EN 1998-1
//   §4.3.3.3.1(3)).
// Sources: CEN, EN 1998-1:2004 Eurocode 8, Part 1, §3.2.2.2 (eq. 3.2-3.7),
// §4.3.3.3, §4.4.2.7; Der Kiureghian, A. (1981), A response spectrum method
// for random vibration analysis of MDF systems, Earthquake Engineering and
// Structural Dynamics 9, 419-435; Chopra, A. K., Dynamics of Structures,
// 4th ed. (2012), §13.2 and §13.7.
#ifndef poundfe_separation_separation_spectrum_h
#define poundfe_separation_separation_spectrum_h

#include <poundfe/dynamics/analysis.h>
#include <poundfe/separation/separation.h>
#include <poundfe/excitation/spectrum_parameters.h>

#include <array>
#include <string>
#include <vector>

namespace poundfe
{
  /// Sd(T, zeta) = Se(T, zeta) (T / 2 pi)^2 of the Spectrum section's target, m.
  double spectral_displacement(const SpectrumParameters &spectrum, double period, double zeta);

  /// phi^T C phi / (2 omega) of a mass-normalised mode phi.
  double modal_damping_ratio(const SparseMatrix &damping, const Eigen::VectorXd &phi,
                             double omega);
  /// The same for a mode phi of the building with the equations `range`,
  /// C = its block of the sparse C plus its modal part (assembly/modal_damping.h).
  double modal_damping_ratio(const LinearSystem &system, std::array<unsigned int, 2> range,
                             const Eigen::VectorXd &phi, double omega);

  /// How many of the modes (their effective mass ratios, in order) EN 1998-1
  /// §4.3.3.3.1(3) takes: the fewest reaching `mass_fraction` (0.9) and every
  /// mode above `single_mode_fraction` (0.05). 0 when the modes given cannot
  /// tell: their sum stays below the fraction, or the mass they leave out
  /// could hide a mode above the single-mode fraction.
  unsigned int modes_for_mass(const std::vector<double> &effective_mass_ratio,
                              double mass_fraction = 0.9, double single_mode_fraction = 0.05);

  /// SRSS and CQC of modal peaks u_i of modes (omega_i, zeta_i).
  double srss_combination(const std::vector<double> &u);
  double cqc_combination(const std::vector<double> &u, const std::vector<double> &omega,
                         const std::vector<double> &zeta);

  /// One building's modes under the spectrum.
  struct SpectrumModalResponse
  {
    std::vector<double> omega, damping_ratio, participation, effective_mass_ratio;
    std::vector<double> spectral_acceleration; // Se(T_i, zeta_i), m/s^2
    std::vector<double> spectral_displacement; // Sd_i, m
    /// Per mode: Gamma_i phi_i Sd_i at every floor of the model
    /// (FloorResponse::index; the other buildings' floors 0), m.
    std::vector<std::vector<double>> floor_displacement;

    unsigned int n_modes() const { return omega.size(); }
    double       cumulative_mass_ratio() const;
  };

  /// Building b's modes, `n_modes` of them (0: EN 1998-1 §4.3.3.3.1(3)),
  /// by `eigensolver` (Modal analysis/Eigensolver), under the spectrum
  /// `target`. Throws InputError naming `input` when the sparse solver
  /// finds no mode.
  SpectrumModalResponse spectrum_modal_response(const Analysis &analysis, unsigned int building,
                                                unsigned int n_modes,
                                                const SpectrumParameters &target,
                                                Eigensolver eigensolver, const InputFile &input);

  /// The combined peak displacement at a floor or common level.
  struct CombinedDisplacement
  {
    double srss = 0, cqc = 0;
    double of(ModalCombination combination) const
    {
      return combination == ModalCombination::cqc ? cqc : srss;
    }
  };
  CombinedDisplacement combined_displacement(const SpectrumModalResponse &response,
                                             const LevelInterpolation    &where);

  /// The route on every building and pair: per pair, per common level, the
  /// left and right building's combined peaks.
  struct SpectrumPeaks
  {
    std::vector<SpectrumModalResponse>                            buildings;
    std::vector<std::vector<std::array<CombinedDisplacement, 2>>> levels;
    std::string                                                   method; // for the reports
  };
  /// The route of the spectrum `target`, Separation/Number of modes and
  /// Modal combination of `separation`, by `eigensolver`.
  SpectrumPeaks spectrum_peaks(const Analysis &analysis, const std::vector<AdjacentPair> &pairs,
                               const SpectrumParameters &target,
                               const SeparationParameters &separation, Eigensolver eigensolver,
                               const InputFile &input);

  /// The route's peaks, by `combination`, into the levels of `results` (no
  /// time-history value: NaN).
  void fill_from_spectrum(const SpectrumPeaks &spectrum, ModalCombination combination,
                          std::vector<PairResult> &results);
} // namespace poundfe

#endif
