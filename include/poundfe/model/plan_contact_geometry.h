// The gap between the slab outlines of two floors in plan, in the deformed
// configuration, and its first and second derivatives with respect to the
// floors' motion q = (ux1, uy1, θ1, ux2, uy2, θ2) at their mass centres.
//   A material point X of floor k is at x = C_k + u_k + R(θ_k)(X - C_k)
//   (finite rotation). Two facing edges, E1 of floor 1 and E2 of floor 2;
//   along E2's direction t2 the two edges overlap on [s_lo, s_hi]; each end
//   of the overlap is a corner of one floor facing the edge of the other.
//   For a corner x_c of floor p and the edge of floor e through x_0 with
//   outward normal n = R(θ_e) N_e:   g = (x_c - x_0) · n   (> 0: open),
//     dg/du_p = n,  dg/dθ_p = (x_c - c_p) × n,
//     dg/du_e = -n, dg/dθ_e = -(x_c - c_e) × n,      (a × b = a_x b_y - a_y b_x)
//   c_k = C_k + u_k the current centres; the second derivatives are
//     d²g/du_p dθ_e = J n, d²g/du_e dθ_e = -J n, d²g/dθ_p² = -(x_c - c_p)·n,
//     d²g/dθ_p dθ_e = (x_c - c_p)·n, d²g/dθ_e² = -(x_c - c_e)·n,
//   J the rotation by +90°. A contact force F (compression) on the
//   equations is -F dg/dq: equal and opposite forces along n through the
//   corner, so an eccentric hit twists both floors and the pair conserves
//   linear and angular momentum.
// Source: node-to-segment contact (Wriggers, Computational Contact
// Mechanics, 2nd ed. (2006), §4.1 and §9.1, here with rigid bodies);
// Leibovich, Rutenberg & Yankelevsky, EESD 25 (1996) 1211-1225 (torsional
// pounding of slabs in plan).
#ifndef poundfe_model_plan_contact_geometry_h
#define poundfe_model_plan_contact_geometry_h

#include <poundfe/model/model.h>

#include <Eigen/Core>

namespace poundfe
{
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  using Matrix6 = Eigen::Matrix<double, 6, 6>;

  struct PlanContactState
  {
    /// false: the edges do not overlap along E2 (no contact possible).
    bool    defined = false;
    double  gap     = 0; // along the normal, m; > 0 open
    Vector6 gradient = Vector6::Zero();
    Matrix6 hessian  = Matrix6::Zero();
    Point2  point;       // the corner, deformed
  };

  /// The state of the end geometry.end of the overlap at motion q.
  PlanContactState plan_contact_state(const PlanContactGeometry &geometry, const Vector6 &q);

  /// The gap of the corner X_c (at rest) of body p on the edge of body
  /// e = 1 - p through X_0 with outward normal N (at rest), the two bodies
  /// moving rigidly by q = (ux, uy, θz) about `centres` each.
  PlanContactState corner_on_edge_state(const std::array<Point2, 2> &centres, const Vector6 &q,
                                        unsigned int p, const Point2 &corner,
                                        const Point2 &edge_point, const Point2 &normal);

  /// The outward normal of a counter-clockwise outline's edge from a to b.
  Point2 outward_normal(const Point2 &a, const Point2 &b);
} // namespace poundfe

#endif
