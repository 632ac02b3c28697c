// A bumper in a gap: a layer of thickness t mounted on one side of a gap of
// initial width g, so that contact is first with the bumper and, once it is
// crushed to zero thickness, with the structure behind it. On the closure d:
//   bumper compression  delta_b = d - (g - t)       (> 0: touching the bumper)
//   bumper force        F_b(min(delta_b, t))      for delta_b > 0, else 0
//     linear            F_b = k delta
//     hertz             F_b = k delta^(3/2)
//     table             F_b piecewise linear through (0, 0) and the given
//                       (compression, force) points (a measured rubber curve)
//   structure           the gap's contact law on the penetration d - g
//   F = F_b + F_contact,   U = int_0^delta_b F_b(min(s, t)) ds + U_contact.
// Once crushed the bumper keeps carrying F_b(t) (it is squeezed between the
// structures) and the structure's law adds its force: both parts are
// elastic, so the bumper dissipates nothing and a bumper of zero thickness
// is exactly the bare contact. In one dimension the side the bumper is
// mounted on does not change the mechanics.
// Sources: the layered contact of pounding mitigation, K.T. Polycarpou,
// P. Komodromos & A.C. Polycarpou, Earthquake Eng. Struct. Dyn. 42 (2013)
// 81 (rubber shock absorbers between buildings); the Hertz law:
// W. Goldsmith, Impact (1960); doc/theory.md §4.9.
#ifndef poundfe_laws_bumper_h
#define poundfe_laws_bumper_h

#include <poundfe/laws/uniaxial_law.h>

#include <array>
#include <memory>
#include <vector>

namespace poundfe
{
  class ContactLaw;

  enum class BumperLaw
  {
    none,
    linear,
    hertz,
    table
  };

  struct BumperParameters
  {
    BumperLaw law       = BumperLaw::none;
    double    thickness = 0; // t, m
    double    stiffness = 0; // k: N/m (linear) or N/m^1.5 (hertz)
    /// (compression m, force N), compressions increasing from > 0 (table).
    std::vector<std::array<double, 2>> table;

    /// F_b(min(delta, t)) (0 for delta <= 0), its derivative (0 once
    /// crushed) and its potential int_0^delta F_b(min(s, t)) ds.
    double force(double compression) const;
    double tangent(double compression) const;
    double energy(double compression) const;
  };

  /// The phases of a gap: open, touching the structure (with or without a
  /// bumper) and touching the bumper only. A change is an event the
  /// integrator locates; the impact log reports which surface was touched.
  enum ContactPhase : int
  {
    open_gap          = 0,
    structure_contact = 1,
    bumper_contact    = 2
  };

  /// A bumper in front of a contact law (whose initial gap is g).
  std::unique_ptr<UniaxialLaw> make_bumpered_contact(std::unique_ptr<ContactLaw> structure,
                                                      const BumperParameters   &bumper);
} // namespace poundfe

#endif
