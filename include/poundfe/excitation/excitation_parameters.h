// The `Ground motion` section (with `Record` and `Stochastic`) and the
// `Nodal forces` section, each declaring and checking its own entries
// (deal.II step-33 style).
#ifndef poundfe_excitation_excitation_parameters_h
#define poundfe_excitation_excitation_parameters_h

#include <poundfe/base/choices.h>
#include <poundfe/base/input_file.h>
#include <poundfe/excitation/records.h>
#include <poundfe/excitation/stochastic.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  enum class GroundMotionType
  {
    kanai_tajimi,
    clough_penzien,
    white_noise,
    record,
    none
  };

  const NameTable<GroundMotionType> &ground_motion_type_names();
  /// Only the two methods a user picks (white noise is a ground-motion type).
  const NameTable<StochasticMethod> &stochastic_method_names();
  const NameTable<EnvelopeKind>     &envelope_names();
  const NameTable<Soil>             &soil_names();
  const NameTable<RecordFileFormat> &record_format_names();
  const NameTable<RecordUnits>      &record_units_names();

  struct GroundMotionParameters
  {
    GroundMotionType type         = GroundMotionType::kanai_tajimi;
    double           scale_factor = 1.0;

    // Two horizontal components (Model/Dimension = 3).
    unsigned int n_components       = 1;
    double       incidence_angle    = 0.0; // degrees
    std::string  second_record_file = "";
    unsigned int second_seed        = 0; // 0: Seed + 1
    double       intensity_ratio    = 1.0; // sigma_2 / sigma_1 (stochastic pair)
    double       correlation        = 0.0; // of the stochastic pair before the rotation

    // The vertical component (Components = 3): a record, or an independent
    // sample of the same process scaled by vertical_ratio.
    std::string  third_record_file = "";
    unsigned int vertical_seed     = 0;          // 0: Seed + 2
    double       vertical_ratio    = 2.0 / 3.0; // sigma_z / sigma_x

    // Recorded motions.
    std::string      record_file       = "";
    RecordFileFormat record_format     = RecordFileFormat::automatic;
    RecordUnits      record_units      = RecordUnits::g;
    double           record_time_step  = 0.0;
    double           record_target_pga = 0.0; // in g; 0 keeps the record's PGA

    // Stochastic motions.
    Soil             soil               = Soil::medium;
    double           omega_g            = 10.0;
    double           zeta_g             = 0.4;
    double           omega_f            = 1.0;
    double           zeta_f             = 0.6;
    StochasticMethod method             = StochasticMethod::filtered_white_noise;
    double           cutoff_frequency   = 0.0; // spectral representation, rad/s; 0: min(pi/dt, 25 omega_g)
    unsigned int     n_frequencies      = 0;   // spectral representation; 0: cutoff * duration / pi
    double           spectral_intensity = 0.0; // S0; 0 = from the target PGA (or from D)
    double           noise_intensity_d  = 0.0; // D = pi S0 (white noise, thesis convention)
    double           target_pga         = 0.3; // in g
    double           peak_factor        = 3.0;
    double           duration           = 20.0;
    double           sample_interval    = 0.0; // 0 = analysis time step
    unsigned int     seed               = 1;
    unsigned int     realization        = 0;

    EnvelopeKind envelope             = EnvelopeKind::jennings;
    double       jennings_rise_end    = 2.0;
    double       jennings_plateau_end = 10.0;
    double       jennings_decay       = 0.3;
    double       saragoni_b           = 2.0;
    double       saragoni_c           = 0.5;
    double       shinozuka_alpha      = 0.2;
    double       shinozuka_beta       = 0.6;

    /// Kanai-Tajimi, Clough-Penzien or white noise: generated from xi.
    bool is_stochastic() const;
    /// Interval of the generated white noise: `Sample interval`, or the
    /// analysis time step when that is 0.
    double held_interval(double time_step) const;

    /// The parameters of the second horizontal component: the second
    /// record, or the same process with the second seed.
    GroundMotionParameters second_component() const;
    /// Components = 3: a vertical component besides the horizontal ones.
    bool has_vertical() const { return n_components == 3; }
    /// The parameters of the vertical component: the third record, or the
    /// same process with the vertical seed (scaled by vertical_ratio
    /// afterwards: correlate_second_component with no correlation).
    GroundMotionParameters vertical_component() const;

    /// Declare the `Ground motion` section (entered and left here).
    void declare(dealii::ParameterHandler &prm);
    /// The record files its entries name (Record/File, Second file, Third
    /// file), those given.
    std::vector<NamedInputFile> input_files() const;
    /// `time_step`: the analysis time step (the default sample interval).
    /// Throws InputError.
    void check(const InputFile &input, double time_step) const;

  private:
    /// The intensity ratio and correlation of a stochastic pair.
    void check_pair(const InputFile &input) const;
    /// The record files of the second and vertical components against
    /// Type and Components.
    void check_component_files(const InputFile &input) const;
    /// The vertical ratio and seed against Components.
    void check_vertical(const InputFile &input) const;
  };

  struct NodalForceParameters
  {
    std::vector<std::string> harmonic;    // 'building floor node dof amplitude omega phase'
    std::vector<std::string> tabulated;   // 'building floor node dof file'
    std::vector<std::string> white_noise; // 'building floor node dof S0'

    /// Declare the `Nodal forces` section (entered and left here); the
    /// entries are checked against the model by make_nodal_forces.
    void declare(dealii::ParameterHandler &prm);
    /// The force tables Tabulated names (each entry's fifth field).
    std::vector<NamedInputFile> input_files() const;
  };
} // namespace poundfe

#endif
