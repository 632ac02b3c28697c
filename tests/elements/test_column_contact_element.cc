// The floor-to-column contact element (elements/column_contact_element.h):
// where the force goes on the column against the fixed-end reactions of a
// point load (closed form), the equilibrium of the pair, its tangent
// against central differences of its force, and an eccentric collision of
// a free slab with a free column that conserves linear and angular momentum.
#include <poundfe/elements/column_contact_element.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace poundfe;

namespace
{
  /// A 10 x 8 slab centred at the origin; its east edge x = 5 faces a
  /// column at (5.15, 1.5), 0.15 m away and 1.5 m north of the mass centre.
  ColumnContactGeometry
  slab_and_column(const std::vector<double> &weights)
  {
    ColumnContactGeometry g;
    g.edge         = {{{5, -4}, {5, 4}}};
    g.slab_centre  = {0, 0};
    g.column_point = {5.15, 1.5};
    g.weights      = weights;
    for (unsigned int j = 0; j < weights.size() / 2; ++j)
      g.column_dofs.push_back(j);
    return g;
  }

  /// W of a vertical column of length `length` between its bottom and top
  /// end DOFs (ux, uy, uz, rx, ry, rz each, the identity map) at `height`.
  std::vector<double>
  column_of_length(const double length, const double height)
  {
    Member3D column;
    column.ends = {{{{5.15, 1.5, 0}}, {{5.15, 1.5, length}}}};
    for (unsigned int j = 0; j < 12; ++j)
      column.dofs.push_back(j);
    column.map.assign(144, 0);
    for (unsigned int j = 0; j < 12; ++j)
      column.map[13 * j] = 1;
    return column_weights(column, height);
  }

  std::unique_ptr<ContactLaw>
  contact_law_named(const std::string &name, const double damping)
  {
    ContactLawParameters p;
    p.law            = name;
    p.stiffness      = 1e8;
    p.damping        = damping;
    p.effective_mass = 5e4;
    return make_contact_law(p);
  }

  ColumnContactElement
  column_element(const std::vector<double> &weights, const std::string &name = "kelvin-voigt",
          const double damping = 0.1)
  {
    std::vector<int> equations;
    for (unsigned int j = 0; j < weights.size() / 2 + 3; ++j)
      equations.push_back(j);
    return ColumnContactElement(0, "test", equations, slab_and_column(weights),
                                contact_law_named(name, damping));
  }

  Eigen::VectorXd
  column_force(ColumnContactElement &e, const Eigen::VectorXd &u, const Eigen::VectorXd &v)
  {
    BOOST_REQUIRE(e.set_trial(u, v));
    Eigen::VectorXd f(u.size());
    e.force_correction(f);
    return f;
  }
} // namespace

BOOST_AUTO_TEST_SUITE(column_contact_element)

BOOST_AUTO_TEST_CASE(force_on_the_column_is_the_fixed_end_reaction)
{
  // A clamped column L = 3.2 m hit at a = 1.2 m (b = 2 m) by the slab pushed
  // 0.17 m east and turned by 0.01 rad: the load on the column's DOFs is the
  // fixed-end reactions of a point load F n (Roark's Formulas, 8th ed.,
  // Table 8.1 case 1e): R0 = F b²(3a + b)/L³, M0 = F a b²/L², R1 = F a²(a + 3b)/L³,
  // M1 = -F a² b/L², in each plane, with ry = du_x/dz and rx = -du_y/dz.
  // Round-off only: 1e-12 relative.
  const double         L = 3.2, a = 1.2, b = L - a;
  ColumnContactElement e = column_element(column_of_length(L, a), "linear", 0);
  Eigen::VectorXd      u = Eigen::VectorXd::Zero(15), v = Eigen::VectorXd::Zero(15);
  u[12] = 0.17;
  u[14] = 0.01;
  const Eigen::VectorXd f = -column_force(e, u, v); // applied loads: minus the internal force
  const double          F = e.force();
  BOOST_REQUIRE(F > 0);
  const Eigen::Vector2d n(std::cos(0.01), std::sin(0.01));
  const double          R0 = F * b * b * (3 * a + b) / std::pow(L, 3), M0 = F * a * b * b / (L * L);
  const double          R1 = F * a * a * (a + 3 * b) / std::pow(L, 3), M1 = -F * a * a * b / (L * L);
  const double          tol = 1e-12 * F * L;
  for (const auto &[index, expected] :
       std::vector<std::pair<unsigned int, double>>{{0, R0 * n.x()}, {1, R0 * n.y()},
                                                    {2, 0},          {3, -M0 * n.y()},
                                                    {4, M0 * n.x()}, {5, 0},
                                                    {6, R1 * n.x()}, {7, R1 * n.y()},
                                                    {8, 0},          {9, -M1 * n.y()},
                                                    {10, M1 * n.x()}, {11, 0}})
    BOOST_TEST(std::abs(f[index] - expected) < tol, "DOF " << index << ": " << f[index]
                                                            << " instead of " << expected);
  BOOST_TEST_MESSAGE("F = " << F << " N, nodal loads " << f.head<12>().transpose());
  // equilibrium of the pair: no net force, no net moment about z (the
  // column point is at rest, the slab's torque about its moved centre)
  const Eigen::Vector2d centre(u[12], u[13]);
  const Eigen::Vector2d on_slab(f[12], f[13]), on_column(f[0] + f[6], f[1] + f[7]);
  BOOST_TEST((on_slab + on_column).norm() < 1e-12 * F);
  const auto cross = [](const Eigen::Vector2d &p, const Eigen::Vector2d &q) {
    return p.x() * q.y() - p.y() * q.x();
  };
  BOOST_TEST(std::abs(cross(Eigen::Vector2d(5.15, 1.5), on_column) + cross(centre, on_slab) +
                      f[14]) < 1e-12 * F * 10);
  // the column's moment about its base equals that of F n at height a
  BOOST_TEST(std::abs(f[4] + f[10] + L * f[6] - a * F * n.x()) < tol);
  BOOST_TEST(std::abs(-f[3] - f[9] + L * f[7] - a * F * n.y()) < tol);
}

BOOST_AUTO_TEST_CASE(tangent_matches_central_differences)
{
  // The column bent and the slab moved and turned, closed by ~20 mm and
  // approaching: force, stiffness and damping all act. The full tangent
  // B D Bᵀ against df/du + c df/dv by central differences, h = 1e-8 m
  // against forces of ~1e6 N: ~1e-6 relative.
  ColumnContactElement e = column_element(column_of_length(3.2, 1.2));
  Eigen::VectorXd      u(15), v(15);
  u << 0.01, -0.02, 0.0, 0.003, -0.002, 0.0, 0.015, 0.004, 0.0, -0.001, 0.002, 0.0, 0.2, 0.03,
    0.012;
  v << -0.1, 0.05, 0.0, 0.01, 0.02, 0.0, -0.2, 0.0, 0.0, 0.0, -0.01, 0.0, 0.4, 0.1, 0.02;
  const double c = 4 / 0.01; // gamma / (beta dt) for dt = 0.01 s
  BOOST_REQUIRE(e.set_trial(u, v));
  BOOST_REQUIRE(e.is_active());
  Eigen::MatrixXd d(5, 5);
  e.tangent_change(c, d);
  const Eigen::MatrixXd B       = e.tangent_basis();
  const Eigen::MatrixXd tangent = B * d * B.transpose();
  Eigen::MatrixXd       fd(15, 15);
  const double          h = 1e-8;
  for (unsigned int j = 0; j < 15; ++j)
    {
      Eigen::VectorXd up = u, um = u, vp = v, vm = v;
      up[j] += h;
      um[j] -= h;
      vp[j] += h;
      vm[j] -= h;
      fd.col(j) = (column_force(e, up, v) - column_force(e, um, v)) / (2 * h) +
                  c * (column_force(e, u, vp) - column_force(e, u, vm)) / (2 * h);
    }
  BOOST_TEST_MESSAGE("tangent: " << (fd - tangent).norm() / tangent.norm() << " relative");
  BOOST_TEST((fd - tangent).norm() / tangent.norm() < 1e-6);
}

BOOST_AUTO_TEST_CASE(eccentric_collision_conserves_momenta)
{
  // A free slab (m1, I1) moving east and turning hits a free column body of
  // mass m2 (W = I: it translates with its point). Symplectic Euler with the
  // force at the kick's configuration: each kick changes the linear momentum
  // by F - F and the angular momentum about the origin by
  // (x_c - c1) x F + c1 x F - x_c x F = 0, each drift leaves m x x v as it
  // is; both are conserved to round-off.
  const double         m1 = 6e4, m2 = 2e4, i1 = m1 * (100 + 64) / 12.0;
  ColumnContactElement e = column_element({1, 0, 0, 1});
  Eigen::VectorXd      mass(5), u = Eigen::VectorXd::Zero(5), v(5);
  mass << m2, m2, m1, m1, i1;
  v << -0.1, 0.05, 1.0, 0.1, 0.02;
  const auto momenta = [&]() {
    const double xc = 5.15 + u[0], yc = 1.5 + u[1];
    return Eigen::Vector3d(m2 * v[0] + m1 * v[2], m2 * v[1] + m1 * v[3],
                           m2 * (xc * v[1] - yc * v[0]) + m1 * (u[2] * v[3] - u[3] * v[2]) +
                             i1 * v[4]);
  };
  const Eigen::Vector3d before = momenta();
  const double          dt     = 1e-4;
  bool                  hit    = false;
  for (unsigned int step = 0; step < 4000; ++step)
    {
      const Eigen::VectorXd f = column_force(e, u, v);
      hit                     = hit || e.is_active();
      e.commit();
      v -= dt * f.cwiseQuotient(mass);
      u += dt * v;
    }
  const Eigen::Vector3d after = momenta();
  BOOST_TEST_MESSAGE("momenta: " << (after - before).transpose() << " of " << before.transpose());
  BOOST_TEST(hit);
  BOOST_TEST(v[2] < v[0]); // the slab bounced back from the column
  BOOST_TEST(std::abs(after[0] - before[0]) < 1e-12 * m1);
  BOOST_TEST(std::abs(after[1] - before[1]) < 1e-12 * m1);
  BOOST_TEST(std::abs(after[2] - before[2]) < 1e-10 * std::abs(before[2]) + 1e-9 * i1);
}

BOOST_AUTO_TEST_SUITE_END()
