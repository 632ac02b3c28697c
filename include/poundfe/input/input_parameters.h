// Everything a parameter file (.prm or .json) says: the sections of every
// module, each declared and checked by its own struct, and where the file
// is (for messages and relative paths). Only the commands see this whole;
// the engine gets the parts it needs (e.g. TimeIntegrationParameters).
#ifndef poundfe_input_input_parameters_h
#define poundfe_input_input_parameters_h

#include <poundfe/assessment/ida_parameters.h>
#include <poundfe/assessment/msa_parameters.h>
#include <poundfe/assessment/selection_parameters.h>
#include <poundfe/dynamics/bifurcation.h>
#include <poundfe/dynamics/initial_conditions.h>
#include <poundfe/dynamics/modal_parameters.h>
#include <poundfe/dynamics/pushover_parameters.h>
#include <poundfe/reliability/random_parameters.h>
#include <poundfe/reliability/reliability_analysis_parameters.h>
#include <poundfe/reliability/reliability_parameters.h>
#include <poundfe/hazard/site_hazard_parameters.h>
#include <poundfe/separation/mitigation_parameters.h>
#include <poundfe/separation/separation_parameters.h>
#include <poundfe/reliability/stationary_pdf_parameters.h>
#include <poundfe/input/sweep.h>
#include <poundfe/base/input_file.h>
#include <poundfe/excitation/excitation_parameters.h>
#include <poundfe/excitation/spectrum_parameters.h>
#include <poundfe/integration/time_integration_parameters.h>
#include <poundfe/model/contact_parameters.h>
#include <poundfe/model/friction_parameters.h>
#include <poundfe/model/parameters.h>
#include <poundfe/output/drift_limits.h>
#include <poundfe/output/section_limits.h>
#include <poundfe/output/output_parameters.h>
#include <poundfe/sections/section_parameters.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  /// A change to a parameter file's value applied before the file is checked:
  /// path "Section/Subsection/Entry" names a numeric entry; "Section/Entry:k"
  /// the k-th (1-based) whitespace-separated field of the first ';'-separated
  /// item of a list entry (e.g. "Nodal forces/Harmonic:5", the amplitude).
  struct ParameterOverride
  {
    std::string path;
    std::string value;
  };

  struct InputParameters : InputFile
  {
    ModelParameters           model;       // Model, Building <i>
    ContactParameters         contact;     // Contact
    SpringParameters          springs;     // Springs
    FrictionParameters        friction;    // Friction
    GroundMotionParameters    ground_motion;
    NodalForceParameters      nodal_forces;
    TimeIntegrationParameters time_integration; // and Contact/Event refinement
    InitialConditionParameters initial_conditions;
    OutputParameters          output;
    ModalParameters           modal;       // Modal analysis
    MonteCarloParameters      monte_carlo;
    SubsetParameters          subset;
    ReliabilityAnalysisParameters reliability; // Reliability (algebraic limit states)
    RandomParameterParameters     random_parameters; // Random parameters (time histories)
    FragilityParameters       fragility;
    StationaryPdfParameters   stationary_pdf;
    SweepParameters           sweep;
    BifurcationParameters     bifurcation;
    SiteHazardParameters      site_hazard;
    DriftLimitParameters      drift_limits;
    SectionLimitParameters    section_limits; // the fibre members' limit states
    SeparationParameters      separation;
    MitigationParameters      mitigation;  // Mitigation (the mitigation command)
    SpectrumParameters        spectrum;    // Spectrum (response spectra)
    SectionsParameters        sections;    // Sections (fibre cross-sections)
    MomentCurvatureParameters moment_curvature; // Moment curvature
    PushoverParameters        pushover;    // Pushover (the pushover command)
    IdaParameters             ida;         // IDA (the ida command)
    MsaParameters             msa;         // MSA (the msa command)
    SelectionParameters       selection;   // Selection (the select-records command)
    /// The overrides the file was read with (a sweep adds its own to them).
    std::vector<ParameterOverride> overrides;
    /// Every entry's value as read (defaults included), by its path
    /// "Section/Subsection/Entry", in declaration order.
    std::vector<std::pair<std::string, std::string>> values;

    /// Declare every section, with `model.buildings.size()` buildings and
    /// `sections.sections.size()` cross-sections.
    void declare(dealii::ParameterHandler &prm);
    /// After parsing: hand the hysteresis settings of Time integration to
    /// the buildings' laws, then check every section. Throws InputError.
    void finalize();
    /// A stochastic motion (or white-noise force) is generated whole before
    /// a run: its samples are bounded like the steps (Maximum number of steps).
    void check_stochastic_samples() const;
    /// The Contact section against Contact/Model (rigid contact takes e = 0).
    void check_contact();
  };

  /// Read and check a .prm or .json file. Throws InputError.
  InputParameters read_parameters(const std::string &file);

  /// Read a .prm or .json file, set the overrides (in order, each through
  /// the entry's pattern), then check everything as for the file alone. An
  /// unknown path or a value the entry refuses is an InputError naming the
  /// path. (Used by sweeps: one InputParameters per swept value.)
  InputParameters read_parameters(const std::string &file,
                                  const std::vector<ParameterOverride> &overrides);

  /// What decides the rows a resuming command (montecarlo, fragility, ...)
  /// keeps from an earlier run in its output directory: the command's name
  /// (path "command") and every entry of `input` but those that only say how
  /// many realizations to run or how to report them (Output, Drift limits,
  /// the realization counts, the fragility levels, each level in its own
  /// directory). output_directory.h compares it with the earlier run's.
  std::vector<std::pair<std::string, std::string>>
  resume_inputs(const InputParameters &input, const std::string &command);

  /// Print every parameter with its documentation and default.
  void print_parameters(std::ostream &out);
} // namespace poundfe

#endif
