// The `Pushover` section (dynamics/pushover_parameters.h).
#include <poundfe/dynamics/pushover_parameters.h>
#include <poundfe/base/numbers.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>

namespace poundfe
{
  const NameTable<LoadPattern> &
  load_pattern_names()
  {
    static const NameTable<LoadPattern> table({{LoadPattern::mode, "mode"},
                                               {LoadPattern::triangular, "triangular"},
                                               {LoadPattern::uniform, "uniform"}});
    return table;
  }

  const NameTable<TargetMethod> &
  target_method_names()
  {
    static const NameTable<TargetMethod> table(
      {{TargetMethod::n2, "N2"}, {TargetMethod::asce41, "ASCE41"}, {TargetMethod::both, "both"}});
    return table;
  }

  void
  PushoverParameters::declare(dealii::ParameterHandler &prm)
  {
    namespace Patterns = dealii::Patterns;
    prm.enter_subsection("Pushover");
    prm.add_parameter("Load pattern", pattern_names,
                      "The lateral loads on each floor's ux, one for all buildings or one per "
                      "building: mode (m_i phi_i, phi the building's first mode), triangular "
                      "(m_i z_i, z_i the height above the base) or uniform (m_i). Each "
                      "building's loads sum to the load factor, so the factor is its base "
                      "shear while no gap is closed. Unit: -.",
                      Patterns::List(Patterns::Selection("mode|triangular|uniform"), 1));
    prm.add_parameter("Control building", control_building,
                      "The building of the control node (its number). Unit: -.",
                      Patterns::Integer(1));
    prm.add_parameter("Control floor", control_floor,
                      "The floor of the control node (its first joint's ux), 1 the lowest; "
                      "0: the roof. Unit: -.",
                      Patterns::Integer(0));
    prm.declare_entry("Type", "monotonic", Patterns::Selection("monotonic|cyclic"),
                      "monotonic: push to Target drift; cyclic: to each drift of Protocol in "
                      "turn. Unit: -.");
    prm.add_action("Type", [this](const std::string &value) { cyclic = value == "cyclic"; });
    prm.add_parameter("Target drift", target_drift,
                      "Monotonic: the control node's displacement over its height above the "
                      "base at which the push ends. Unit: -.");
    prm.add_parameter("Protocol", protocol,
                      "Cyclic: the control node's drift ratios to reach in turn, signed "
                      "(e.g. 0.005, -0.005, 0.01, -0.01). Unit: -.");
    prm.add_parameter("Number of steps", n_steps,
                      "Displacement steps of each excursion (halved on non-convergence). "
                      "Unit: -.",
                      Patterns::Integer(1, 1000000));
    prm.add_parameter("Tolerance", tolerance,
                      "Newton converges when the residual's norm is at most this times the "
                      "load's. Unit: -.");
    prm.add_parameter("Max iterations", max_iterations, "Newton iterations per step. Unit: -.",
                      Patterns::Integer(1, 1000));
    prm.add_parameter("Max step cuts", max_step_cuts,
                      "How often a step that does not converge is halved. Unit: -.",
                      Patterns::Integer(0, 30));
    prm.add_parameter("Arc length", arc_length,
                      "Where displacement control fails (a peak of the control displacement, "
                      "a snap-back), continue by arc length (Crisfield's cylindrical "
                      "constraint). Unit: -.");
    add_choice(prm, "Target method", target_method,
               "The target displacement of the control building's curve under "
               "Spectrum/Target: N2 (EN 1998-1 Annex B, when a Spectrum/Target is given), "
               "ASCE41 (ASCE/SEI 41-17 7.4.3.3: C0 C1 C2 S_a T_e^2 / 4 pi^2 on the "
               "bilinear idealisation of 7.4.3.2.4; needs a Spectrum/Target) or both. "
               "Unit: -.",
               target_method_names());
    add_choice(prm, "ASCE41 site class", site_class,
               "ASCE41: the site class (ASCE 7 ch. 20) of C1's factor a: 130 for A and B, "
               "90 for C, 60 for D, E and F. Unit: -.",
               site_class_names());
    prm.add_parameter("ASCE41 effective mass factor", effective_mass_factor,
                      "ASCE41: C_m of ASCE 41-17 Table 7-4 in mu_strength = S_a / (V_y / W) "
                      "C_m (1.0 for one storey; 0.8 to 0.9 for two or more storeys by the "
                      "system); taken as 1.0 where T_e exceeds 1 s. Unit: -.");
    prm.leave_subsection();
  }

  void
  PushoverParameters::finalize(const InputFile &input, const unsigned int n_buildings,
                               const bool spectrum_target)
  {
    if (pattern_names.size() != 1 && pattern_names.size() != n_buildings)
      input.fail("Pushover/Load pattern", "needs one value or one per building (" +
                                            std::to_string(n_buildings) + "), got " +
                                            std::to_string(pattern_names.size()));
    patterns.clear();
    for (unsigned int b = 0; b < n_buildings; ++b)
      patterns.push_back(
        load_pattern_names().value(pattern_names[pattern_names.size() == 1 ? 0 : b]));
    if (control_building > n_buildings)
      input.fail("Pushover/Control building",
                 "there is no building " + std::to_string(control_building) + " (the model has " +
                   std::to_string(n_buildings) + ")");
    if (!(tolerance > 0 && tolerance < 1))
      input.fail("Pushover/Tolerance", "must lie in (0, 1), got " + number_text(tolerance));
    if (!cyclic && !(target_drift > 0 && target_drift < 1))
      input.fail("Pushover/Target drift",
                 "must be positive (and below 1), got " + number_text(target_drift));
    if (cyclic && protocol.empty())
      input.fail("Pushover/Protocol", "a cyclic pushover needs at least one target drift");
    for (const double drift : protocol)
      if (!(drift != 0 && std::abs(drift) < 1))
        input.fail("Pushover/Protocol",
                   "each drift must be nonzero (and below 1 in size), got " + number_text(drift));
    if (!(effective_mass_factor > 0 && effective_mass_factor <= 1))
      input.fail("Pushover/ASCE41 effective mass factor",
                 "C_m must lie in (0, 1], got " + number_text(effective_mass_factor));
    if (asce41() && !spectrum_target)
      input.fail("Pushover/Target method",
                 target_method_names().name(target_method) +
                   " needs the spectrum S_a(T_e): set Spectrum/Target");
  }

  std::vector<double>
  PushoverParameters::targets() const
  {
    return cyclic ? protocol : std::vector<double>{target_drift};
  }
} // namespace poundfe
