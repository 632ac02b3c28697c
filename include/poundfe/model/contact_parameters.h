// The `Contact` section: the law of the gap elements the model builder
// makes between buildings and at barriers. `Event refinement`, also in this
// section, belongs to the integrator (integration/time_integration_parameters.h).
#ifndef poundfe_model_contact_parameters_h
#define poundfe_model_contact_parameters_h

#include <poundfe/base/choices.h>
#include <poundfe/base/input_file.h>
#include <poundfe/model/link_parameters.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  /// Where the damping parameter of a damped law comes from.
  enum class ContactDampingFrom
  {
    given,      // the value of Damping
    formula,    // the law's literature formula of e
    calibrated  // one simulated impact returns e exactly
  };

  /// The literature formula of xi_bar of the Hertz-damp law.
  enum class HertzDampFormula
  {
    muthukumar_desroches,
    ye_li_zhu
  };

  const NameTable<ContactDampingFrom> &contact_damping_from_names();
  /// Also the `variant` names of damping_from_restitution_formula.
  const NameTable<HertzDampFormula> &hertz_damp_formula_names();

  struct ContactParameters
  {
    std::string        law       = "none"; // none or one of contact_law_names()
    double             stiffness = 2.75e9;
    ContactDampingFrom damping_from = ContactDampingFrom::calibrated;
    double             damping      = 0.0; // xi or xi_bar when given
    double             restitution  = 0.65;
    HertzDampFormula   hertz_damp_formula   = HertzDampFormula::muthukumar_desroches;
    double             effective_mass       = 0.0; // 0: from the floor masses
    double             calibration_velocity = 1.0;
    bool               between_buildings    = true;
    bool               floor_to_column      = true;
    /// Dimension 3: slab edges against the columns of 3D frame neighbours.
    bool               floor_to_column_in_plan = false;
    std::vector<std::string> barriers; // "building floor side gap"
    /// The `Links` and `Bumpers` sections: what is put in and across the
    /// gaps (declared in their own subsections by InputParameters).
    LinkParameters        links;
    BumperInputParameters bumpers;

    /// Declare this section's entries in the current subsection (`Contact`).
    void declare(dealii::ParameterHandler &prm);
    /// Throws InputError.
    void check(const InputFile &input) const;
    /// The law's entries given in the file (a .prm: its line index) that
    /// have no effect with this Law and Damping from, one warning each:
    /// with Law = none every entry of the law; an undamped law's damping
    /// entries; a given Damping's restitution entries, or a Damping beside
    /// a formula or a calibration; the Hertz-damp formula of another law.
    std::vector<std::string> entries_without_effect(const InputFile &input) const;
  };

  struct ContactLawParameters;

  /// The damping parameter of the contact law `law` (its stiffness and
  /// effective mass set) as the model builder sets it from `contact`: 0 for
  /// an undamped law, Damping when given, else from the Coefficient of
  /// restitution by the law's formula or by calibration on `law`.
  double contact_law_damping(const ContactParameters &contact, const ContactLawParameters &law);
} // namespace poundfe

#endif
