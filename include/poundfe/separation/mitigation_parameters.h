// The `Mitigation` section of the `mitigation` command
// (separation/mitigation.h): where the viscous dampers between the pair go,
// the coefficients c to compare (F = c |v|^alpha sgn v, laws/link_laws.h)
// and the bumpers (thickness, stiffness law: laws/bumper.h) to compare with
// the bare pair. The realizations are Monte Carlo/Realizations (a random
// ground motion) or one (a record).
#ifndef poundfe_separation_mitigation_parameters_h
#define poundfe_separation_mitigation_parameters_h

#include <poundfe/base/input_file.h>
#include <poundfe/laws/bumper.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  struct MitigationParameters
  {
    /// 'building floor node building floor node' of each damper (as
    /// Links/Viscous dampers without the law's numbers).
    std::vector<std::string> damper_locations;
    std::vector<double>      damper_coefficients; // c of every damper, per case
    double                   damper_exponent = 1; // alpha in (0, 1]
    BumperLaw                bumper_law      = BumperLaw::linear; // linear or hertz
    std::vector<double>      bumper_thicknesses;  // m, per case
    std::vector<double>      bumper_stiffnesses;  // one for all or one per thickness

    /// Declare the section (entered and left here).
    void declare(dealii::ParameterHandler &prm);
    /// The values given (every command reads the section): no negative
    /// coefficient or thickness, alpha in (0, 1], stiffnesses positive and
    /// one or one per thickness, locations with coefficients. Throws InputError.
    void check(const InputFile &input) const;
    /// What the mitigation command needs besides: something to compare.
    void require(const InputFile &input) const;
    /// Case k's bumper (k < bumper_thicknesses.size()).
    BumperParameters bumper(unsigned int k) const;
    /// 'location c alpha' of every damper: Links/Viscous dampers of c.
    std::vector<std::string> damper_entries(double c) const;
  };
} // namespace poundfe

#endif
