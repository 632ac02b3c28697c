// The chord of a member made on nodes that may have moved: from end I to
// end J, each displaced by its node's translation u_0 then,
//   c = ((X_J + o_J) - (X_I + o_I)) - u_0I + u_0J,
// summed in OpenSees's order (LinearCrdTransf2d/3d, PDeltaCrdTransf2d/3d,
// CorotCrdTransf2d: dx = X_J - X_I, dx -= nodeIInitialDisp, dx +=
// nodeJInitialDisp). One sum for the member's length and for the checks of
// it (zero length, vecxz), so that they agree to the last bit; with u_0 = 0
// it is X_J + o_J - (X_I + o_I) exactly.
#ifndef poundfe_elements_displaced_chord_h
#define poundfe_elements_displaced_chord_h

#include <Eigen/Core>

namespace poundfe
{
  /// `end_i`, `end_j`: the member's ends (the nodes plus any offsets);
  /// `u_made`: the nodes' displacements then, node I's DOFs then node J's
  /// (2D: 3 each, 3D: 6 each; the translations come first).
  template <int dim, typename Displacements>
  Eigen::Matrix<double, dim, 1>
  displaced_chord(const Eigen::Matrix<double, dim, 1> &end_i,
                  const Eigen::Matrix<double, dim, 1> &end_j, const Displacements &u_made)
  {
    constexpr int                 node_dofs = dim == 2 ? 3 : 6;
    Eigen::Matrix<double, dim, 1> chord     = end_j - end_i;
    chord -= u_made.template segment<dim>(0);
    chord += u_made.template segment<dim>(node_dofs);
    return chord;
  }
} // namespace poundfe

#endif
