// Everything a parameter file (.prm or .json) can say, as plain data.
// Parsing uses deal.II's ParameterHandler, kept out of this header.
#ifndef poundfe_model_parameters_h
#define poundfe_model_parameters_h

#include <poundfe/laws/bouc_wen.h>
#include <poundfe/output/recorder_parameters.h>

#include <iosfwd>
#include <map>
#include <string>
#include <vector>

namespace poundfe
{
  struct BuildingParameters
  {
    std::string name = "";
    std::string type = "frame"; // frame | mesh | shear

    // Generated frames and shear buildings.
    unsigned int        n_storeys = 1;
    unsigned int        n_bays    = 1;
    std::vector<double> storey_heights{3.0};
    std::vector<double> bay_widths{6.0};
    std::vector<double> column_youngs_modulus{3.0e10};
    std::vector<double> column_area{0.16};
    std::vector<double> column_second_moment{2.133e-3};
    std::vector<double> beam_youngs_modulus{3.0e10};
    std::vector<double> beam_area{0.12};
    std::vector<double> beam_second_moment{1.6e-3};
    std::vector<double> column_mass_per_length{0.0};
    std::vector<double> beam_mass_per_length{0.0};
    std::vector<double> floor_masses{20000.0};
    std::string         base_fixity         = "fixed"; // fixed | pinned
    unsigned int        elements_per_member = 1;

    // Shear buildings.
    std::vector<double> storey_stiffnesses{5.0e6};
    std::vector<double> storey_damping{0.0};
    double              drawing_width = 0.0;

    // Frames from a Gmsh mesh.
    std::string               mesh_file = "";
    std::vector<unsigned int> group_ids{1};
    std::vector<double>       group_youngs_modulus{3.0e10};
    std::vector<double>       group_area{0.16};
    std::vector<double>       group_second_moment{2.133e-3};
    std::vector<double>       group_mass_per_length{0.0};

    // Bouc-Wen hinges at member ends (frames) and hysteretic storeys (shear).
    std::vector<std::string>  hinge_locations;  // column bases|column tops|column ends|beam ends
    std::vector<unsigned int> hinge_groups;     // empty: every group
    std::vector<double>       hinge_yield_moments{0.0};
    std::vector<double>       hinge_yield_rotations{0.0};
    std::vector<double>       hinge_stiffnesses{0.0}; // 0: factor 6 E I / L
    double                    hinge_stiffness_factor = 10.0;
    std::vector<double>       storey_yield_drifts; // empty or 0: elastic storey
    BoucWenParameters         hysteresis;          // shape; k and u_y come per spring

    // Rayleigh damping.
    std::string               damping_type  = "modes"; // none|modes|coefficients
    double                    damping_ratio = 0.05;
    std::vector<unsigned int> damping_modes{1, 2};
    double                    rayleigh_a0 = 0.0;
    double                    rayleigh_a1 = 0.0;
  };

  struct GroundMotionParameters
  {
    std::string type         = "kanai-tajimi"; // kanai-tajimi|clough-penzien|white-noise|record|none
    double      scale_factor = 1.0;

    // Recorded motions.
    std::string record_file        = "";
    std::string record_format      = "auto"; // auto | at2 | text
    std::string record_units       = "g";    // g | m/s^2
    double      record_time_step   = 0.0;
    double      record_target_pga  = 0.0; // in g; 0 keeps the record's PGA

    // Stochastic motions.
    std::string  soil              = "medium"; // firm|medium|soft|custom
    double       omega_g           = 10.0;
    double       zeta_g            = 0.4;
    double       omega_f           = 1.0;
    double       zeta_f            = 0.6;
    std::string  method            = "filtered-white-noise"; // or spectral-representation
    double       cutoff_frequency  = 0.0; // spectral representation, rad/s; 0: min(pi/dt, 25 omega_g)
    unsigned int n_frequencies     = 0;   // spectral representation; 0: cutoff * duration / pi
    double       spectral_intensity = 0.0; // S0; 0 = from the target PGA (or from D)
    double       noise_intensity_d = 0.0;  // D = pi S0 (white noise, thesis convention)
    double       target_pga        = 0.3;  // in g
    double       peak_factor       = 3.0;
    double       duration          = 20.0;
    double       sample_interval   = 0.0; // 0 = analysis time step
    unsigned int seed              = 1;
    unsigned int realization       = 0;

    std::string envelope = "jennings"; // none|jennings|saragoni-hart|shinozuka-sato
    double      jennings_rise_end     = 2.0;
    double      jennings_plateau_end  = 10.0;
    double      jennings_decay        = 0.3;
    double      saragoni_b            = 2.0;
    double      saragoni_c            = 0.5;
    double      shinozuka_alpha       = 0.2;
    double      shinozuka_beta        = 0.6;
  };

  struct ContactParameters
  {
    std::string law                  = "none"; // none or a contact law name
    double      stiffness            = 2.75e9;
    std::string damping_from         = "calibrated"; // given|formula|calibrated
    double      damping              = 0.0; // xi or xi_bar when given
    double      restitution          = 0.65;
    std::string hertz_damp_formula   = "muthukumar-desroches"; // or ye-li-zhu
    double      effective_mass       = 0.0; // 0: from the floor masses
    double      calibration_velocity = 1.0;
    bool        between_buildings    = true;
    bool        floor_to_column      = true;
    std::vector<std::string> barriers; // "building floor side gap"
    unsigned int event_refinement    = 4; // a step with a contact change: 2^r sub-steps
  };

  struct MonteCarloParameters
  {
    unsigned int        realizations = 100;
    std::vector<double> drift_limits{0.005, 0.01, 0.02}; // drift ratios
    unsigned int        histogram_bins = 20;
  };

  struct SubsetParameters
  {
    std::string  response  = "peak drift ratio"; // |peak roof displacement|peak contact force
    unsigned int building  = 1;
    unsigned int storey    = 0; // 0: the largest over the building's storeys
    double       threshold = 0.01;
    unsigned int samples_per_level       = 500;
    double       conditional_probability = 0.1;
    unsigned int max_levels              = 10;
    double       proposal_spread         = 1.0;
  };

  struct FragilityParameters
  {
    std::vector<double> pga_levels{0.1, 0.2, 0.3, 0.4, 0.5}; // g
    unsigned int        realizations_per_level = 50;
  };

  struct InputParameters
  {
    std::string file;
    std::string directory; // relative input paths are resolved against it

    std::string                     mass_matrix = "lumped";
    std::vector<double>             separations{0.05};
    std::vector<BuildingParameters> buildings;
    GroundMotionParameters          ground_motion;
    std::vector<std::string>        harmonic_forces;
    std::vector<std::string>        tabulated_forces;
    std::vector<std::string>        white_noise_forces;
    MonteCarloParameters            monte_carlo;
    SubsetParameters                subset;
    FragilityParameters             fragility;
    ContactParameters               contact;

    double      time_step     = 0.001;
    double      end_time      = 0.0; // 0 = length of the ground motion
    double      newmark_gamma = 0.5;
    double      newmark_beta  = 0.25;
    std::string linear_solver = "eigen-ldlt";

    // Newton-Raphson of nonlinear steps.
    double       newton_residual_tolerance = 1e-8;
    double       newton_energy_tolerance   = 1e-12;
    unsigned int newton_max_iterations     = 20;
    unsigned int max_step_cuts             = 10;
    std::string  tangent_update            = "auto"; // auto | woodbury | refactorize
    std::string  hysteresis_integration    = "trapezoidal"; // trapezoidal | backward-euler
    double       law_tolerance             = 1e-12;
    unsigned int law_max_iterations        = 30;

    std::string  output_directory = "results";
    double       output_interval  = 0.0; // 0 = every step
    double       vtu_interval     = 0.1; // 0 = no VTU
    bool         plots            = true;
    unsigned int n_modes          = 6;
    RecorderParameters recorders;

    /// Line of "set <path>" in the file (0 when unknown, e.g. JSON input).
    int line_of(const std::string &path) const;
    /// Path of an input file named in the parameter file.
    std::string resolve(const std::string &relative) const;

    std::map<std::string, int> lines;
  };

  /// Interval of the generated white noise: Ground motion/Stochastic/Sample
  /// interval, or the analysis time step when that is 0.
  double stochastic_sample_interval(const InputParameters &input);

  /// Read and check a .prm or .json file. Throws InputError.
  InputParameters read_parameters(const std::string &file);

  /// Print every parameter with its documentation and default.
  void print_parameters(std::ostream &out);
} // namespace poundfe

#endif
