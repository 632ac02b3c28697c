#include <poundfe/separation/separation_parameters.h>

#include <poundfe/base/numbers.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace poundfe
{
  namespace Patterns = dealii::Patterns;

  const NameTable<PeakDisplacements> &
  peak_displacements_names()
  {
    static const NameTable<PeakDisplacements> table(
      {{PeakDisplacements::time_history, "time history"},
       {PeakDisplacements::response_spectrum, "response spectrum"}});
    return table;
  }

  const NameTable<ModalCombination> &
  modal_combination_names()
  {
    static const NameTable<ModalCombination> table(
      {{ModalCombination::cqc, "CQC"}, {ModalCombination::srss, "SRSS"}});
    return table;
  }

  namespace
  {
    /// Where the rules' peak displacements come from, and the response spectrum's modes.
    void
    declare_response_spectrum_entries(dealii::ParameterHandler &prm, SeparationParameters &p)
    {
      add_choice(prm, "Peak displacements", p.peak_displacements,
                 "Where u_1, u_2 of the rules come from: time history (the file's ground "
                 "motion without contact: one run, or the Monte Carlo means of a random one), "
                 "or response spectrum (no time history: each building's modes under the "
                 "Spectrum section's Eurocode 8 target, Spectrum/Target, at each mode's own "
                 "damping ratio, combined by Modal combination; the Ground motion section is "
                 "not used). Unit: -.",
                 peak_displacements_names());
      add_choice(prm, "Modal combination", p.modal_combination,
                 "Response spectrum: the modal combination of the displacements given to the "
                 "rules (both are reported): CQC (Der Kiureghian 1981, EN 1998-1 "
                 "§4.3.3.3.2(3)) or SRSS (eq. 4.16, for modes whose periods differ by more "
                 "than 10 %). Unit: -.",
                 modal_combination_names());
      prm.add_parameter("Number of modes", p.n_spectrum_modes,
                        "Response spectrum: the modes of each building combined; 0: the fewest "
                        "whose effective masses sum to at least 90 % of the building's mass and "
                        "that include every mode above 5 % (EN 1998-1 §4.3.3.3.1(3)). "
                        "Unit: count.",
                        Patterns::Integer(0, 10000));
    }
  } // namespace

  void
  SeparationParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Separation");
    prm.add_parameter("Deflection amplification", deflection_amplification,
                      "ASCE 7-16 C_d of each building (one value for all, or one per "
                      "building): delta_M = C_d delta_max / I_e (eq. 12.12-1). 1 (with I_e = 1) "
                      "takes the run's displacements as the inelastic ones, as a nonlinear "
                      "response history gives them; use the code's C_d when the run is an "
                      "elastic analysis at the reduced design forces. In [1, 10] (the C_d "
                      "values of ASCE 7-16 Table 12.2-1 lie well below 10). Unit: dimensionless.",
                      Patterns::List(Patterns::Double(0), 1));
    prm.add_parameter("Importance factor", importance_factor,
                      "ASCE 7-16 I_e of each building (one for all, or one per building), "
                      "in [1, 2] (ASCE 7-16 Table 1.5-2: 1, 1.25 or 1.5). Unit: dimensionless.",
                      Patterns::List(Patterns::Double(0), 1));
    prm.add_parameter("Behaviour factor", behaviour_factor,
                      "Eurocode 8 q of each building (one for all, or one per building): "
                      "d_s = q d_e (EN 1998-1 eq. 4.23, q_d = q). 1 takes the run's "
                      "displacements as d_s. In [1, 10] (the behaviour factors of EN 1998-1 "
                      "lie well below 10). "
                      "Unit: dimensionless.",
                      Patterns::List(Patterns::Double(0), 1));
    prm.add_parameter("Coinciding levels factor", coinciding_levels_factor,
                      "Eurocode 8 §4.4.2.7(4): the SRSS separation is multiplied by this "
                      "where both buildings have a floor at the level (EN 1998-1: 0.7). "
                      "Unit: dimensionless.",
                      Patterns::Double(0, 1));
    prm.add_parameter("Target probability", target_probability,
                      "Probability of pounding per event (one realization of the random "
                      "ground motion) for which the gap is reported, in (0, 1). "
                      "Unit: dimensionless.",
                      Patterns::Double(0, 1));
    prm.add_parameter("Number of gap values", n_gap_values,
                      "Gap widths of the exceedance curve, equally spaced from 0 to 1.2 times "
                      "the largest relative approach of the realizations (or the existing "
                      "gap if larger), when Gap values is empty. Unit: count.",
                      Patterns::Integer(2, 100000));
    prm.add_parameter("Gap values", gap_values,
                      "Gap widths g of the exceedance curve P(max relative approach > g), "
                      "ascending; empty: the grid of Number of gap values. Unit: m.",
                      Patterns::List(Patterns::Double(0), 0));
    prm.add_parameter("Confidence level", confidence_level,
                      "Of the pointwise Wilson score band of the probability of pounding, "
                      "in (0, 1). Unit: dimensionless.",
                      Patterns::Double(0, 1));
    declare_response_spectrum_entries(prm, *this);
    hazard.declare(prm);
    prm.leave_subsection();
  }

  namespace
  {
    /// The codes' factors within the range of the codes' own values: a C_d
    /// of 1e200 gave an ASCE 7 gap of 8e198 m with exit 0.
    void
    check_code_factors(const InputFile &input, const std::string &entry,
                       const std::vector<double> &factors, const double lower, const double upper,
                       const std::string &why)
    {
      for (const double f : factors)
        if (!(f >= lower && f <= upper))
          input.fail(entry, "must lie in [" + number_text(lower) + ", " + number_text(upper) +
                              "], got " + number_text(f) + " (" + why + ")");
    }
  } // namespace

  void
  SeparationParameters::check(const InputFile &input, const unsigned int n_buildings) const
  {
    const std::string s = "Separation/";
    input.list(s + "Deflection amplification", deflection_amplification, n_buildings, false,
               "one per building");
    input.list(s + "Importance factor", importance_factor, n_buildings, false, "one per building");
    input.list(s + "Behaviour factor", behaviour_factor, n_buildings, false, "one per building");
    check_code_factors(input, s + "Deflection amplification", deflection_amplification, 1, 10,
                       "the C_d values of ASCE 7-16 Table 12.2-1 lie well below 10; 1: the "
                       "run's own inelastic displacements");
    check_code_factors(input, s + "Importance factor", importance_factor, 1, 2,
                       "ASCE 7-16 Table 1.5-2 gives I_e = 1, 1.25 or 1.5");
    check_code_factors(input, s + "Behaviour factor", behaviour_factor, 1, 10,
                       "the behaviour factors of EN 1998-1 lie well below 10");
    input.positive(s + "Coinciding levels factor", coinciding_levels_factor);
    if (!(target_probability > 0 && target_probability < 1))
      input.fail(s + "Target probability", "must lie in (0, 1)");
    if (!(confidence_level > 0 && confidence_level < 1))
      input.fail(s + "Confidence level", "must lie in (0, 1)");
    for (std::size_t i = 1; i < gap_values.size(); ++i)
      if (!(gap_values[i] > gap_values[i - 1]))
        input.fail(s + "Gap values", "must be ascending");
    hazard.check(input);
  }
} // namespace poundfe
