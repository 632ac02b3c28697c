// Floor-to-column contact in plan (Model/Dimension = 3): the edge of a
// rigid slab of one building against a column of a 3D frame neighbour
// between two of its floors (buildings with different storey heights).
//   The column is vertical, from z_0 to z_1 = z_0 + L; at the slab's height
//   z = z_0 + ξ L its plan displacement is the Euler-Bernoulli cubic
//   (Hermite) interpolation of its end translations and rotations,
//     w_x = N1 ux_0 + N2 ry_0 + N3 ux_1 + N4 ry_1,
//     w_y = N1 uy_0 - N2 rx_0 + N3 uy_1 - N4 rx_1,
//     N1 = 1 - 3ξ² + 2ξ³, N2 = L (ξ - 2ξ² + ξ³), N3 = 3ξ² - 2ξ³, N4 = L (ξ³ - ξ²),
//   (du_x/dz = r_y, du_y/dz = -r_x), so w = W u, W = H(ξ) T with T the
//   member's map of its 12 end DOFs (model/model.h's Member3D).
//   The column point x_c = P + w is a corner that translates only; the
//   slab's edge through X_0 (outward normal N) moves rigidly with the slab
//   (ux, uy, θz at its mass centre C):  g = (x_c - x_0) · n, n = R(θ) N,
//   as for a slab corner (model/plan_contact_geometry.h) with the corner's
//   body not rotating. In z = (w_x, w_y, ux, uy, θz):
//     dg/dw = n,  dg/du = -n,  dg/dθ = -(x_c - c) × n,
//     d²g/dw dθ = J n, d²g/du dθ = -J n, d²g/dθ² = -(x_c - c) · n.
//   The force F (compression) acts along -n on the slab at x_c and along +n
//   on the column at its point: on the column's DOFs it is Wᵀ n F, the
//   consistent (work-equivalent) nodal loads of a point load, which are the
//   fixed-end reactions of the beam (no node is inserted: the frame's mesh,
//   its DOFs and every other output stay as they are).
// Sources: Wriggers, Computational Contact Mechanics, 2nd ed. (2006), §4.1
// (node-to-segment contact); Cook, Malkus, Plesha & Witt, Concepts and
// Applications of Finite Element Analysis, 4th ed. (2002), §2.3 and §4.2
// (Hermite beam shape functions, consistent nodal loads); Karayannis &
// Favvata, EESD 34 (2005) 1-20 (floor-to-column pounding).
#ifndef poundfe_model_column_contact_geometry_h
#define poundfe_model_column_contact_geometry_h

#include <poundfe/model/model.h>

#include <Eigen/Core>

namespace poundfe
{
  using Vector5 = Eigen::Matrix<double, 5, 1>;
  using Matrix5 = Eigen::Matrix<double, 5, 5>;

  struct ColumnContactState
  {
    /// false: the column point is beyond the ends of the slab's edge.
    bool    defined  = false;
    double  gap      = 0; // along the normal, m; > 0 open
    Vector5 gradient = Vector5::Zero();
    Matrix5 hessian  = Matrix5::Zero();
    Point2  point; // the column point, deformed
  };

  /// The state at z = (w_x, w_y, ux, uy, θz): the column's plan
  /// displacement at the slab's height and the slab's motion.
  ColumnContactState column_contact_state(const ColumnContactGeometry &geometry, const Vector5 &z);

  /// Hermite weights (N1, N2, N3, N4) at ξ of a member of length L.
  std::array<double, 4> hermite_weights(double xi, double length);

  /// W (2 x member.dofs.size(), row-major) of a vertical column at the site
  /// height `height` between its ends.
  std::vector<double> column_weights(const Member3D &member, double height);
} // namespace poundfe

#endif
