// The plan contact gap of include/poundfe/model/plan_contact_geometry.h
// (equations and sources there; doc/theory.md §1.13).
#include <poundfe/model/plan_contact_geometry.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  namespace
  {
    using Vec2 = Eigen::Vector2d;

    Vec2 vec(const Point2 &p) { return {p.x, p.y}; }
    Vec2 perp(const Vec2 &v) { return {-v.y(), v.x()}; } // J v
    double cross(const Vec2 &a, const Vec2 &b) { return a.x() * b.y() - a.y() * b.x(); }

    /// A floor's rigid motion: centre at rest C, displacement u, rotation R.
    struct FloorMotion
    {
      Vec2            centre, displacement;
      Eigen::Matrix2d rotation;

      FloorMotion(const Point2 &c, const double ux, const double uy, const double theta)
        : centre(vec(c)), displacement(ux, uy)
      {
        rotation << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
      }
      Vec2 current_centre() const { return centre + displacement; }
      Vec2 place(const Point2 &x) const { return current_centre() + rotation * (vec(x) - centre); }
    };

    /// g and its derivatives for the corner X_c of floor p on the edge of
    /// floor e through X_0 with outward normal N (at rest).
    PlanContactState
    corner_on_edge(const std::array<FloorMotion, 2> &floors, const unsigned int p,
                   const Point2 &corner, const Point2 &edge_point, const Point2 &normal)
    {
      const unsigned int e  = 1 - p;
      const Vec2         xc = floors[p].place(corner), x0 = floors[e].place(edge_point);
      const Vec2         n  = floors[e].rotation * vec(normal);
      const Vec2         rp = xc - floors[p].current_centre(), re = xc - floors[e].current_centre();
      PlanContactState   s;
      s.defined = true;
      s.gap     = (xc - x0).dot(n);
      s.point   = {xc.x(), xc.y()};
      const unsigned int ip = 3 * p, ie = 3 * e;
      s.gradient.segment<2>(ip) = n;
      s.gradient[ip + 2]        = cross(rp, n);
      s.gradient.segment<2>(ie) = -n;
      s.gradient[ie + 2]        = -cross(re, n);
      const Vec2 jn = perp(n);
      s.hessian.block<2, 1>(ip, ie + 2) = jn;
      s.hessian.block<2, 1>(ie, ie + 2) = -jn;
      s.hessian(ip + 2, ip + 2)         = -rp.dot(n);
      s.hessian(ip + 2, ie + 2)         = rp.dot(n);
      s.hessian(ie + 2, ie + 2)         = -re.dot(n);
      // symmetric: mirror the upper entries set above
      for (unsigned int i = 0; i < 6; ++i)
        for (unsigned int j = 0; j < i; ++j)
          if (s.hessian(i, j) == 0)
            s.hessian(i, j) = s.hessian(j, i);
          else
            s.hessian(j, i) = s.hessian(i, j);
      return s;
    }
  } // namespace

  PlanContactState
  corner_on_edge_state(const std::array<Point2, 2> &centres, const Vector6 &q,
                       const unsigned int p, const Point2 &corner, const Point2 &edge_point,
                       const Point2 &normal)
  {
    const std::array<FloorMotion, 2> floors{{{centres[0], q[0], q[1], q[2]},
                                             {centres[1], q[3], q[4], q[5]}}};
    return corner_on_edge(floors, p, corner, edge_point, normal);
  }

  Point2
  outward_normal(const Point2 &a, const Point2 &b)
  {
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    return {(b.y - a.y) / length, -(b.x - a.x) / length};
  }

  PlanContactState
  plan_contact_state(const PlanContactGeometry &geometry, const Vector6 &q)
  {
    const std::array<FloorMotion, 2> floors{{{geometry.centres[0], q[0], q[1], q[2]},
                                             {geometry.centres[1], q[3], q[4], q[5]}}};
    const auto &[a0, a1] = geometry.edges[0];
    const auto &[b0, b1] = geometry.edges[1];
    const Vec2   xb0 = floors[1].place(b0), xb1 = floors[1].place(b1);
    const double length = (xb1 - xb0).norm();
    const Vec2   t      = (xb1 - xb0) / length;
    const std::array<double, 2> s{{(floors[0].place(a0) - xb0).dot(t),
                                   (floors[0].place(a1) - xb0).dot(t)}};
    const double lo = std::min(s[0], s[1]), hi = std::max(s[0], s[1]);
    if (hi < 0 || lo > length)
      return {};
    if (geometry.end == 0)
      {
        if (lo > 0) // a corner of floor 1 on edge 2
          return corner_on_edge(floors, 0, s[0] < s[1] ? a0 : a1, b0, outward_normal(b0, b1));
        return corner_on_edge(floors, 1, b0, a0, outward_normal(a0, a1));
      }
    if (hi < length)
      return corner_on_edge(floors, 0, s[0] > s[1] ? a0 : a1, b0, outward_normal(b0, b1));
    return corner_on_edge(floors, 1, b1, a0, outward_normal(a0, a1));
  }
} // namespace poundfe
