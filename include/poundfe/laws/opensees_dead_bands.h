// OpenSees 3.8's dead bands: its Concrete01, Concrete02, Steel02 and
// Hysteretic skip a strain change below DBL_EPSILON from the committed
// strain (Steel02: below 10 DBL_EPSILON, from a virgin state only); each
// law's file says how.
// `poundfe opensees` asks for them, so that a script gives OpenSees's
// numbers; poundfe's own fibre members do without them (a band can stall a
// member's iteration).
#ifndef poundfe_laws_opensees_dead_bands_h
#define poundfe_laws_opensees_dead_bands_h

#include <poundfe/laws/uniaxial_law.h>

#include <map>
#include <memory>
#include <string>

namespace poundfe
{
  /// The entry of MaterialParameters::values, 1, by which the interpreter
  /// asks make_material for the dead band. It is no parameter of the
  /// material (no MaterialType lists it, export-opensees never writes it):
  /// make_material takes it out before the law sees its parameters.
  inline constexpr const char *opensees_dead_band_entry = "OpenSees dead band";

  /// The material `name` with its OpenSees dead band, from its parameters
  /// (defaults filled in); nullptr for a material without one (the others'
  /// bands, as Steel01's, are in their laws in every run).
  std::unique_ptr<UniaxialLaw>
  make_with_opensees_dead_band(const std::string &name, const std::map<std::string, double> &values);
} // namespace poundfe

#endif
