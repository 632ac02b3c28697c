// The state of each integration point of the members on fibre sections, as
// the outputs show it: the section at point i of a member element, its
// resultants and deformations (N, Mz, eps0, kappa) and the extreme fibre
// strains of output/section_limits.h (the most compressed concrete fibre,
// the largest and smallest steel strains). The section states recorder
// (sections.csv) and the VTU frames take their numbers from here, so that
// both show the same doubles.
#ifndef poundfe_output_section_states_h
#define poundfe_output_section_states_h

#include <poundfe/elements/beam_integration.h>
#include <poundfe/model/model.h>
#include <poundfe/output/section_limits.h>

#include <array>
#include <vector>

namespace poundfe
{
  class NonlinearElement;

  /// The fibre section at integration point i of a member element, plane
  /// or in space (elements/member_element.h); nullptr: not a member on
  /// fibre sections, or no point i.
  const FibreSection *fibre_section_of(const NonlinearElement &element, unsigned int i);

  /// The places along a fibre member of its integration points: the rule
  /// make_beam_column builds (Gauss-Lobatto for a force-based member,
  /// Gauss-Legendre for a displacement-based one, fibre.n_points points).
  BeamIntegration fibre_member_integration(const FibreMember &fibre);

  /// N, Mz, eps0, kappa, the most compressed concrete fibre's strain, the
  /// largest and the smallest steel fibre strain, in this order.
  constexpr unsigned int n_section_state_entries = 7;
  using SectionStateEntries = std::array<double, n_section_state_entries>;
  SectionStateEntries section_state_entries(const FibreSection          &section,
                                            const std::vector<FibreKind> &kinds);

  /// A section in space adds My and kappa_y to the entries above: the
  /// number of values of section_state_values, 7 in the plane, 9 in space.
  unsigned int n_section_state_values(const FibreSection &section);
  /// The entries above, then (in space) My and kappa_y, written to `to`.
  void section_state_values(const FibreSection &section, const std::vector<FibreKind> &kinds,
                            double *to);
} // namespace poundfe

#endif
