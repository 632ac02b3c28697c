// The coordinate transformations of the beam-columns: consistent tangents
// against central differences of the global forces (linear, PDelta,
// corotational; plane and space; before and after yield; rigid offsets),
// the corotational member's rigid-body rotation and its elastica (a
// cantilever under M = 2 pi EI/L rolls into a circle), and the Euler
// buckling loads from the tangent's determinant; PDelta with OpenSees's
// tangent (the scripts' members).
#include "beam_column_frames.h"

#include <poundfe/base/exceptions.h>
#include <poundfe/elements/beam_column.h>
#include <poundfe/elements/frame_element_3d.h>
#include <poundfe/laws/material_registry.h>
#include <poundfe/sections/aggregator_section.h>
#include <poundfe/sections/elastic_section.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace poundfe;
using namespace beam_column_frames;

namespace
{
  constexpr double geo_EA = 2e9, geo_EI = 2e7, geo_GJ = 1e7, geo_My = 1e5;

  template <int dim>
  AggregatorSection
  yielding_section()
  {
    SectionVector rigidities(dim == 2 ? 2 : 4);
    if constexpr (dim == 2)
      rigidities << geo_EA, geo_EI;
    else
      rigidities << geo_EA, geo_EI, 0.5 * geo_EI, geo_GJ;
    AggregatorSection section(rigidities);
    for (unsigned int r = 1; r < (dim == 2 ? 2u : 3u); ++r)
      section.set_law(r, [r] {
        return make_material(
          {"Steel01", {{"fy", geo_My}, {"E0", (r == 1 ? 1 : 0.5) * geo_EI}, {"b", 0.03}}});
      });
    return section;
  }

  /// max |K - K_fd| / max |K| at the trial u, with the element committed at
  /// u_committed (central differences, step h in each DOF).
  template <int dim>
  double
  tangent_error(BeamColumn<dim> &e, const typename BeamColumn<dim>::GlobalVector &u_committed,
                const typename BeamColumn<dim>::GlobalVector &u, const double h)
  {
    using Vector = typename BeamColumn<dim>::GlobalVector;
    using Matrix = typename BeamColumn<dim>::GlobalMatrix;
    e.reset();
    BOOST_REQUIRE(e.set_trial(u_committed));
    e.commit();
    BOOST_REQUIRE(e.set_trial(u));
    const Matrix k = e.tangent();
    Matrix       fd;
    for (int j = 0; j < Vector::RowsAtCompileTime; ++j)
      {
        Vector up = u, um = u;
        up[j] += h;
        um[j] -= h;
        BOOST_REQUIRE(e.set_trial(up));
        const Vector fp = e.resisting_force();
        BOOST_REQUIRE(e.set_trial(um));
        fd.col(j) = (fp - e.resisting_force()) / (2 * h);
      }
    return (k - fd).cwiseAbs().maxCoeff() / k.cwiseAbs().maxCoeff();
  }
} // namespace

BOOST_AUTO_TEST_CASE(plane_tangents_are_the_derivatives_of_the_forces)
{
  const AggregatorSection section = yielding_section<2>();
  const Eigen::Vector2d   a(0.3, -0.2), b(2.8, 1.1), oa(0.1, 0.15), ob(-0.2, 0.05);
  Eigen::Matrix<double, 6, 1> elastic, before, after;
  // a drifted, rotated state within yield (from the virgin state), and one
  // past it (end curvatures near 0.03 against 0.005 at yield), loading on
  // from a committed state already yielding
  before << 0.001, -0.002, 0.002, 0.003, 0.01, -0.001;
  elastic = 0.2 * before;
  after << 0.01, -0.02, 0.03, 0.03, 0.11, -0.01;
  for (const Transformation kind :
       {Transformation::linear, Transformation::pdelta, Transformation::corotational})
    for (const bool offsets : {false, true})
      {
        const CrdTransformation<2> t(kind, a, b, offsets ? oa : Eigen::Vector2d::Zero(),
                                     offsets ? ob : Eigen::Vector2d::Zero());
        ForceBeamColumn<2> fb(t, section, 5);
        DispBeamColumn<2>  db(t, section, 3);
        for (BeamColumn<2> *e : std::initializer_list<BeamColumn<2> *>{&fb, &db})
          {
            const double pre  = tangent_error(*e, 0 * elastic, elastic, 1e-7);
            const double post = tangent_error(*e, before, after, 1e-7);
            BOOST_TEST_MESSAGE("kind " << int(kind) << " offsets " << offsets << ": " << pre
                                       << ", " << post);
            BOOST_TEST(pre < 1e-6);
            BOOST_TEST(post < 1e-6);
            // past yield indeed
            BOOST_TEST(std::abs(e->section(0).resultant()[1]) > geo_My);
          }
      }
}

BOOST_AUTO_TEST_CASE(space_tangents_are_the_derivatives_of_the_forces)
{
  const AggregatorSection section = yielding_section<3>();
  const Eigen::Vector3d   a(0.3, -0.2, 0.1), b(2.1, 1.1, 1.7), oa(0.1, 0.0, 0.15),
    ob(0, -0.2, 0.05);
  const Eigen::Vector3d         orientation(0.3, 0.2, 1.0);
  Eigen::Matrix<double, 12, 1> before, after;
  before << 0.001, -0.002, 0.001, 0.002, -0.003, 0.002, 0.003, 0.006, -0.004, 0.001, 0.002,
    -0.001;
  after = 8 * before;
  after[9] += 0.01;
  for (const Transformation kind : {Transformation::linear, Transformation::pdelta})
    for (const bool offsets : {false, true})
      {
        const CrdTransformation<3> t(kind, a, b, offsets ? oa : Eigen::Vector3d::Zero(),
                                     offsets ? ob : Eigen::Vector3d::Zero(), orientation);
        ForceBeamColumn<3> fb(t, section, 4);
        DispBeamColumn<3>  db(t, section, 3);
        for (BeamColumn<3> *e : std::initializer_list<BeamColumn<3> *>{&fb, &db})
          {
            const double pre  = tangent_error(*e, 0 * before, 0.2 * before, 1e-7);
            const double post = tangent_error(*e, before, after, 1e-7);
            BOOST_TEST_MESSAGE("3D kind " << int(kind) << " offsets " << offsets << ": " << pre
                                          << ", " << post);
            BOOST_TEST(pre < 1e-6);
            BOOST_TEST(post < 1e-6);
            BOOST_TEST(std::abs(e->section(0).resultant()[1]) > geo_My);
          }
      }
  // a corotational member in space takes no offsets (OpenSees 3.8 drops them)
  BOOST_CHECK_THROW(CrdTransformation<3>(Transformation::corotational, a, b, oa, ob), InputError);
}

BOOST_AUTO_TEST_CASE(pdelta_with_the_opensees_tangent_drops_the_axial_force_variation)
{
  // an elastic member on a rotated, drifted and stretched chord: OpenSees's
  // PDeltaCrdTransf2d::getGlobalStiffMatrix gives B^T k_b B + N/L g g^T
  // (k_b the classical EA/L, 4EI/L, 2EI/L; g the chord's transverse
  // relative displacement), without the consistent tangent's (delta/L) g
  // (dN/du)^T; the forces are the same
  const Eigen::Vector2d a(0.3, -0.2), b(2.8, 1.1);
  const double          L = (b - a).norm(), c = (b - a)[0] / L, s = (b - a)[1] / L;
  Eigen::Matrix<double, 6, 1> u;
  u << 0.001, -0.002, 0.002, 0.004, 0.03, -0.001;
  CrdTransformation<2> opensees(Transformation::pdelta, a, b);
  opensees.use_opensees_tangent();
  const CrdTransformation<2> consistent(Transformation::pdelta, a, b);
  const ElasticSection       section(geo_EA, geo_EI);
  DispBeamColumn<2>          ours(opensees, section, 2), theirs(consistent, section, 2);
  BOOST_REQUIRE(ours.set_trial(u));
  BOOST_REQUIRE(theirs.set_trial(u));

  Eigen::Matrix<double, 3, 6> B;
  B << -c, -s, 0, c, s, 0, //
    -s / L, c / L, 1, s / L, -c / L, 0, //
    -s / L, c / L, 0, s / L, -c / L, 1;
  Eigen::Matrix3d k_b;
  k_b << geo_EA / L, 0, 0, 0, 4 * geo_EI / L, 2 * geo_EI / L, 0, 2 * geo_EI / L, 4 * geo_EI / L;
  Eigen::Matrix<double, 6, 1> g;
  g << s, -c, 0, -s, c, 0;
  const double                N        = geo_EA / L * (B.row(0) * u)(0);
  const Eigen::Matrix<double, 6, 6> expected = B.transpose() * k_b * B + N / L * g * g.transpose();
  const double scale = expected.cwiseAbs().maxCoeff();
  BOOST_TEST((ours.tangent() - expected).cwiseAbs().maxCoeff() / scale < 1e-12);
  BOOST_TEST(opensees.has_symmetric_tangent());
  BOOST_TEST(!consistent.has_symmetric_tangent());
  // the consistent tangent differs by (delta/L) g (EA/L B_0), not by round-off
  BOOST_TEST((theirs.tangent() - expected).cwiseAbs().maxCoeff() / scale > 1e-4);
  BOOST_TEST((ours.resisting_force() - theirs.resisting_force()).norm() <=
             1e-14 * theirs.resisting_force().norm());
}

BOOST_AUTO_TEST_CASE(a_corotational_rigid_body_rotation_strains_nothing)
{
  const ElasticSection section(geo_EA, geo_EI);
  const double         L = 2.5;
  for (const double angle : {M_PI / 2, 2.0, -3.0, 7.5})
    {
      // the member from (1, 2) at 30 degrees, turned by `angle` about node I
      // and moved by (0.4, -0.3)
      const Eigen::Vector2d xi(1, 2), dir(std::cos(M_PI / 6), std::sin(M_PI / 6));
      const Eigen::Vector2d xj = xi + L * dir;
      ForceBeamColumn<2>    element(CrdTransformation<2>(Transformation::corotational, xi, xj),
                                 section, 4);
      const Eigen::Rotation2Dd    r(angle);
      const Eigen::Vector2d       shift(0.4, -0.3), moved = r * (L * dir) - L * dir + shift;
      Eigen::Matrix<double, 6, 1> u;
      u << shift[0], shift[1], angle, moved[0], moved[1], angle;
      BOOST_REQUIRE(element.set_trial(u));
      BOOST_TEST(element.resisting_force().norm() <= 1e-12 * geo_EA);
      BOOST_TEST(element.basic_deformation().norm() <= 1e-14);
    }
}

// A member made on nodes that have moved (OpenSees's nodeIInitialDisp,
// nodeJInitialDisp): its chord joins the displaced nodes, and the nodes'
// displacements then, rotations included, are its zero. A rigid-body
// rotation from there strains nothing (closed form: v = 0), which the
// member measured from the undisplaced nodes would not.
BOOST_AUTO_TEST_CASE(a_member_made_on_moved_nodes_is_measured_from_them)
{
  const ElasticSection        section(geo_EA, geo_EI);
  const Eigen::Vector2d       xi(1, 2), xj(3, 2.5);
  Eigen::Matrix<double, 6, 1> made;
  made << 0.3, -0.1, 0.05, 0.2, 0.6, -0.04; // stretches, turns and bends the member
  const Eigen::Vector2d chord = xj + made.segment<2>(3) - xi - made.segment<2>(0);
  for (const auto kind : {Transformation::linear, Transformation::corotational})
    {
      ForceBeamColumn<2> element(CrdTransformation<2>(kind, xi, xj, Eigen::Vector2d::Zero(),
                                                      Eigen::Vector2d::Zero(),
                                                      Eigen::Vector3d::UnitZ(), made),
                                 section, 4);
      BOOST_TEST(std::abs(element.length() - chord.norm()) <= 1e-15 * chord.norm());
      BOOST_REQUIRE(element.set_trial(made));
      BOOST_TEST(element.basic_deformation().norm() == 0.0);
      BOOST_TEST(element.resisting_force().norm() <= 1e-12 * geo_EA);
      // a rigid rotation by `angle` about node I's displaced position
      const double                angle = kind == Transformation::linear ? 1e-7 : 1.2;
      const Eigen::Vector2d       turned = Eigen::Rotation2Dd(angle) * chord - chord;
      Eigen::Matrix<double, 6, 1> u      = made;
      u[2] += angle, u[5] += angle, u[3] += turned[0], u[4] += turned[1];
      BOOST_REQUIRE(element.set_trial(u));
      // linear: the chord's rotation to first order (angle^2 L of stretch)
      const double allowed = kind == Transformation::linear ? 1e-13 : 1e-14;
      BOOST_TEST(element.basic_deformation().norm() <= allowed);
    }
}

BOOST_AUTO_TEST_CASE(a_corotational_cantilever_rolls_into_a_circle)
{
  // Euler's elastica under a tip moment: constant curvature M/EI, the tip
  // back at the base after one turn. Elements in equilibrium carry no shear
  // nor axial force, so each chord keeps its length l and turns by M l/EI:
  // the nodes lie on the circle of radius l / (2 sin(pi/n)) through the base,
  // the tip exactly at the base (the continuum circle: L / 2 pi).
  const ElasticSection section(geo_EA, geo_EI);
  const unsigned int   n = 16;
  const double         L = 4, M = 2 * M_PI * geo_EI / L, l = L / n;
  Frame2d              frame;
  const int            base = frame.add_node(0, 0);
  fix(frame, base);
  const int tip = add_line(frame, base, Eigen::Vector2d(L, 0), n, Formulation::force,
                           Transformation::corotational, section, 3);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(frame.n_dofs());
  Eigen::VectorXd load(frame.n_dofs());
  const unsigned int steps = 40;
  for (unsigned int s = 1; s <= steps; ++s)
    {
      load.setZero();
      load[3 * tip + 2] = M * s / steps;
      frame.solve(u, load, M / L, 1e-10);
    }
  BOOST_TEST(u[3 * tip + 2] == 2 * M_PI, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(std::hypot(L + u[3 * tip], u[3 * tip + 1]) <= 1e-8 * L);
  const double radius = l / (2 * std::sin(M_PI / n));
  BOOST_TEST(radius / (L / (2 * M_PI)) - 1 < 0.007); // the polygon's own error, (pi/n)^2/6
  for (int node = 0; node <= tip; ++node)
    {
      const Eigen::Vector2d x = frame.nodes[node] + u.segment<2>(3 * node);
      BOOST_TEST((x - Eigen::Vector2d(0, radius)).norm() == radius,
                 boost::test_tools::tolerance(1e-8));
    }
}

namespace
{
  /// The lowest load P at which the free tangent of a column of n members
  /// under the axial force -P turns singular (its determinant changes sign),
  /// by bisection; `cantilever`: fixed base and free top, else pinned ends.
  double
  critical_load(const Transformation kind, const unsigned int n, const bool is_cantilever,
                const double guess)
  {
    // axially stiff, so that the shortening under P (1e-4 of L at Euler's
    // load) does not shift the corotational member's load
    const double         ea = 100 * geo_EA;
    const ElasticSection section(ea, geo_EI);
    const double         L = 5;
    Frame2d              frame;
    const int            base = frame.add_node(0, 0);
    const int top = add_line(frame, base, Eigen::Vector2d(0, L), n, Formulation::force, kind,
                             section, 3);
    frame.prescribed[3 * base] = frame.prescribed[3 * base + 1] = true;
    if (is_cantilever)
      frame.prescribed[3 * base + 2] = true;
    else
      frame.prescribed[3 * top] = true;
    const auto sign_at = [&](const double p) {
      // the uniform shortening of the axial force -P
      Eigen::VectorXd u = Eigen::VectorXd::Zero(frame.n_dofs());
      for (int node = 0; node <= top; ++node)
        u[3 * node + 1] = -p / ea * frame.nodes[node][1];
      return frame.free_tangent(u).partialPivLu().determinant() > 0;
    };
    double low = 0, high = 2 * guess;
    BOOST_REQUIRE(sign_at(low) != sign_at(high));
    while (high - low > 1e-12 * guess)
      {
        const double mid = 0.5 * (low + high);
        (sign_at(mid) == sign_at(low) ? low : high) = mid;
      }
    return 0.5 * (low + high);
  }
} // namespace

BOOST_AUTO_TEST_CASE(pdelta_and_corotational_columns_buckle_at_the_euler_load)
{
  const double L = 5, euler = M_PI * M_PI * geo_EI / (L * L);
  for (const Transformation kind : {Transformation::pdelta, Transformation::corotational})
    {
      // pinned-pinned: pi^2 EI/L^2; the chords' string stiffness N/l
      // underestimates the work of the axial force on a sine mode by about
      // (pi/n)^2/12 (5% at 4 members, 0.3% at 16), the error falling as 1/n^2
      const double coarse = critical_load(kind, 4, false, euler) / euler - 1;
      const double fine   = critical_load(kind, 16, false, euler) / euler - 1;
      BOOST_TEST_MESSAGE("pinned column, kind " << int(kind) << ": " << coarse << ", " << fine);
      BOOST_TEST(std::abs(coarse) < 0.06);
      BOOST_TEST(std::abs(fine) < 0.004);
      BOOST_TEST(std::abs(fine) < std::abs(coarse) / 8);
      // the cantilever: pi^2 EI / 4L^2
      const double cantilever = critical_load(kind, 16, true, euler / 4) / (euler / 4) - 1;
      BOOST_TEST(std::abs(cantilever) < 0.004);
    }
}

BOOST_AUTO_TEST_CASE(elastic_space_members_have_the_frame_element_stiffness)
{
  // the elastic 3D frame element (Euler-Bernoulli, no shear areas) is the
  // closed form each formulation must meet with one element
  Section3D s;
  s.youngs_modulus   = 200e9;
  s.shear_modulus    = 80e9;
  s.area             = 0.01;
  s.second_moment_y  = 5e-5;
  s.second_moment_z  = 1e-4;
  s.torsion_constant = 2e-5;
  const ElasticSection section(s.youngs_modulus * s.area, s.youngs_modulus * s.second_moment_z,
                               s.youngs_modulus * s.second_moment_y,
                               s.shear_modulus * s.torsion_constant);
  const Eigen::Vector3d a(0.5, -1, 2), b(2.5, 1.5, 4), orientation(0.2, -0.4, 1);
  const Matrix12        k = FrameElement3D(a, b, orientation, s).stiffness();
  const CrdTransformation<3> t(Transformation::linear, a, b, Eigen::Vector3d::Zero(),
                               Eigen::Vector3d::Zero(), orientation);
  const ForceBeamColumn<3> fb(t, section, 3);
  const DispBeamColumn<3>  db(t, section, 2);
  BOOST_TEST((fb.tangent() - k).norm() <= 1e-12 * k.norm());
  BOOST_TEST((db.tangent() - k).norm() <= 1e-12 * k.norm());
}
