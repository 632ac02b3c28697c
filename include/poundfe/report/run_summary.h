// The run's closing outputs, written when the time history ends (also
// after a failure or an interruption): summary.json, impacts.csv, the peak
// profiles (drift_profile.csv, acceleration_profile.csv) and, drawn by
// RunPlots (report/run_plots.h), the PNG plots of whatever CSV time series
// the recorders wrote. summary.json's `files` lists every file the run wrote.
#ifndef poundfe_report_run_summary_h
#define poundfe_report_run_summary_h

#include <poundfe/dynamics/analysis.h>
#include <poundfe/excitation/excitation.h>
#include <poundfe/output/drift_limits.h>
#include <poundfe/report/run_parameters.h>
#include <poundfe/output/observer.h>

#include <poundfe/output/plan_response.h>
#include <poundfe/output/storey_forces.h>

#include <array>
#include <string>
#include <vector>

namespace poundfe
{
  class JsonWriter;
  class MemoryResults;
  class PeakResponse;
  class ResponseRange;
  class SectionLimitStates;

  /// The model's size and whole-model modes (run and modal summaries).
  void write_model(JsonWriter &json, const Analysis &analysis);
  /// "gravity": the gravity state the dynamics start from (load steps,
  /// peak displacement, the vertical load each building carries to its
  /// base); nothing without Model/Gravity analysis.
  void write_gravity_state(JsonWriter &json, const GravityState &gravity);
  /// Frequencies, periods and participating mass ratios under `key`.
  void write_modes(JsonWriter &json, const std::string &key, const Modes &modes);
  /// Building b's damping: its Type, the Rayleigh coefficients (0 for modal
  /// damping) and, for modal damping, the ratio it gives each damped mode.
  void write_damping(JsonWriter &json, const Analysis &analysis, unsigned int b);

  class RunSummary : public StepObserver
  {
  public:
    /// `solver` and `tangent_update` name the integrator's choices; `files`
    /// are those the other observers write (recorders, VTU index); `range`'s
    /// warnings go to "warnings"; `base_shears` and `plan` (at the steps)
    /// must be observed with it. With `memory` the texts go there
    /// (output/table_writer.h), no file is written and nothing is drawn.
    /// `section_limits` (observed with it; nullptr: no fibre members): the
    /// members' limit states in summary.json, each storey's damage state in
    /// drift_profile.csv.
    RunSummary(const Analysis &analysis, const RunParameters &parameters,
               const Excitation &excitation, const PeakResponse &peaks,
               const ResponseRange &range, const BaseShearPeaks &base_shears,
               const PlanResponse &plan, const std::string &directory, bool plots,
               const std::string &solver, const std::string &tangent_update,
               std::vector<std::string> files, MemoryResults *memory = nullptr,
               const SectionLimitStates *section_limits = nullptr);

    void observe_step(const ResponseView &) override {} // the others observe for it
    void finish(const ResponseView &state, const RunStatus &status) override;

  private:
    void write_profiles() const;
    /// demands_<building>.csv (output/demand_table.h), Output/Demand tables; the files.
    std::vector<std::string> write_demand_tables(const ResponseView &state) const;
    void write_impacts(const ResponseView &state) const;
    /// summary.json, in the order of its keys: status, model, ground
    /// motion, buildings, hinges, gaps, springs and friction, energy and
    /// Newton, the analysis settings and the files.
    void write_json(const ResponseView &state, const RunStatus &status,
                    const std::vector<std::string> &files) const;
    /// "buildings": Rayleigh coefficients, modes, peak storey responses, drift checks.
    void write_buildings(JsonWriter &json) const;
    /// A 3D model's storey (flat floor index i): its peaks along y and about z.
    void write_storey_plan(JsonWriter &json, unsigned int i) const;
    /// A 3D model's "ratios": what each ratio of the summary is divided by.
    void write_ratio_definitions(JsonWriter &json) const;
    /// "hinges": yield, peak and plastic deformation, ductility, force, energy.
    void write_hinges(JsonWriter &json, const ResponseView &state) const;
    /// "contact" (the law) and "gaps": impacts, peak force, penetration, impulse.
    void write_gaps(JsonWriter &json, const ResponseView &state) const;
    /// "energy" (the balance's terms) and "newton" (iteration statistics).
    void write_energy_and_newton(JsonWriter &json, const ResponseView &state) const;
    /// "analysis" (the integrator, steps, solver, wall time) and "output".
    void write_run(JsonWriter &json, const RunStatus &status,
                   const std::vector<std::string> &files) const;
    /// The drift limits of the input against building b's peak drift ratios.
    std::vector<DriftCheck> drift_checks(unsigned int b) const;
    /// Building b's "drift_limits" in summary.json (nothing without limits).
    void write_drift_checks(JsonWriter &json, unsigned int b) const;

    const Analysis      &analysis;
    const RunParameters &parameters;
    const Excitation   &excitation;
    const PeakResponse &peaks;
    const ResponseRange &range;
    const std::string   directory;
    const bool          plots;
    const std::string   solver, tangent_update;
    const std::vector<std::string> files;
    /// Each building's peak base shear, for summary.json.
    const BaseShearPeaks &base_shears;
    /// 3D buildings: rotations, irregularity ratios, base shears and torque.
    const PlanResponse &plan;
    MemoryResults      *memory;
    const SectionLimitStates *section_limits;
  };
} // namespace poundfe

#endif
