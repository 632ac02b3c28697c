#include <poundfe/base/numbers.h>
#include <poundfe/model/friction_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>

namespace poundfe
{
  namespace Patterns = dealii::Patterns;

  const NameTable<FrictionModel> &
  friction_model_names()
  {
    static const NameTable<FrictionModel> table(
      {{FrictionModel::elastic_plastic, "elastic-plastic"},
       {FrictionModel::regularized, "regularized"}});
    return table;
  }

  void
  SpringParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.add_parameter("SD springs", sd,
                      "Smooth-and-discontinuous springs 'building floor node K L H' "
                      "separated by ';', between the node's ux and the ground: "
                      "F = K x (1 - L/sqrt(x^2 + H^2)) (K in N/m, L and H in m; H = 0 is "
                      "the discontinuous limit). K is assembled into the linear K. The "
                      "building: its number (1-based) or its Name; floor 1-based, node "
                      "0-based from the left. Unit: per field.",
                      Patterns::List(Patterns::Anything(), 0, 1000, ";"));
    prm.add_parameter("Cubic springs", cubic,
                      "Duffing springs 'building floor node k1 k3' separated by ';', "
                      "between the node's ux and the ground: F = k1 x + k3 x^3 (N/m, "
                      "N/m^3). k1 is assembled into the linear K. The building: its number "
                      "or its Name. Unit: per field.",
                      Patterns::List(Patterns::Anything(), 0, 1000, ";"));
  }

  void
  FrictionParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.add_parameter("Surfaces", surfaces,
                      "Friction elements 'building floor node' separated by ';': the "
                      "node's ux slides on the ground or on a belt moving at Belt "
                      "velocity (a base sliding on its foundation, a floor on a "
                      "bearing, a mass on a belt). The building: its number (1-based) or "
                      "its Name. Unit: -.",
                      Patterns::List(Patterns::Anything(), 0, 1000, ";"));
    add_choice(prm, "Model", law.model,
               "elastic-plastic: Coulomb slider with a stiff stick spring, by return "
               "mapping (stick and slip exact up to the stick spring's deflection "
               "mu_s N/k_s); regularized: F = mu N tanh(v_slip/eps), as in the "
               "thesis. Unit: -.",
               friction_model_names());
    prm.add_parameter("Static coefficient", law.static_coefficient,
                      "mu_s: stick holds while |F| <= mu_s N. Unit: dimensionless.");
    prm.add_parameter("Kinetic coefficient", law.kinetic_coefficient,
                      "mu_k: F = mu_k N in slip (without a Stribeck curve); mu_k <= mu_s. "
                      "Unit: dimensionless.");
    prm.add_parameter("Stribeck velocity", law.stribeck_velocity,
                      "v_s: mu = mu_k + (mu_s - mu_k) exp(-|v_slip|/v_s) in slip; "
                      "0: no Stribeck curve. Unit: m/s.");
    prm.add_parameter("Belt velocity", law.belt_velocity,
                      "v0: the surface's velocity; the slip velocity is x' - v0. "
                      "Unit: m/s.");
    prm.add_parameter("Normal force", law.normal.constant, "C0. Unit: N.");
    prm.add_parameter("Normal force per displacement", law.normal.per_displacement,
                      "C1: N = C0 + C1 |x| + C2 |x'| + C3 |x'|^3 (N < 0: lift-off, no "
                      "friction). Unit: N/m.");
    prm.add_parameter("Normal force per velocity", law.normal.per_velocity,
                      "C2 (negative: friction falling with the speed). Unit: N s/m.");
    prm.add_parameter("Normal force per velocity cubed", law.normal.per_velocity_cubed,
                      "C3 (with C2 < 0 < C3: the cubic falling-rising friction "
                      "characteristic). Unit: N s^3/m^3.");
    prm.add_parameter("Normal force from SD spring", normal_force_from_sd_spring,
                      "N also carries the vertical reaction of the SD spring at the same "
                      "node: C0 - K H (1 - L/sqrt(x^2 + H^2)) (the thesis's eq. 2.7). Unit: -.");
    prm.add_parameter("Stick stiffness", law.stick_stiffness,
                      "k_s of the elastic-plastic model; 0: 1e4 times the "
                      "linear stiffness at the node (the diagonal of K). Unit: N/m.");
    prm.add_parameter("Regularization velocity", law.regularization_velocity,
                      "eps of the regularized model. Unit: m/s.");
  }

  void
  FrictionParameters::check(const InputFile &input) const
  {
    bool any = false;
    for (const std::string &s : surfaces)
      any = any || s.find_first_not_of(" \t") != std::string::npos;
    if (!any)
      return;
    input.non_negative("Friction/Static coefficient", law.static_coefficient);
    input.non_negative("Friction/Kinetic coefficient", law.kinetic_coefficient);
    if (law.kinetic_coefficient > law.static_coefficient)
      input.fail("Friction/Kinetic coefficient",
                 "must not exceed the static coefficient " +
                   number_text(law.static_coefficient) + ", got " +
                   number_text(law.kinetic_coefficient));
    input.non_negative("Friction/Stribeck velocity", law.stribeck_velocity);
    input.non_negative("Friction/Normal force", law.normal.constant);
    input.non_negative("Friction/Stick stiffness", law.stick_stiffness);
    input.positive("Friction/Regularization velocity", law.regularization_velocity);
    for (const auto &[entry, value] :
         {std::pair{"Belt velocity", law.belt_velocity},
          std::pair{"Normal force per displacement", law.normal.per_displacement},
          std::pair{"Normal force per velocity", law.normal.per_velocity},
          std::pair{"Normal force per velocity cubed", law.normal.per_velocity_cubed}})
      if (!std::isfinite(value))
        input.fail(std::string("Friction/") + entry, "must be a finite number");
    // A belt (or ground) surface faster than sound in air is no physical
    // input, and at |v0| ~ 1e150 the slip velocity's square overflows.
    if (std::abs(law.belt_velocity) > maximum_belt_velocity)
      input.fail("Friction/Belt velocity",
                 "|v0| = " + number_text(std::abs(law.belt_velocity)) +
                   " m/s is beyond any physical surface velocity (at most " +
                   number_text(maximum_belt_velocity) + " m/s)");
  }
} // namespace poundfe
