#include <poundfe/base/numbers.h>
#include <poundfe/excitation/ground_motion_bounds.h>
#include <poundfe/excitation/spectrum_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>

namespace poundfe
{
  namespace Patterns = dealii::Patterns;

  namespace
  {
    /// The longest period of a spectrum: far past any structure's, where
    /// the oscillator only follows the ground (Sd is its peak displacement).
    /// A maximum period of 1e200 s had not finished after 100 s, nor
    /// stopped at once on SIGTERM, where input/floor-spectra.prm's spectrum
    /// takes a second.
    constexpr double largest_spectral_period = 1000;
    /// The shortest: 1 ms, 1000 Hz, past any structure's frequency and any
    /// record's sampling (an oscillator far stiffer than the record's step
    /// is rigid: PSA = PGA). A minimum period of 1e-300 s asked for ~1e300
    /// sub-steps an oscillator, an endless loop.
    constexpr double shortest_spectral_period = 1e-3;
  } // namespace

  const NameTable<DesignSpectrum> &
  design_spectrum_names()
  {
    static const NameTable<DesignSpectrum> table({{DesignSpectrum::none, "none"},
                                                  {DesignSpectrum::ec8_type_1, "ec8-type-1"},
                                                  {DesignSpectrum::ec8_type_2, "ec8-type-2"}});
    return table;
  }

  const NameTable<GroundType> &
  ground_type_names()
  {
    static const NameTable<GroundType> table({{GroundType::A, "A"},
                                              {GroundType::B, "B"},
                                              {GroundType::C, "C"},
                                              {GroundType::D, "D"},
                                              {GroundType::E, "E"}});
    return table;
  }

  void
  SpectrumParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Spectrum");
    prm.add_parameter("Minimum period", min_period,
                      "Shortest period of the response spectra, at least 0.001 s (1000 Hz). "
                      "Unit: s.",
                      Patterns::Double(0));
    prm.add_parameter("Maximum period", max_period, "Longest period of the response spectra, "
                      "at most 1000 s (far past any structure's period). Unit: s.",
                      Patterns::Double(0));
    prm.add_parameter("Number of periods", n_periods,
                      "Periods from the minimum to the maximum, both included. Unit: count.",
                      Patterns::Integer(1, 10000));
    add_choice(prm, "Spacing", logarithmic ? "logarithmic" : "linear",
               "Spacing of the periods. Unit: -.", {"logarithmic", "linear"},
               [this](const std::string &s) { logarithmic = s == "logarithmic"; });
    prm.add_parameter("Damping ratios", damping_ratios,
                      "Damping ratios of the spectral oscillators, fractions of critical in "
                      "[0, 0.9], comma separated (the first is the one plotted and matched). "
                      "Unit: dimensionless.",
                      Patterns::List(Patterns::Double(0), 1, 20, ","));
    add_choice(prm, "Target", target,
               "Design spectrum drawn with the spectra and matched by a stochastic motion's "
               "intensity: none, or the horizontal elastic spectrum of EN 1998-1 section "
               "3.2.2.2, type 1 (Table 3.2; large earthquakes, Ms > 5.5) or type 2 "
               "(Table 3.3). Unit: -.",
               design_spectrum_names());
    add_choice(prm, "Ground type", ground_type,
               "Ground type of EN 1998-1 Table 3.1 (A rock ... E shallow alluvium on rock): "
               "the soil factor S and corner periods TB, TC, TD of the target. Unit: -.",
               ground_type_names());
    prm.add_parameter("Design ground acceleration", design_ground_acceleration,
                      "a_g of the target on type A ground (EN 1998-1: gamma_I a_gR), at "
                      "most 10 g (more than twice the largest ground acceleration recorded). Unit: g.",
                      Patterns::Double(0));
    prm.add_parameter("Matching period", matching_period,
                      "Period at which `spectrum --realizations N` matches the ensemble's mean "
                      "pseudo-acceleration to the target (0: the model's first period). "
                      "Unit: s.",
                      Patterns::Double(0));
    prm.leave_subsection();
  }

  void
  SpectrumParameters::check(const InputFile &input) const
  {
    const std::string s = "Spectrum/";
    input.positive(s + "Minimum period", min_period);
    if (!(min_period >= shortest_spectral_period))
      input.fail(s + "Minimum period",
                 "must be at least " + number_text(shortest_spectral_period) + " s, got " +
                   number_text(min_period) + " s (1000 Hz: past any structure's frequency and "
                   "any record's sampling, where the oscillator is rigid)");
    input.positive(s + "Maximum period", max_period);
    input.at_most(s + "Maximum period", max_period, largest_spectral_period, "s",
                  "far past any structure's period, where Sd is the peak ground displacement");
    if (!(max_period > min_period) && n_periods > 1)
      input.fail(s + "Maximum period", "must exceed the minimum period (" +
                                         std::to_string(min_period) + " s)");
    for (const double zeta : damping_ratios)
      if (!(zeta >= 0 && zeta <= 0.9))
        input.fail(s + "Damping ratios", "each must lie in [0, 0.9]");
    input.distinct(s + "Damping ratios", damping_ratios);
    if (target != DesignSpectrum::none)
      input.positive(s + "Design ground acceleration", design_ground_acceleration);
    input.at_most(s + "Design ground acceleration", design_ground_acceleration,
                  largest_ground_acceleration_g, "g", largest_ground_acceleration_why);
    input.non_negative(s + "Matching period", matching_period);
  }

  std::vector<double>
  SpectrumParameters::periods() const
  {
    return period_grid(min_period, max_period, n_periods, logarithmic);
  }

  double
  SpectrumParameters::target_psa(const double zeta, const double period) const
  {
    if (target == DesignSpectrum::none)
      return 0;
    return ec8_elastic_spectrum(target, ground_type, design_ground_acceleration * standard_gravity,
                                zeta, period);
  }
} // namespace poundfe
