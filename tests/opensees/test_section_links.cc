// corotTruss's tangent against central differences of its resisting force
// (2D -ndf 3 and 3D -ndf 3, elastic and yielded Steel01, large rotations),
// and zeroLengthSection's force and tangent against its definition A^T s,
// A^T k A on an elastic section (closed form).
#include <poundfe/opensees/opensees_section_links.h>
#include <poundfe/sections/elastic_section.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace poundfe;
using namespace poundfe::opensees;

namespace
{
  Domain
  two_node_domain(const unsigned int ndm, const unsigned int ndf,
                  const std::vector<double> &b)
  {
    Domain d;
    d.ndm = ndm, d.ndf = ndf;
    for (const int tag : {1, 2})
      {
        Node n;
        n.tag         = tag;
        n.coordinates = tag == 1 ? std::vector<double>(ndm, 0.0) : b;
        n.mass.assign(ndf, 0.0);
        n.element_mass = n.mass;
        n.fixed.assign(ndf, false);
        n.disp = n.vel = n.accel = n.mass;
        d.nodes.emplace(tag, n);
      }
    d.materials[1] = {"Elastic", {{"E", 2.0e11}}};
    d.materials[2] = {"Steel01", {{"fy", 2.5e8}, {"E0", 2.0e11}, {"b", 0.05}}};
    return d;
  }

  /// The largest difference of the tangent from central differences of the
  /// force at u, relative to the tangent's largest entry.
  double
  tangent_error(Element &e, const Vector &u)
  {
    const Vector zero = Vector::Zero(u.size());
    BOOST_REQUIRE(e.set_trial(u, zero));
    const Matrix K = e.tangent();
    Matrix       fd(K.rows(), K.cols());
    for (Eigen::Index j = 0; j < u.size(); ++j)
      {
        const double h  = 1.0e-7 * std::max(1.0, u.norm());
        Vector       up = u, um = u;
        up[j] += h, um[j] -= h;
        BOOST_REQUIRE(e.set_trial(up, zero));
        const Vector fp = e.force();
        e.revert();
        BOOST_REQUIRE(e.set_trial(um, zero));
        fd.col(j) = (fp - e.force()) / (2 * h);
        e.revert();
      }
    const double error = (K - fd).cwiseAbs().maxCoeff() / K.cwiseAbs().maxCoeff();
    BOOST_TEST_MESSAGE("corotTruss " << e.tag << ": tangent - differences " << error);
    return error;
  }
} // namespace

BOOST_AUTO_TEST_CASE(corot_truss_tangent_is_the_derivative_of_its_force)
{
  // a bar rotated by 1 rad and stretched 1 %: central differences of step
  // 1e-7 are exact to ~1e-8 of the tangent (round-off / h and h^2 terms)
  for (const int material : {1, 2})
    {
      Domain     plane = two_node_domain(2, 3, {3.0, 4.0});
      const auto truss = make_corot_truss(plane, 1, {{1, 2}}, 1.0e-3, material, false);
      Vector     u(6);
      u << 0.01, -0.02, 0.3, -2.9, 1.6, -0.1;
      BOOST_TEST(tangent_error(*truss, u) < 1.0e-6);

      Domain     space = two_node_domain(3, 3, {2.0, -1.0, 2.0});
      const auto bar   = make_corot_truss(space, 2, {{1, 2}}, 2.0e-3, material, false);
      Vector     v(6);
      v << 0.02, 0.01, -0.03, -1.2, 1.5, 0.4;
      BOOST_TEST(tangent_error(*bar, v) < 1.0e-6);
    }
}

BOOST_AUTO_TEST_CASE(corot_truss_strain_is_the_change_of_length)
{
  // a 5 m bar turned by 90 degrees and stretched to 5.05 m: strain 0.01,
  // force A E 0.01 along the new chord (exact to round-off)
  Domain     d     = two_node_domain(2, 2, {3.0, 4.0});
  const auto truss = make_corot_truss(d, 1, {{1, 2}}, 1.0e-3, 1, false);
  Vector     u(4);
  // the new chord (-4, 3) * 1.01, from (3, 4)
  u << 0, 0, -4.0 * 1.01 - 3.0, 3.0 * 1.01 - 4.0;
  BOOST_REQUIRE(truss->set_trial(u, Vector::Zero(4)));
  const Vector f = truss->force();
  const double N = 1.0e-3 * 2.0e11 * 0.01;
  BOOST_TEST(std::abs(f[2] - N * -0.8) < 1e-9 * N);
  BOOST_TEST(std::abs(f[3] - N * 0.6) < 1e-9 * N);
  BOOST_TEST(std::abs(truss->response({"deformation"})[0] - 0.05) < 1e-12);
}

BOOST_AUTO_TEST_CASE(zero_length_section_is_the_section_between_its_nodes)
{
  // x along global Y, yp along -X: P resists Δu_Y, Mz Δθ (z = x × yp = +Z)
  Domain d = two_node_domain(2, 3, {0.0, 0.0});
  d.sections[1] = std::make_shared<ElasticSection>(2.0e11 * 0.01, 2.0e11 * 1.0e-4);
  ZeroLengthSectionData data;
  data.nodes   = {{1, 2}};
  data.section = 1;
  data.x       = {{0, 1, 0}};
  data.y       = {{-1, 0, 0}};
  const auto e = make_zero_length_section(d, 1, data);
  Vector     u(6);
  u << 0.1, 0.2, 0.3, 0.5, 0.7, 0.9;
  BOOST_REQUIRE(e->set_trial(u, Vector::Zero(6)));
  const Vector f  = e->force();
  const double EA = 2.0e11 * 0.01, EI = 2.0e11 * 1.0e-4;
  Vector       expected(6);
  expected << 0, -EA * 0.5, -EI * 0.6, 0, EA * 0.5, EI * 0.6;
  BOOST_TEST((f - expected).norm() < 1e-12 * expected.norm());
  BOOST_TEST((e->tangent() * u - f).norm() < 1e-12 * f.norm());
  BOOST_TEST(e->response({"deformation"})[1] == 0.6, boost::test_tools::tolerance(1e-14));
}
