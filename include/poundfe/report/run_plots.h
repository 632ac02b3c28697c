// The figures of a run (PNG through gnuplot, output/plots.h), drawn when
// the time history ends from the CSV files its recorders wrote and from the
// peaks the observers gathered: the peak profiles, roof displacement,
// ground motion, base shear, energy balance, hysteresis loops, floor
// spectra, phase portraits, contact forces and (3D) the impacts in plan.
// The run's summary (report/run_summary.h) calls it before it writes
// summary.json, which lists the figures drawn.
#ifndef poundfe_report_run_plots_h
#define poundfe_report_run_plots_h

#include <poundfe/dynamics/analysis.h>
#include <poundfe/excitation/excitation.h>
#include <poundfe/output/observer.h>
#include <poundfe/output/plots.h>
#include <poundfe/output/storey_forces.h>
#include <poundfe/report/run_parameters.h>

#include <array>
#include <string>
#include <vector>

namespace poundfe
{
  class PeakResponse;

  /// Curves a figure's key can name: a figure with more draws groups of them.
  constexpr unsigned int max_named_curves = 12;

  /// contact_force.png from <directory>/contact_force.csv, of the gap
  /// elements that touched (a force other than 0 in some row; the title
  /// says how many of the recorded ones): a curve per gap element when
  /// there are at most max_named_curves, else a curve per pair of buildings
  /// (or a building and a barrier) with such gaps between them, the total
  /// force of its gaps (of the max_named_curves pairs with the largest
  /// peaks, when there are more), given to gnuplot as data blocks. No gap
  /// touched: a line at 0 titled so. Without a readable file: no curves.
  Plot contact_force_plot(const Model &model, const std::string &directory);

  /// energy.png from energy.csv: the terms of the model's energy balance
  /// in kJ, each in its own dark colour, and a panel with the contact and
  /// friction energies (kJ) and the balance error (a ratio, right axis).
  Plot energy_plot(const Model &model);

  /// What opens the title of a figure of the whole model: "Building A: ",
  /// "Buildings A and B: ", "Buildings A, B and C: ", or "12 buildings: "
  /// past four (the key names the curves drawn).
  std::string buildings_in_title(const Model &model);
  /// The titles of a run's figures of the whole model (profiles, roof
  /// displacement, base shear, energy, floor spectra, contact forces,
  /// impacts in plan) opened by buildings_in_title.
  void name_buildings_in_titles(std::vector<Plot> &plots, const Model &model);

  class RunPlots
  {
  public:
    /// `files`: those the run's observers write (the recorders' CSV files,
    /// the VTU index): a figure is drawn of each one it knows. Every
    /// argument must outlive this object.
    RunPlots(const Analysis &analysis, const RunParameters &parameters,
             const Excitation &excitation, const PeakResponse &peaks,
             const BaseShearPeaks &base_shears, const std::string &directory,
             const std::vector<std::string> &files);

    /// The figures, drawn into the directory; returns the files drawn.
    std::vector<std::string> draw(const ResponseView &state) const;

  private:
    /// Whether this run writes `file` (not: whether it exists).
    bool writes(const std::string &file) const;
    /// x against x' of each equation of a one- or two-DOF model, stick marked.
    void draw_phase_portraits(std::vector<Plot> &plots) const;
    /// drift_profile.png and acceleration_profile.png (with the drift limits).
    std::array<Plot, 2> profile_plots() const;
    /// The profile of building b along x (d = 0) or y (d = 1, a 3D model:
    /// `plan`) onto `plot`: its peak drift ratios (`drift`) or its peak
    /// absolute floor accelerations from the ground's `pga`.
    void add_profile(Plot &plot, unsigned int b, unsigned int d, bool plan, bool drift,
                     double pga) const;
    /// roof_displacement.png, from floor_displacement.csv (3D: the mass
    /// centre's x and y).
    Plot roof_plot() const;
    /// base_shear.png, from base_shear.csv.
    Plot base_shear_plot() const;
    /// The ground motion's peak, m/s^2 (0 without one).
    double peak_ground_acceleration() const;
    /// hysteresis_<label>.png: one loop per building.
    void draw_hysteresis(const ResponseView &state, std::vector<Plot> &plots) const;
    /// PSA of every floor and of the ground against the period (floor_spectra.csv).
    Plot floor_spectra_plot() const;

    const Analysis                 &analysis;
    const RunParameters            &parameters;
    const Excitation               &excitation;
    const PeakResponse             &peaks;
    const BaseShearPeaks           &base_shears;
    const std::string              &directory;
    const std::vector<std::string> &files;
  };
} // namespace poundfe

#endif
