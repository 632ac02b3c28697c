// The largest material constants a fibre section's engineering data take
// (Sections/Section k): the input check of the section builders
// (section_builders.cc) and the range of the same entries as random or
// swept parameters (model/section_registration.cc), so that a sampled or
// swept value is held to the bound a typed one is.
#ifndef poundfe_sections_material_bounds_h
#define poundfe_sections_material_bounds_h

namespace poundfe
{
  /// The largest elastic modulus taken: ten times diamond's (1.2e12 Pa),
  /// the stiffest material; more is a typing error (1e200 Pa made the
  /// section's stiffness overflow in the analysis, a numerical failure).
  constexpr double largest_section_modulus = 1e13;
  /// The largest strength taken (yield stress, concrete strength): ten
  /// times the strongest steel wires' (about 5e9 Pa).
  constexpr double largest_section_strength = 5e10;
} // namespace poundfe

#endif
