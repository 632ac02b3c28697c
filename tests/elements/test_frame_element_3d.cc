// The 3D beam-column (include/poundfe/elements/frame_element_3d.h) against
// closed forms of beam theory, a second derivation of its matrices by
// quadrature of the Timoshenko shape functions, invariance under rotation,
// and the planar element. The cubic (Timoshenko) element is exact for end
// loads, so static closed forms hold to round-off; eigenvalues converge as
// h^4 (bending) and h^2 (linear torsion), tolerances from the measured
// errors (doc/verification.md).
#include <poundfe/base/exceptions.h>
#include <poundfe/elements/frame_element.h>
#include <poundfe/elements/frame_element_3d.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "test_utilities.h"

using namespace poundfe;

namespace
{
  // A steel HEB 200 (Iy strong axis, Iz weak; Avz web, Avy flanges).
  Section3D
  heb200(const bool with_shear)
  {
    Section3D s;
    s.youngs_modulus   = 2.1e11;
    s.shear_modulus    = 8.1e10;
    s.area             = 7.81e-3;
    s.second_moment_y  = 5.696e-5;
    s.second_moment_z  = 2.003e-5;
    s.torsion_constant = 5.959e-7;
    s.shear_area_y     = with_shear ? 5.0e-3 : 0;
    s.shear_area_z     = with_shear ? 2.483e-3 : 0;
    s.mass_per_length  = 61.3;
    return s;
  }

  /// A straight member from `a` to `b` in n equal elements, node i to i+1.
  std::vector<FrameElement3D>
  chain(const Eigen::Vector3d &a, const Eigen::Vector3d &b, const Eigen::Vector3d &orientation,
        const Section3D &section, const unsigned int n)
  {
    std::vector<FrameElement3D> elements;
    for (unsigned int i = 0; i < n; ++i)
      elements.emplace_back(a + (b - a) * double(i) / n, a + (b - a) * double(i + 1) / n,
                            orientation, section);
    return elements;
  }

  /// Global matrix of a chain (element i on DOFs 6i .. 6i + 11), with node 0
  /// clamped: the rows and columns of nodes 1..n.
  Eigen::MatrixXd
  clamped(const std::vector<FrameElement3D>               &elements,
          const std::function<Matrix12(const FrameElement3D &)> &matrix)
  {
    const unsigned int n = elements.size();
    Eigen::MatrixXd    k = Eigen::MatrixXd::Zero(6 * (n + 1), 6 * (n + 1));
    for (unsigned int i = 0; i < n; ++i)
      k.block<12, 12>(6 * i, 6 * i) += matrix(elements[i]);
    return k.bottomRightCorner(6 * n, 6 * n);
  }

  Eigen::MatrixXd
  clamped_stiffness(const std::vector<FrameElement3D> &elements)
  {
    return clamped(elements, [](const FrameElement3D &e) { return e.stiffness(); });
  }

  double
  relative_difference(const Eigen::MatrixXd &a, const Eigen::MatrixXd &b)
  {
    return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
  }

  /// The element of `values` nearest to `target`, relative to it.
  double
  nearest_relative_error(const Eigen::VectorXd &values, const double target)
  {
    double error = INFINITY;
    for (const double v : values)
      error = std::min(error, std::abs(v - target) / target);
    return error;
  }

  constexpr double beta_1_L = 1.8751040687119611; // first root of cos x cosh x = -1
} // namespace

// A cantilever along global x (local = global with v_xz = z), one and four
// elements: tip loads along y and z, a torque and an axial force against
// δ = PL³/3EI (+ PL/(G Av) with shear), θ = PL²/2EI, φ = TL/GJ, u = PL/EA.
BOOST_AUTO_TEST_CASE(frame3d_cantilever_matches_beam_theory)
{
  const double L = 4.0, P = 1.0e4, T = 2.0e3;
  for (const bool with_shear : {false, true})
    for (const unsigned int n : {1u, 4u})
      {
        const Section3D s = heb200(with_shear);
        const double    E = s.youngs_modulus, G = s.shear_modulus;
        const auto      elements = chain({0, 0, 0}, {L, 0, 0}, {0, 0, 1}, s, n);
        const Eigen::LDLT<Eigen::MatrixXd> ldlt(clamped_stiffness(elements));
        const auto tip = [&](const unsigned int loaded, const double load) {
          Eigen::VectorXd f = Eigen::VectorXd::Zero(6 * n);
          f[6 * (n - 1) + loaded] = load;
          const Eigen::VectorXd u = ldlt.solve(f);
          return Eigen::Matrix<double, 6, 1>(u.tail(6));
        };
        const double shear_y = with_shear ? P * L / (G * s.shear_area_y) : 0;
        const double shear_z = with_shear ? P * L / (G * s.shear_area_z) : 0;
        const auto   uy      = tip(1, P);
        const auto   uz      = tip(2, P);
        const auto   rx      = tip(3, T);
        const auto   ux      = tip(0, P);
        const double tol     = 1e-12;
        BOOST_TEST(uy[1] == P * L * L * L / (3 * E * s.second_moment_z) + shear_y,
                   boost::test_tools::tolerance(tol));
        BOOST_TEST(uy[5] == P * L * L / (2 * E * s.second_moment_z),
                   boost::test_tools::tolerance(tol));
        BOOST_TEST(uz[2] == P * L * L * L / (3 * E * s.second_moment_y) + shear_z,
                   boost::test_tools::tolerance(tol));
        // a load along +z turns the tip about -y (θy = -dw/dx)
        BOOST_TEST(-uz[4] == P * L * L / (2 * E * s.second_moment_y),
                   boost::test_tools::tolerance(tol));
        BOOST_TEST(rx[3] == T * L / (G * s.torsion_constant), boost::test_tools::tolerance(tol));
        BOOST_TEST(ux[0] == P * L / (E * s.area), boost::test_tools::tolerance(tol));
        // each load moves only its own components
        BOOST_TEST(std::abs(uy[2]) + std::abs(uy[3]) + std::abs(uy[0]) < 1e-14 * uy[1]);
        BOOST_TEST(std::abs(uz[1]) + std::abs(uz[3]) + std::abs(uz[5]) < 1e-14 * uz[2]);
      }
}

// OpenSees's geomTransf convention: a vertical column with v_xz = X has local
// y = -Y and z = X; a vector along the member (or zero) is bad input, as are
// coincident nodes and a section without torsional stiffness.
BOOST_AUTO_TEST_CASE(frame3d_local_axes_follow_the_orientation_vector)
{
  const Section3D      s = heb200(false);
  const FrameElement3D column({1, 2, 0}, {1, 2, 3}, {1, 0, 0}, s);
  Eigen::Matrix3d      expected;
  expected << 0, 0, 1, 0, -1, 0, 1, 0, 0;
  BOOST_TEST(relative_difference(column.local_axes(), expected) == 0.0);
  BOOST_CHECK_THROW(FrameElement3D({0, 0, 0}, {0, 0, 3}, {0, 0, -2}, s), InputError);
  BOOST_CHECK_THROW(FrameElement3D({0, 0, 0}, {0, 0, 3}, {1e-9, 0, 1}, s), InputError);
  BOOST_CHECK_THROW(FrameElement3D({0, 0, 0}, {0, 0, 3}, {0, 0, 0}, s), InputError);
  BOOST_CHECK_THROW(FrameElement3D({1, 1, 1}, {1, 1, 1}, {1, 0, 0}, s), InputError);
  Section3D no_torsion        = s;
  no_torsion.torsion_constant = 0;
  BOOST_CHECK_THROW(FrameElement3D({0, 0, 0}, {0, 0, 3}, {1, 0, 0}, no_torsion), InputError);
}

// The same cantilever rotated by an arbitrary rotation Q (axis and angle
// below), its orientation vector rotated with it: global matrices are
// Q-conjugates, local matrices equal, and the rotated tip load gives the
// rotated displacements and rotations at every node.
BOOST_AUTO_TEST_CASE(frame3d_rotated_member_gives_the_rotated_response)
{
  const Section3D       s = heb200(true);
  const double          L = 3.0;
  const Eigen::Matrix3d q =
    Eigen::AngleAxisd(2.1, Eigen::Vector3d(0.3, -0.8, 0.52).normalized()).toRotationMatrix();
  const Eigen::Vector3d offset(5, -2, 7), a(0, 0, 0), b(L, 0, 0), v(0.2, 0.4, 1);
  const unsigned int    n = 4;
  const auto            plain   = chain(a, b, v, s, n);
  const auto            rotated = chain(offset + q * a, offset + q * b, q * v, s, n);

  Matrix12 big_q = Matrix12::Zero();
  for (unsigned int block = 0; block < 4; ++block)
    big_q.block<3, 3>(3 * block, 3 * block) = q;
  const FrameElement3D &e = plain[0], &r = rotated[0];
  BOOST_TEST(relative_difference(r.local_stiffness(), e.local_stiffness()) < 1e-15);
  BOOST_TEST(relative_difference(r.stiffness(), big_q * e.stiffness() * big_q.transpose()) < 1e-14);
  for (const MassMatrixType type : {MassMatrixType::lumped, MassMatrixType::consistent})
    BOOST_TEST(relative_difference(r.mass(type, RotaryInertia::included),
                                   big_q * e.mass(type, RotaryInertia::included) *
                                     big_q.transpose()) < 1e-14);
  BOOST_TEST(relative_difference(r.geometric_stiffness(-3e5),
                                 big_q * e.geometric_stiffness(-3e5) * big_q.transpose()) < 1e-14);

  Eigen::VectorXd f = Eigen::VectorXd::Zero(6 * n), f_rotated = f;
  Eigen::Vector3d force(1e4, -3e4, 2e4), moment(5e3, 1e3, -2e3);
  f.segment<3>(6 * (n - 1))             = force;
  f.segment<3>(6 * (n - 1) + 3)         = moment;
  f_rotated.segment<3>(6 * (n - 1))     = q * force;
  f_rotated.segment<3>(6 * (n - 1) + 3) = q * moment;
  const Eigen::VectorXd u   = clamped_stiffness(plain).ldlt().solve(f);
  const Eigen::VectorXd u_r = clamped_stiffness(rotated).ldlt().solve(f_rotated);
  double                worst = 0;
  for (unsigned int node = 0; node < n; ++node)
    for (unsigned int part = 0; part < 2; ++part)
      {
        const Eigen::Vector3d expected = q * u.segment<3>(6 * node + 3 * part);
        worst = std::max(worst, (u_r.segment<3>(6 * node + 3 * part) - expected).norm() /
                                  u.segment<3>(6 * node + 3 * part).norm());
      }
  BOOST_TEST_MESSAGE("rotated cantilever: largest relative difference " << worst);
  BOOST_TEST(worst < 1e-11);
}

// An element in a general position: K, M and K_G symmetric; K has exactly
// six zero-energy modes, and they are the rigid motions (translations and
// rotations u = ω × (x - p), θ = ω); M carries the member's mass and polar
// inertia in rigid motion.
BOOST_AUTO_TEST_CASE(frame3d_has_six_rigid_body_modes)
{
  const Section3D       s = heb200(true);
  const Eigen::Vector3d x1(0.3, -1.2, 2.0), x2(2.9, 0.4, 4.1);
  const FrameElement3D  e(x1, x2, {-0.4, 1.0, 0.3}, s);
  const Matrix12        k = e.stiffness();
  BOOST_TEST((k - k.transpose()).cwiseAbs().maxCoeff() <= 1e-15 * k.cwiseAbs().maxCoeff());
  for (const MassMatrixType type : {MassMatrixType::lumped, MassMatrixType::consistent})
    {
      const Matrix12 m = e.mass(type, RotaryInertia::included);
      BOOST_TEST((m - m.transpose()).cwiseAbs().maxCoeff() <= 1e-15 * m.cwiseAbs().maxCoeff());
    }
  const Matrix12 g = e.geometric_stiffness(-1e5);
  BOOST_TEST((g - g.transpose()).cwiseAbs().maxCoeff() <= 1e-15 * g.cwiseAbs().maxCoeff());

  const Eigen::SelfAdjointEigenSolver<Matrix12> solver(k);
  const auto   lambda = solver.eigenvalues(); // ascending
  const double scale  = lambda[11];
  BOOST_TEST_MESSAGE("rigid modes: |λ_6|/λ_max = " << std::abs(lambda[5]) / scale
                                                   << ", λ_7/λ_max = " << lambda[6] / scale);
  for (unsigned int i = 0; i < 6; ++i)
    BOOST_TEST(std::abs(lambda[i]) < 1e-12 * scale);
  BOOST_TEST(lambda[6] > 1e-8 * scale);

  const Eigen::Vector3d p(1, 1, 1);
  const double          length = (x2 - x1).norm(), m = s.mass_per_length * length;
  for (unsigned int d = 0; d < 3; ++d)
    {
      Vector12 translation = Vector12::Zero(), rotation = Vector12::Zero();
      translation[d] = translation[6 + d] = 1;
      const Eigen::Vector3d omega         = Eigen::Vector3d::Unit(d);
      rotation.segment<3>(0)              = omega.cross(x1 - p);
      rotation.segment<3>(3)              = omega;
      rotation.segment<3>(6)              = omega.cross(x2 - p);
      rotation.segment<3>(9)              = omega;
      BOOST_TEST((k * translation).norm() < 1e-12 * scale);
      BOOST_TEST((k * rotation).norm() < 1e-12 * scale * rotation.norm());
      for (const MassMatrixType type : {MassMatrixType::lumped, MassMatrixType::consistent})
        BOOST_TEST(translation.dot(e.mass(type) * translation) == m,
                   boost::test_tools::tolerance(1e-13));
    }
  // a rigid twist about the member axis: kinetic energy of ρ Ip L
  Vector12 twist = Vector12::Zero();
  twist.segment<3>(3) = twist.segment<3>(9) = e.local_axes().row(0).transpose();
  const double rho_ip =
    s.mass_per_length / s.area * (s.second_moment_y + s.second_moment_z) * length;
  for (const MassMatrixType type : {MassMatrixType::lumped, MassMatrixType::consistent})
    BOOST_TEST(twist.dot(e.mass(type) * twist) == rho_ip, boost::test_tools::tolerance(1e-13));
}

namespace
{
  /// A polynomial in ξ = x/L, coefficients from ξ^0.
  using Polynomial = std::vector<double>;

  double
  value(const Polynomial &p, const double xi)
  {
    double v = 0;
    for (auto c = p.rbegin(); c != p.rend(); ++c)
      v = v * xi + *c;
    return v;
  }

  /// d/dx = (1/L) d/dξ.
  Polynomial
  derivative(const Polynomial &p, const double L)
  {
    Polynomial d;
    for (unsigned int i = 1; i < p.size(); ++i)
      d.push_back(i * p[i] / L);
    return d;
  }

  /// The exact end-load solution of a Timoshenko beam on (v1, θ1, v2, θ2):
  /// deflection v (cubic) and section rotation ψ (quadratic), with
  /// Φ = 12 EI/(G Av L²) (Przemieniecki ch. 5, derived anew from
  /// EI ψ'' + G Av (v' - ψ) = 0, v'' = ψ').
  struct TimoshenkoShapes
  {
    std::array<Polynomial, 4> v, psi;
    TimoshenkoShapes(const double L, const double phi)
    {
      const double c = 1 / (1 + phi), h = L / (2 * (1 + phi));
      v[0]   = {c * (1 + phi), -c * phi, -3 * c, 2 * c};
      v[1]   = {0, h * (phi + 2), -h * (phi + 4), 2 * h};
      v[2]   = {0, c * phi, 3 * c, -2 * c};
      v[3]   = {0, -h * phi, h * (phi - 2), 2 * h};
      psi[0] = {0, -6 * c / L, 6 * c / L};
      psi[1] = {c * (1 + phi), -c * (4 + phi), 3 * c};
      psi[2] = {0, 6 * c / L, -6 * c / L};
      psi[3] = {0, c * (phi - 2), 3 * c};
    }
  };

  /// ∫_0^L f(ξ) dx by 5-point Gauss (exact to degree 9).
  Eigen::Matrix4d
  integrate(const double L, const std::function<Eigen::Matrix4d(double)> &f)
  {
    const double a = std::sqrt(5 - 2 * std::sqrt(10. / 7)) / 3,
                 b = std::sqrt(5 + 2 * std::sqrt(10. / 7)) / 3;
    const double wa = (322 + 13 * std::sqrt(70.)) / 900, wb = (322 - 13 * std::sqrt(70.)) / 900;
    const std::array<std::pair<double, double>, 5> points{
      {{0, 128. / 225}, {-a, wa}, {a, wa}, {-b, wb}, {b, wb}}};
    Eigen::Matrix4d sum = Eigen::Matrix4d::Zero();
    for (const auto &[t, w] : points)
      sum += 0.5 * w * L * f(0.5 * (1 + t));
    return sum;
  }

  Eigen::Matrix4d
  block(const Matrix12 &k, const std::array<unsigned int, 4> &dofs,
        const std::array<double, 4> &signs)
  {
    Eigen::Matrix4d b;
    for (unsigned int i = 0; i < 4; ++i)
      for (unsigned int j = 0; j < 4; ++j)
        b(i, j) = signs[i] * signs[j] * k(dofs[i], dofs[j]);
    return b;
  }
} // namespace

// With shear deformation (Φ = 0.087 and 0.50 for a short member): each bending
// block of the local stiffness, consistent mass (translation + rotary
// inertia) and geometric stiffness equals the quadrature of the Timoshenko
// shape functions: ∫ EI ψ'² + G Av (v' - ψ)², ∫ m̄ v² + ρI ψ², ∫ N v'².
BOOST_AUTO_TEST_CASE(frame3d_matrices_are_the_integrals_of_the_timoshenko_shapes)
{
  const Section3D      s = heb200(true);
  const double         L = 1.2, N = -2.5e5, rho = s.mass_per_length / s.area;
  const FrameElement3D e({0, 0, 0}, {L, 0, 0}, {0, 0, 1}, s);
  const Matrix12       k = e.local_stiffness(), g = e.local_geometric_stiffness(N);
  const Matrix12       m = e.local_mass(MassMatrixType::consistent, RotaryInertia::included);
  struct Plane
  {
    std::array<unsigned int, 4> dofs;
    std::array<double, 4>       signs;
    double                      second_moment, shear_area, phi;
  };
  for (const Plane &plane :
       {Plane{{{1, 5, 7, 11}}, {{1, 1, 1, 1}}, s.second_moment_z, s.shear_area_y,
              e.shear_parameter_y()},
        Plane{{{2, 4, 8, 10}}, {{1, -1, 1, -1}}, s.second_moment_y, s.shear_area_z,
              e.shear_parameter_z()}})
    {
      const double EI = s.youngs_modulus * plane.second_moment;
      BOOST_TEST(plane.phi == 12 * EI / (s.shear_modulus * plane.shear_area * L * L),
                 boost::test_tools::tolerance(1e-15));
      const TimoshenkoShapes shapes(L, plane.phi);
      const auto             at = [&](const std::array<Polynomial, 4> &f, const double xi,
                          const bool differentiate) {
        Eigen::Vector4d r;
        for (unsigned int i = 0; i < 4; ++i)
          r[i] = value(differentiate ? derivative(f[i], L) : f[i], xi);
        return r;
      };
      const Eigen::Matrix4d stiffness = integrate(L, [&](const double xi) {
        const Eigen::Vector4d curvature = at(shapes.psi, xi, true);
        const Eigen::Vector4d shear     = at(shapes.v, xi, true) - at(shapes.psi, xi, false);
        return Eigen::Matrix4d(EI * curvature * curvature.transpose() +
                               s.shear_modulus * plane.shear_area * shear * shear.transpose());
      });
      const Eigen::Matrix4d mass = integrate(L, [&](const double xi) {
        const Eigen::Vector4d v = at(shapes.v, xi, false), psi = at(shapes.psi, xi, false);
        return Eigen::Matrix4d(s.mass_per_length * v * v.transpose() +
                               rho * plane.second_moment * psi * psi.transpose());
      });
      const Eigen::Matrix4d geometric = integrate(L, [&](const double xi) {
        const Eigen::Vector4d slope = at(shapes.v, xi, true);
        return Eigen::Matrix4d(N * slope * slope.transpose());
      });
      BOOST_TEST(relative_difference(block(k, plane.dofs, plane.signs), stiffness) < 1e-13);
      BOOST_TEST(relative_difference(block(m, plane.dofs, plane.signs), mass) < 1e-13);
      BOOST_TEST(relative_difference(block(g, plane.dofs, plane.signs), geometric) < 1e-13);
    }
}

// A member in the global X-Z plane (Z up) is the planar element of the
// (X, Y) plane with Y -> Z and θz -> -θy: its (ux, uz, ry) rows of K, the
// consistent and lumped M and K_G equal the 2D matrices entry by entry
// (ry's sign flipped), both with local y in the plane (v_xz = -Y, I = Iz)
// and with local z in it (v_xz in the plane, I = Iy).
BOOST_AUTO_TEST_CASE(frame3d_in_a_plane_reproduces_the_planar_element)
{
  const double    angle = 1.1, L = 3.7, N = -4e5;
  const double    c = std::cos(angle), s = std::sin(angle);
  const Point2    start{0.5, 1.0}, end{0.5 + L * c, 1.0 + L * s};
  const Section   planar{2.1e11, 7.81e-3, 5.696e-5, 61.3};
  const FrameElement element_2d(start, end, planar);
  const std::array<unsigned int, 6> dofs{{0, 2, 4, 6, 8, 10}};
  const std::array<double, 6>       signs{{1, 1, -1, 1, 1, -1}};
  for (const bool in_plane_y : {true, false})
    {
      Section3D section = heb200(false);
      section.youngs_modulus  = planar.youngs_modulus;
      section.area            = planar.area;
      section.mass_per_length = planar.mass_per_length;
      (in_plane_y ? section.second_moment_z : section.second_moment_y) = planar.second_moment;
      const Eigen::Vector3d orientation =
        in_plane_y ? Eigen::Vector3d(0, -1, 0) : Eigen::Vector3d(-s, 0, c);
      const FrameElement3D element({start.x, 0, start.y}, {end.x, 0, end.y}, orientation, section);
      const auto in_plane = [&](const Matrix12 &m) {
        Matrix6 r;
        for (unsigned int i = 0; i < 6; ++i)
          for (unsigned int j = 0; j < 6; ++j)
            r(i, j) = signs[i] * signs[j] * m(dofs[i], dofs[j]);
        return r;
      };
      const double tol = 1e-14;
      BOOST_TEST(relative_difference(in_plane(element.stiffness()), element_2d.stiffness()) < tol);
      for (const MassMatrixType type : {MassMatrixType::lumped, MassMatrixType::consistent})
        BOOST_TEST(relative_difference(in_plane(element.mass(type)), element_2d.mass(type)) <
                   tol);
      BOOST_TEST(relative_difference(in_plane(element.geometric_stiffness(N)),
                                     element_2d.geometric_stiffness(N)) < tol);
    }
}

// Consistent-mass cantilever, rotated in space so that the global problem
// couples every DOF: its first bending frequencies about both axes converge
// (from above, as h^4) to (β1 L)² sqrt(EI/(m̄ L⁴)), its first torsional one
// to (π/2L) sqrt(GJ/(ρ Ip)) (as h²) — and equals, to round-off, the exact eigenvalue
// of n linear elements, ω² = (6GJ/(ρIp h²)) (1 - cos θ)/(2 + cos θ),
// θ = π/(2n).
BOOST_AUTO_TEST_CASE(frame3d_cantilever_frequencies_converge_to_the_closed_forms)
{
  const Section3D s = heb200(false);
  const double    L = 5.0, E = s.youngs_modulus, m = s.mass_per_length;
  const double    rho_ip = m / s.area * (s.second_moment_y + s.second_moment_z);
  const double    bending = beta_1_L * beta_1_L / (L * L);
  const double    omega_z = bending * std::sqrt(E * s.second_moment_z / m);
  const double    omega_y = bending * std::sqrt(E * s.second_moment_y / m);
  const double    omega_t =
    M_PI / (2 * L) * std::sqrt(s.shear_modulus * s.torsion_constant / rho_ip);
  const Eigen::Matrix3d q =
    Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, -0.5).normalized()).toRotationMatrix();
  double previous_z = INFINITY, previous_y = INFINITY, previous_t = INFINITY;
  for (const unsigned int n : {2u, 4u, 8u, 16u})
    {
      const auto elements =
        chain({0, 0, 0}, q * Eigen::Vector3d(L, 0, 0), q * Eigen::Vector3d(0, 0, 1), s, n);
      const auto consistent = [](const FrameElement3D &e) {
        return e.mass(MassMatrixType::consistent);
      };
      const Eigen::VectorXd omega =
        poundfe_test::generalized_eigenvalues(clamped_stiffness(elements),
                                              clamped(elements, consistent))
          .cwiseSqrt();
      const double error_z = nearest_relative_error(omega, omega_z);
      const double error_y = nearest_relative_error(omega, omega_y);
      const double h = L / n, theta = M_PI / (2 * n);
      const double omega_t_discrete = std::sqrt(6 * s.shear_modulus * s.torsion_constant /
                                                (rho_ip * h * h) * (1 - std::cos(theta)) /
                                                (2 + std::cos(theta)));
      BOOST_TEST_MESSAGE("n = " << n << ": bending about z " << error_z << ", about y " << error_y
                                << ", torsion " << nearest_relative_error(omega, omega_t)
                                << " (to the discrete closed form "
                                << nearest_relative_error(omega, omega_t_discrete) << ")");
      // the eigensolver's error is ~ε λ_max: relative ε ω_max²/ω_t² here,
      // 1e-14 (n = 2) to 1e-11 (n = 16)
      BOOST_TEST(nearest_relative_error(omega, omega_t_discrete) < 1e-10);
      BOOST_TEST(error_z < previous_z / 10);
      BOOST_TEST(error_y < previous_y / 10);
      const double error_t = nearest_relative_error(omega, omega_t);
      BOOST_TEST(error_t < previous_t / 3.9);
      previous_z = error_z;
      previous_y = error_y;
      previous_t = error_t;
      if (n == 16)
        {
          BOOST_TEST(error_z < 2e-7);
          BOOST_TEST(error_y < 2e-7);
          BOOST_TEST(error_t < 5e-4);
        }
    }
}

// Euler buckling of a cantilever column (8 elements, in a general direction)
// from K φ = P G φ, G the geometric stiffness of a unit compression: the
// two flexural loads π²EI/(4L²) about both axes, and the torsional load
// GJ A/Ip (Saint-Venant, no warping: exact for any mesh).
BOOST_AUTO_TEST_CASE(frame3d_cantilever_buckles_at_the_euler_load)
{
  const Section3D s = heb200(false);
  const double    L = 4.0, E = s.youngs_modulus;
  const unsigned int n = 8;
  const auto elements  = chain({1, 2, 3}, {1 + 0.6 * L, 2, 3 + 0.8 * L}, {0, 1, 0}, s, n);
  const Eigen::MatrixXd k = clamped_stiffness(elements);
  const Eigen::MatrixXd g =
    clamped(elements, [](const FrameElement3D &e) { return e.geometric_stiffness(-1.0); });
  // K φ = P (-G) φ with -G semi-definite: the loads are 1/μ of the
  // eigenvalues μ of L⁻¹(-G)L⁻ᵀ, K = L Lᵀ.
  const Eigen::LLT<Eigen::MatrixXd> llt(k);
  BOOST_REQUIRE(llt.info() == Eigen::Success);
  Eigen::MatrixXd c = llt.matrixL().solve(Eigen::MatrixXd(-g));
  c                 = llt.matrixL().solve(Eigen::MatrixXd(c.transpose()));
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(c);
  Eigen::VectorXd loads(0);
  for (const double mu : solver.eigenvalues())
    if (mu > 1e-12 * solver.eigenvalues().maxCoeff())
      {
        loads.conservativeResize(loads.size() + 1);
        loads[loads.size() - 1] = 1 / mu;
      }
  const double weak   = M_PI * M_PI * E * s.second_moment_z / (4 * L * L);
  const double strong = M_PI * M_PI * E * s.second_moment_y / (4 * L * L);
  const double torsional =
    s.shear_modulus * s.torsion_constant * s.area / (s.second_moment_y + s.second_moment_z);
  BOOST_TEST_MESSAGE("buckling, 8 elements: weak axis "
                     << nearest_relative_error(loads, weak) << ", strong axis "
                     << nearest_relative_error(loads, strong) << ", torsional "
                     << nearest_relative_error(loads, torsional));
  BOOST_TEST(loads.minCoeff() == weak, boost::test_tools::tolerance(5e-6));
  BOOST_TEST(nearest_relative_error(loads, strong) < 5e-6);
  BOOST_TEST(nearest_relative_error(loads, torsional) < 1e-12);
}
