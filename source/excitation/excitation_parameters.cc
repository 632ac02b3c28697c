#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/excitation/excitation_parameters.h>

#include <poundfe/excitation/ground_motion_bounds.h>
#include <poundfe/excitation/ground_motion_filter.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <sstream>
#include <tuple>
#include <utility>

namespace poundfe
{
  namespace Patterns = dealii::Patterns;

  const NameTable<GroundMotionType> &
  ground_motion_type_names()
  {
    static const NameTable<GroundMotionType> table(
      {{GroundMotionType::kanai_tajimi, "kanai-tajimi"},
       {GroundMotionType::clough_penzien, "clough-penzien"},
       {GroundMotionType::white_noise, "white-noise"},
       {GroundMotionType::record, "record"},
       {GroundMotionType::none, "none"}});
    return table;
  }

  const NameTable<StochasticMethod> &
  stochastic_method_names()
  {
    static const NameTable<StochasticMethod> table(
      {{StochasticMethod::filtered_white_noise, "filtered-white-noise"},
       {StochasticMethod::spectral_representation, "spectral-representation"}});
    return table;
  }

  const NameTable<EnvelopeKind> &
  envelope_names()
  {
    static const NameTable<EnvelopeKind> table({{EnvelopeKind::none, "none"},
                                                {EnvelopeKind::jennings, "jennings"},
                                                {EnvelopeKind::saragoni_hart, "saragoni-hart"},
                                                {EnvelopeKind::shinozuka_sato, "shinozuka-sato"}});
    return table;
  }

  const NameTable<Soil> &
  soil_names()
  {
    static const NameTable<Soil> table(
      {{Soil::firm, "firm"}, {Soil::medium, "medium"}, {Soil::soft, "soft"}, {Soil::custom, "custom"}});
    return table;
  }

  const NameTable<RecordFileFormat> &
  record_format_names()
  {
    static const NameTable<RecordFileFormat> table({{RecordFileFormat::automatic, "auto"},
                                                    {RecordFileFormat::at2, "at2"},
                                                    {RecordFileFormat::text, "text"}});
    return table;
  }

  const NameTable<RecordUnits> &
  record_units_names()
  {
    static const NameTable<RecordUnits> table(
      {{RecordUnits::g, "g"}, {RecordUnits::m_per_s2, "m/s^2"}});
    return table;
  }

  bool
  GroundMotionParameters::is_stochastic() const
  {
    return type == GroundMotionType::kanai_tajimi || type == GroundMotionType::clough_penzien ||
           type == GroundMotionType::white_noise;
  }

  double
  GroundMotionParameters::held_interval(const double time_step) const
  {
    return sample_interval > 0 ? sample_interval : time_step;
  }

  namespace
  {
    /// The Record subsection of Ground motion (a recorded accelerogram).
    void
    declare_record_entries(dealii::ParameterHandler &prm, GroundMotionParameters &p)
    {
      prm.enter_subsection("Record");
      prm.add_parameter("Second file", p.second_record_file,
                        "The second horizontal component (Components = 2), along y before "
                        "the incidence rotation; same format and units as File, scaled as "
                        "File is (to Target PGA by its own PGA, then times Scale factor). "
                        "Unit: -.");
      prm.add_parameter("Third file", p.third_record_file,
                        "The vertical component (Components = 3), upward positive: uz of "
                        "every joint of a 3D frame, uy of every node of a 2D frame; not "
                        "rotated by the incidence angle; same format and units as File, scaled "
                        "by File's factor (Target PGA / PGA of File, times Scale factor), so "
                        "the recorded vertical-to-horizontal ratio is kept. Unit: -.");
      prm.add_parameter("File", p.record_file,
                        "PEER .AT2, or text with one (acceleration) or two (time, "
                        "acceleration) columns; relative to this parameter file. Unit: -.");
      add_choice(prm, "Format", p.record_format,
                 "auto: PEER AT2 for a .at2 file (any case), text otherwise. Unit: -.",
                 record_format_names());
      add_choice(prm, "Units", p.record_units,
                 "Units of the values in a text file (AT2 files are in g). Unit: -.",
                 record_units_names());
      prm.add_parameter("Time step", p.record_time_step,
                        "Sample interval of a one-column text record. Unit: s.");
      prm.add_parameter("Target PGA", p.record_target_pga,
                        "Scale the record to this PGA (0: keep it); Scale factor then "
                        "multiplies it: the PGA is Target PGA x Scale factor. At most 10 g, and so is "
                        "Target PGA x Scale factor (more than twice the largest ground acceleration "
                        "recorded). Unit: g.");
      prm.leave_subsection();
    }

    /// Stochastic: the process (its filter and method) and its intensity.
    void
    declare_stochastic_process_entries(dealii::ParameterHandler &prm, GroundMotionParameters &p)
    {
      add_choice(prm, "Soil", p.soil,
                 "Filter parameters preset (Der Kiureghian & Neuenhofer 1992): firm "
                 "15 rad/s, 0.6; medium 10, 0.4; soft 5, 0.2; custom uses omega_g, "
                 "zeta_g. Clough-Penzien presets use omega_f = omega_g/10, zeta_f 0.6. Unit: -.",
                 soil_names());
      prm.add_parameter("omega_g", p.omega_g, "Ground filter frequency (custom). Unit: rad/s.");
      prm.add_parameter("zeta_g", p.zeta_g, "Ground filter damping ratio (custom). "
                        "Unit: dimensionless.");
      prm.add_parameter("omega_f", p.omega_f, "Clough-Penzien high-pass frequency (custom). "
                        "Unit: rad/s.");
      prm.add_parameter("zeta_f", p.zeta_f, "Clough-Penzien high-pass damping (custom). "
                        "Unit: dimensionless.");
      add_choice(prm, "Method", p.method,
                 "Kanai-Tajimi/Clough-Penzien samples: white noise through the filter "
                 "(exact over each held interval), or the spectral representation "
                 "(sum of cosines with random phases). Unit: -.",
                 stochastic_method_names());
      prm.add_parameter("Cutoff frequency", p.cutoff_frequency,
                        "Spectral representation: upper frequency w_u (0: min(pi/dt, "
                        "25 omega_g)); needs dt <= pi/w_u. Unit: rad/s.");
      prm.add_parameter("Number of frequencies", p.n_frequencies,
                        "Spectral representation: N (0: w_u duration / pi, so the sample "
                        "does not repeat within twice its duration), at most 10^6 (w_u "
                        "duration / pi is 3e4 for 100 rad/s over 1000 s). Unit: count.",
                        dealii::Patterns::Integer(0, 1000000));
      prm.add_parameter("S0", p.spectral_intensity,
                        "Two-sided PSD intensity of the white noise; 0: from D, or "
                        "from the target PGA and peak factor. At most what gives 3 standard "
                        "deviations of 10 g: of the filtered motion, or of a white noise below "
                        "25 Hz, sqrt(2 S0 x 2 pi 25 rad/s), whatever the time step (S0 <= 3.4 for "
                        "white noise). Unit: m^2/s^3.");
      prm.add_parameter("D", p.noise_intensity_d,
                        "White-noise intensity in the thesis's convention <w(t) w(t')> = "
                        "2 D delta(t - t'), D = pi S0 (used when S0 = 0), bounded as S0. "
                        "Unit: m^2/s^3.");
      prm.add_parameter("Target PGA", p.target_pga,
                        "Expected PGA (Peak factor x the stationary standard deviation) that "
                        "sets S0 when S0 and D are 0; Scale factor then multiplies the sample: "
                        "the PGA is Target PGA x Scale factor, in expectation. At most 10 g, and so is "
                        "Target PGA x Scale factor, times Intensity ratio or Vertical ratio where one "
                        "exceeds 1 (more than twice the largest ground acceleration recorded). "
                        "Unit: g.");
      prm.add_parameter("Peak factor", p.peak_factor, "PGA / standard deviation, with which Target PGA sets S0 (a given S0 "
                        "or D does not use it). Unit: dimensionless.");
    }

    /// Stochastic: the sample (its length, seeds, components) and its envelope.
    void
    declare_stochastic_sample_entries(dealii::ParameterHandler &prm, GroundMotionParameters &p)
    {
      prm.add_parameter("Duration", p.duration, "Length of the sample. Unit: s.");
      prm.add_parameter("Sample interval", p.sample_interval,
                        "White-noise sample interval (0: the analysis time step); this or the time "
                        "step at most Duration. Unit: s.");
      // explicit ranges: deal.II's pattern for unsigned int has none, and
      // "-1" would be read as 4294967295
      prm.add_parameter("Seed", p.seed, "Random seed. Unit: -.", dealii::Patterns::Integer(0));
      prm.add_parameter("Second seed", p.second_seed,
                        "Seed of the second horizontal component (Components = 2): an "
                        "independent sample of the same process; 0: Seed + 1. Unit: -.",
                        dealii::Patterns::Integer(0));
      prm.add_parameter("Intensity ratio", p.intensity_ratio,
                        "Components = 2: standard deviation of the second component over the "
                        "first's, gamma (Penzien-Watabe 1975: about 0.5 to 1 along the principal "
                        "axes). Unit: dimensionless.");
      prm.add_parameter("Correlation", p.correlation,
                        "Components = 2: correlation coefficient rho of the two components "
                        "before the incidence rotation, in [-1, 1] (0: along their principal "
                        "axes); g_2 = gamma (rho z_1 + sqrt(1 - rho^2) z_2) of two independent "
                        "samples z_1 = g_1, z_2. Unit: dimensionless.");
      prm.add_parameter("Vertical seed", p.vertical_seed,
                        "Seed of the vertical component (Components = 3): an independent "
                        "sample of the same process; 0: Seed + 2. Unit: -.",
                        dealii::Patterns::Integer(0));
      prm.add_parameter("Vertical ratio", p.vertical_ratio,
                        "Components = 3: standard deviation of the vertical component over the "
                        "first horizontal one's (2/3: Newmark, Blume & Kapur 1973; EC8 Table 3.4 "
                        "gives a_vg/a_g = 0.90 for type 1 and 0.45 for type 2 spectra). "
                        "Unit: dimensionless.");
      // an explicit range: deal.II's pattern for unsigned int has none, and
      // "-5" would be read as 4294967291
      prm.add_parameter("Realization", p.realization,
                        "Realization index: (seed, index) fixes the sample. Unit: -.",
                        dealii::Patterns::Integer(0));
      add_choice(prm, "Envelope", p.envelope,
                 "Amplitude modulation: Jennings et al. (1968) trapezoid, Saragoni-Hart "
                 "t^b e^(-ct), Shinozuka-Sato e^(-at) - e^(-bt), or none. Unit: -.",
                 envelope_names());
      prm.add_parameter("Rise end", p.jennings_rise_end, "Jennings: end of (t/t1)^2 rise. Unit: s.");
      prm.add_parameter("Plateau end", p.jennings_plateau_end, "Jennings: end of plateau. Unit: s.");
      prm.add_parameter("Decay rate", p.jennings_decay, "Jennings: exp(-c (t - t2)) rate. Unit: 1/s.");
      prm.add_parameter("Saragoni b", p.saragoni_b, "Saragoni-Hart t^b e^(-ct): b. "
                        "Unit: dimensionless.");
      prm.add_parameter("Saragoni c", p.saragoni_c, "Saragoni-Hart t^b e^(-ct): c. Unit: 1/s.");
      prm.add_parameter("Shinozuka alpha", p.shinozuka_alpha, "e^(-at)-e^(-bt): a. Unit: 1/s.");
      prm.add_parameter("Shinozuka beta", p.shinozuka_beta, "e^(-at)-e^(-bt): b. Unit: 1/s.");
    }
  } // namespace

  void
  GroundMotionParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Ground motion");
    add_choice(prm, "Type", type,
               "Horizontal ground acceleration: a generated Kanai-Tajimi or "
               "Clough-Penzien sample, plain white noise (intensity S0 or D, held "
               "over the sample interval), a record, or none. Unit: -.",
               ground_motion_type_names());
    prm.add_parameter("Scale factor", scale_factor,
                      "Multiplies every component of the motion after any Target PGA: a "
                      "record first scaled to Record/Target PGA, a Kanai-Tajimi or "
                      "Clough-Penzien sample's S0 first set from Stochastic/Target PGA (its "
                      "expected PGA); with both given, the PGA is Target PGA x Scale factor "
                      "(the product: neither replaces the other). Unit: dimensionless.");
    prm.add_parameter("Components", n_components,
                      "Horizontal components: 1 (along x), or 2 (x and y, Model/Dimension = "
                      "3: Record/Second file, or a second independent stochastic sample "
                      "from Stochastic/Second seed); 3 adds the vertical component "
                      "(Record/Third file, or a sample from Stochastic/Vertical seed): x, y "
                      "and z in 3D, x and the vertical in 2D (frames only). Unit: count.",
                      dealii::Patterns::Integer(1, 3));
    prm.add_parameter("Incidence angle", incidence_angle,
                      "Rotates the horizontal pair counter-clockwise in plan: a_x = cos a "
                      "g_1 - sin a g_2, a_y = sin a g_1 + cos a g_2 (Model/Dimension = 3). "
                      "Unit: degrees.");
    declare_record_entries(prm, *this);
    prm.enter_subsection("Stochastic");
    declare_stochastic_process_entries(prm, *this);
    declare_stochastic_sample_entries(prm, *this);
    prm.leave_subsection();
    prm.leave_subsection();
  }

  namespace
  {
    /// One component of `g` alone: `file` (a record), or the seed
    /// `given_seed` (0: Seed + seed_offset) of the same process.
    GroundMotionParameters
    one_component(const GroundMotionParameters &g, const std::string &file,
                  const unsigned int given_seed, const unsigned int seed_offset)
    {
      GroundMotionParameters component = g;
      component.record_file            = file;
      component.seed                   = given_seed > 0 ? given_seed : g.seed + seed_offset;
      component.n_components           = 1;
      return component;
    }
  } // namespace

  GroundMotionParameters
  GroundMotionParameters::second_component() const
  {
    return one_component(*this, second_record_file, second_seed, 1);
  }

  GroundMotionParameters
  GroundMotionParameters::vertical_component() const
  {
    return one_component(*this, third_record_file, vertical_seed, 2);
  }

  void
  GroundMotionParameters::check_vertical(const InputFile &input) const
  {
    const std::string st = "Ground motion/Stochastic/";
    if (!(vertical_ratio >= 0 && vertical_ratio <= 1e3))
      input.fail(st + "Vertical ratio", "must be a number in [0, 1000]");
    if (has_vertical() && is_stochastic() && vertical_ratio == 0)
      input.fail(st + "Vertical ratio", "0 gives a vertical component of zero, although "
                                        "Components = 3 asks for one: give a positive ratio "
                                        "or set Components = 2");
    for (const char *entry : {"Vertical ratio", "Vertical seed"})
      if (input.line_of(st + entry) > 0 && !(has_vertical() && is_stochastic()))
        input.fail(st + entry, "is read only by a generated vertical component: it needs "
                               "Ground motion/Components = 3 and a stochastic Type");
  }

  void
  GroundMotionParameters::check_component_files(const InputFile &input) const
  {
    const std::string gm = "Ground motion/";
    if (type == GroundMotionType::record && n_components == 2 && second_record_file.empty())
      // Second file is absent, so the message points at the line that asks for it
      throw InputError(input.file, input.line_of(gm + "Components"), gm + "Record/Second file",
                       "Components = 2 with a record needs a second file");
    if (type == GroundMotionType::record && has_vertical() && third_record_file.empty())
      throw InputError(input.file, input.line_of(gm + "Components"), gm + "Record/Third file",
                       "Components = 3 with a record needs a third (vertical) file");
    // a record that nothing reads would leave the user believing the
    // building was shaken in that direction as well
    for (const auto &[entry, file] : {std::pair<const char *, const std::string &>{
                                        "Record/Second file", second_record_file},
                                      {"Record/Third file", third_record_file}})
      if (!file.empty() && type != GroundMotionType::record)
        input.fail(gm + entry, "is read only by a record ground motion (Type = record), "
                               "not by '" + ground_motion_type_names().name(type) + "'");
    if (!second_record_file.empty() && n_components == 1)
      input.fail(gm + "Record/Second file",
                 "is the second horizontal component, but Ground motion/Components = 1: "
                 "set Components = 2 or remove this line");
    if (!third_record_file.empty() && !has_vertical())
      input.fail(gm + "Record/Third file",
                 "is the vertical component, but Ground motion/Components = " +
                   std::to_string(n_components) + ": set Components = 3 or remove this line");
  }

  void
  GroundMotionParameters::check_pair(const InputFile &input) const
  {
    const std::string st = "Ground motion/Stochastic/";
    if (!(intensity_ratio >= 0 && intensity_ratio <= 1e3))
      input.fail(st + "Intensity ratio", "must be a number in [0, 1000]");
    if (!(std::abs(correlation) <= 1))
      input.fail(st + "Correlation", "must be in [-1, 1]");
    const bool correlated = intensity_ratio != 1 || correlation != 0;
    if (correlated && n_components < 2)
      input.fail(st + (correlation != 0 ? "Correlation" : "Intensity ratio"),
                 "relates the two horizontal components: it needs Ground motion/Components = 2");
    if (correlated && !is_stochastic())
      input.fail(st + (correlation != 0 ? "Correlation" : "Intensity ratio"),
                 "applies to generated (stochastic) components, not to '" +
                   ground_motion_type_names().name(type) + "'");
  }

  FilterParameters
  ground_motion_filter(const GroundMotionParameters &g)
  {
    const bool cp = g.type == GroundMotionType::clough_penzien;
    return g.soil == Soil::custom ? FilterParameters{cp, g.omega_g, g.zeta_g, g.omega_f, g.zeta_f} :
                                    soil_preset(g.soil, cp);
  }

  double
  given_spectral_intensity(const GroundMotionParameters &g)
  {
    return g.spectral_intensity > 0 ? g.spectral_intensity : g.noise_intensity_d / M_PI;
  }

  namespace
  {
    /// The engineering band of a white noise's bound: 25 Hz, above the
    /// frequencies that carry a ground motion's energy to a structure, so
    /// the bound does not move with the time step or Sample interval (the
    /// held samples' own deviation, sqrt(2 pi S0 / dt), grows without end
    /// as dt shrinks although the response does not).
    constexpr double white_noise_bound_band_hz = 25;
    /// A fixed peak factor for the bound (Davenport's for a stationary
    /// motion of some tens of seconds is about 3); the input's Peak factor
    /// only sets S0 from a target PGA and does not change a given S0.
    constexpr double bound_peak_factor = 3;

    /// The standard deviation (m/s^2) of a generated motion given by its
    /// intensity S0 (or D = pi S0): of the filtered stationary motion
    /// (Kanai-Tajimi, Clough-Penzien), or of the white noise band-limited
    /// to 25 Hz, sqrt(2 S0 w_c) with w_c = 2 pi 25 rad/s.
    double
    deviation_of_intensity(const GroundMotionParameters &g)
    {
      const double s0 = given_spectral_intensity(g);
      if (g.type == GroundMotionType::white_noise)
        return std::sqrt(2 * s0 * 2 * M_PI * white_noise_bound_band_hz);
      return std::sqrt(s0 * stationary_variance_per_unit_s0(ground_motion_filter(g)));
    }

    /// The peak a target PGA or a stochastic intensity asks for, times Scale
    /// factor and the largest ratio of a generated component to the first,
    /// is bounded as the target PGA alone is: a scale factor of 1000 on
    /// 10 g ran, of 1e200 gave an inf floor force, and an S0 of 1e200 ran
    /// with exit 0 to a drift of 6e99 m. Only the input is checked: IDA, MSA
    /// and fragility scale each run themselves, past this check.
    void
    check_scaled_peak(const GroundMotionParameters &g, const InputFile &input)
    {
      const std::string gm     = "Ground motion/";
      const bool        record = g.type == GroundMotionType::record;
      if (record ? !(g.record_target_pga > 0) : !g.is_stochastic())
        return;
      const bool by_target = record || (g.spectral_intensity == 0 && g.noise_intensity_d == 0);
      const std::string intensity = g.spectral_intensity > 0 ? "S0" : "D";
      double            peak =
        by_target ? (record ? g.record_target_pga : g.target_pga) :
                    bound_peak_factor * deviation_of_intensity(g) / standard_gravity;
      if (!by_target && !(peak <= largest_ground_acceleration_g))
        input.fail(gm + "Stochastic/" + intensity,
                   "gives an expected peak ground acceleration of " + number_text(peak) + " g (3 x its " +
                     (g.type == GroundMotionType::white_noise ? "standard deviation below 25 Hz" :
                                                                "standard deviation") +
                     "): at most " + number_text(largest_ground_acceleration_g) + " g (" +
                     largest_ground_acceleration_why + ")");
      const std::string scaled = (by_target ? "Target PGA" : "the expected PGA of " + intensity) +
                                 " x Scale factor";
      std::string product = scaled, blamed = gm + "Scale factor";
      double      ratio   = 1;
      for (const auto &[entry, value, used] :
           {std::tuple{"Intensity ratio", g.intensity_ratio, g.n_components >= 2},
            std::tuple{"Vertical ratio", g.vertical_ratio, g.has_vertical()}})
        if (!record && used && value > ratio)
          {
            ratio   = value;
            product = scaled + " x " + entry;
            if (g.scale_factor == 1)
              blamed = gm + "Stochastic/" + entry;
          }
      peak *= std::abs(g.scale_factor) * ratio;
      if (!(peak <= largest_ground_acceleration_g))
        input.fail(blamed, product + " = " + number_text(peak) + " g, the motion's peak ground " +
                             "acceleration" + (record ? "" : " in expectation") + ": at most " +
                             number_text(largest_ground_acceleration_g) + " g (" +
                             largest_ground_acceleration_why + ")");
    }
  } // namespace

  void
  GroundMotionParameters::check(const InputFile &input, const double time_step) const
  {
    const std::string gm = "Ground motion/";
    if (type == GroundMotionType::record && record_file.empty())
      input.fail(gm + "Record/File", "a record ground motion needs a file");
    check_component_files(input);
    if (!(std::abs(incidence_angle) <= 360))
      input.fail(gm + "Incidence angle", "must be a finite angle in [-360, 360] degrees");
    check_pair(input);
    check_vertical(input);
    input.non_negative(gm + "Record/Time step", record_time_step);
    input.non_negative(gm + "Record/Target PGA", record_target_pga);
    input.at_most(gm + "Record/Target PGA", record_target_pga, largest_ground_acceleration_g, "g",
                  largest_ground_acceleration_why);
    if (!std::isfinite(scale_factor))
      input.fail(gm + "Scale factor", "must be finite");
    if (type == GroundMotionType::white_noise && !(spectral_intensity > 0 || noise_intensity_d > 0))
      input.fail(gm + "Stochastic/S0", "white noise needs S0 > 0 or D > 0 (it has no finite PGA)");
    if (is_stochastic())
      {
        const std::string st = gm + "Stochastic/";
        input.non_negative(st + "D", noise_intensity_d);
        input.non_negative(st + "Cutoff frequency", cutoff_frequency);
        const double dt = held_interval(time_step);
        if (method == StochasticMethod::spectral_representation && cutoff_frequency * dt > M_PI)
          input.fail(st + "Cutoff frequency",
                 "exceeds pi / sample interval = " + number_text(M_PI / dt) + " rad/s");
        input.positive(st + "omega_g", omega_g);
        if (!(zeta_g > 0 && zeta_g < 1))
          input.fail(st + "zeta_g", "must lie in (0, 1)");
        input.positive(st + "omega_f", omega_f);
        if (!(zeta_f > 0 && zeta_f < 1))
          input.fail(st + "zeta_f", "must lie in (0, 1)");
        input.non_negative(st + "S0", spectral_intensity);
        input.non_negative(st + "Target PGA", target_pga);
        input.at_most(st + "Target PGA", target_pga, largest_ground_acceleration_g, "g",
                      largest_ground_acceleration_why);
        input.positive(st + "Peak factor", peak_factor);
        input.positive(st + "Duration", duration);
        input.non_negative(st + "Sample interval", sample_interval);
        // one sample for the whole motion: a Time step of 1e200 s gave the
        // spectrum of nothing with exit 0
        if (!(held_interval(time_step) <= duration))
          input.fail(sample_interval > 0 ? st + "Sample interval" : "Time integration/Time step",
                     "must not exceed the motion's length, " + number_text(duration) + " s (" +
                       st + "Duration), got " + number_text(held_interval(time_step)) + " s");
        input.positive(st + "Rise end", jennings_rise_end);
        if (jennings_plateau_end < jennings_rise_end)
          input.fail(st + "Plateau end", "must not be before the rise end");
        input.non_negative(st + "Decay rate", jennings_decay);
        input.positive(st + "Saragoni b", saragoni_b);
        input.positive(st + "Saragoni c", saragoni_c);
        input.positive(st + "Shinozuka alpha", shinozuka_alpha);
        if (!(shinozuka_beta > shinozuka_alpha)) // blame the one set last in the file
          input.fail(st + (input.line_of(st + "Shinozuka alpha") > input.line_of(st + "Shinozuka beta") ?
                             "Shinozuka alpha" : "Shinozuka beta"),
                     "needs Shinozuka alpha < Shinozuka beta, got alpha = " +
                       number_text(shinozuka_alpha) + ", beta = " + number_text(shinozuka_beta));
      }
    check_scaled_peak(*this, input);
  }

  std::vector<NamedInputFile>
  GroundMotionParameters::input_files() const
  {
    std::vector<NamedInputFile> files;
    const std::string           record = "Ground motion/Record/";
    for (const auto &[entry, name] : {std::pair{"File", &record_file},
                                      std::pair{"Second file", &second_record_file},
                                      std::pair{"Third file", &third_record_file}})
      if (!name->empty())
        files.push_back({record + entry, "record file", *name, ""});
    return files;
  }

  std::vector<NamedInputFile>
  NodalForceParameters::input_files() const
  {
    std::vector<NamedInputFile> files;
    for (const std::string &entry : tabulated)
      {
        std::istringstream fields(entry);
        std::string        field;
        for (unsigned int k = 0; k < 5 && fields >> field; ++k)
          if (k == 4) // 'building floor node dof file'
            files.push_back({"Nodal forces/Tabulated", "tabulated force file", field, ""});
      }
    return files;
  }

  void
  NodalForceParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Nodal forces");
    prm.add_parameter("Harmonic", harmonic,
                      "Harmonic forces 'building floor node dof amplitude omega phase', "
                      "separated by ';', e.g. '1 3 0 ux 1e4 12; B 2 0 ux 5e3 20 0.5'. The "
                      "building: its number (1-based) or its Name; floor 1-based, node "
                      "0-based from the left, dof ux|uy|rz, amplitude in N (N m), omega in "
                      "rad/s, phase in rad (optional, 0). Unit: per field.",
                      Patterns::List(Patterns::Anything(), 0, 1000, ";"));
    prm.add_parameter("Tabulated", tabulated,
                      "Tabulated forces 'building floor node dof file' separated by ';'; "
                      "the file has two columns: time, force (linear in between, zero "
                      "outside); building, floor, node, dof as in Harmonic. Unit: per field.",
                      Patterns::List(Patterns::Anything(), 0, 1000, ";"));
    prm.add_parameter("White noise", white_noise,
                      "Random forces 'building floor node dof S0' separated by ';': white "
                      "noise of two-sided intensity S0 (N^2 s), held over the sample "
                      "interval of Ground motion/Stochastic; part of each realization; "
                      "building, floor, node, dof as in Harmonic. Unit: per field.",
                      Patterns::List(Patterns::Anything(), 0, 1000, ";"));
    prm.leave_subsection();
  }
} // namespace poundfe
