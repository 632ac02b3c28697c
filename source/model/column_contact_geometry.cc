// The floor-to-column gap of include/poundfe/model/column_contact_geometry.h
// (equations and sources there; doc/theory.md §1.13).
#include <poundfe/model/column_contact_geometry.h>
#include <poundfe/model/plan_contact_geometry.h>

#include <deal.II/base/exceptions.h>

#include <cmath>

namespace poundfe
{
  std::array<double, 4>
  hermite_weights(const double xi, const double length)
  {
    const double xi2 = xi * xi, xi3 = xi2 * xi;
    return {{1 - 3 * xi2 + 2 * xi3, length * (xi - 2 * xi2 + xi3), 3 * xi2 - 2 * xi3,
             length * (xi3 - xi2)}};
  }

  std::vector<double>
  column_weights(const Member3D &member, const double height)
  {
    const double length = member.ends[1][2] - member.ends[0][2];
    Assert(length > 0 && std::hypot(member.ends[1][0] - member.ends[0][0],
                                    member.ends[1][1] - member.ends[0][1]) <= 1e-9 * length,
           dealii::ExcMessage("a column for floor-to-column contact is vertical, bottom end first"));
    const std::array<double, 4> n = hermite_weights((height - member.ends[0][2]) / length, length);
    // row r of H (2 x 12): (end DOF, weight) pairs; end DOFs ux uy uz rx ry rz
    const std::array<std::array<std::pair<unsigned int, double>, 4>, 2> h{
      {{{{0, n[0]}, {4, n[1]}, {6, n[2]}, {10, n[3]}}},
       {{{1, n[0]}, {3, -n[1]}, {7, n[2]}, {9, -n[3]}}}}};
    const unsigned int  n_dofs = member.dofs.size();
    std::vector<double> w(2 * n_dofs, 0.0);
    for (unsigned int r = 0; r < 2; ++r)
      for (const auto &[row, weight] : h[r])
        for (unsigned int j = 0; j < n_dofs; ++j)
          w[r * n_dofs + j] += weight * member.map[row * n_dofs + j];
    return w;
  }

  ColumnContactState
  column_contact_state(const ColumnContactGeometry &geometry, const Vector5 &z)
  {
    const Point2 &a = geometry.edge[0], &b = geometry.edge[1];
    // is the column point between the ends of the slab's deformed edge?
    const double c = std::cos(z[4]), s = std::sin(z[4]);
    const auto   place = [&](const Point2 &x) { // a point of the slab, deformed
      const double dx = x.x - geometry.slab_centre.x, dy = x.y - geometry.slab_centre.y;
      return Eigen::Vector2d(geometry.slab_centre.x + z[2] + c * dx - s * dy,
                             geometry.slab_centre.y + z[3] + s * dx + c * dy);
    };
    const Eigen::Vector2d xa = place(a), xb = place(b);
    const Eigen::Vector2d xc(geometry.column_point.x + z[0], geometry.column_point.y + z[1]);
    const double          along = (xc - xa).dot(xb - xa) / (xb - xa).squaredNorm();
    ColumnContactState    state;
    if (along < 0 || along > 1)
      return state;
    Vector6 q;
    q << z[0], z[1], 0, z[2], z[3], z[4]; // the column point's body does not turn
    const PlanContactState corner =
      corner_on_edge_state({{geometry.column_point, geometry.slab_centre}}, q, 0,
                           geometry.column_point, a, outward_normal(a, b));
    const std::array<unsigned int, 5> kept{{0, 1, 3, 4, 5}};
    state.defined = true;
    state.gap     = corner.gap;
    state.point   = corner.point;
    for (unsigned int i = 0; i < 5; ++i)
      {
        state.gradient[i] = corner.gradient[kept[i]];
        for (unsigned int j = 0; j < 5; ++j)
          state.hessian(i, j) = corner.hessian(kept[i], kept[j]);
      }
    return state;
  }
} // namespace poundfe
