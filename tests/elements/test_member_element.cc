// The beam-column as a NonlinearElement: the integrator's pieces (force
// correction, B_e D_e B_e^T, K_ref) add up to the member's force and
// tangent, with the basic system's rank for a linear transformation and the
// member's DOFs otherwise; revert; the mass of the frame elements.
#include <poundfe/elements/frame_element.h>
#include <poundfe/elements/member_element.h>
#include <poundfe/laws/material_registry.h>
#include <poundfe/sections/aggregator_section.h>

#include <boost/test/unit_test.hpp>

#include <atomic>
#include <cstdlib>

using namespace poundfe;

namespace
{
  std::atomic<bool> count_allocations{false};
  std::atomic<long> allocations{0};
} // namespace

// malloc, interposed for this test executable (glibc): Eigen's heap and
// operator new both come here; counts while count_allocations is set.
extern "C" void *__libc_malloc(std::size_t) noexcept;
extern "C" void *
malloc(std::size_t size) noexcept
{
  if (count_allocations.load(std::memory_order_relaxed))
    allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(size);
}

BOOST_AUTO_TEST_CASE(member_element_splits_force_and_tangent_as_the_integrator_needs)
{
  SectionVector rigidities(2);
  rigidities << 2e9, 2e7;
  AggregatorSection section(rigidities);
  section.set_law(1, [] {
    return make_material({"Steel01", {{"fy", 1e5}, {"E0", 2e7}, {"b", 0.02}}});
  });
  const Eigen::Vector2d a(0, 0), b(3, 0.5);
  for (const Transformation kind : {Transformation::linear, Transformation::corotational})
    {
      MemberElement<2> element(0, "member", {0, 1, 2, 3, 4, 5},
                               std::make_unique<ForceBeamColumn<2>>(
                                 CrdTransformation<2>(kind, a, b), section, 5));
      BOOST_TEST(element.rank() == (kind == Transformation::linear ? 3u : 6u));
      const Eigen::MatrixXd basis = element.tangent_basis();
      BOOST_TEST(basis.rows() == 6);
      Eigen::VectorXd u(6), v = Eigen::VectorXd::Zero(6);
      u << 0.003, -0.03, 0.06, 0.012, 0.15, -0.03; // past yield
      BOOST_REQUIRE(element.set_trial(u, v));
      Eigen::VectorXd f(6);
      Eigen::MatrixXd d(element.rank(), element.rank());
      element.force_correction(f);
      element.tangent_change(123.0, d);
      const auto &member = element.member();
      const Eigen::Matrix<double, 6, 6> k_ref = element.reference_stiffness();
      BOOST_TEST((f + k_ref * u - member.resisting_force()).norm() <=
                 1e-12 * member.resisting_force().norm());
      BOOST_TEST((basis * d * basis.transpose() + k_ref - member.tangent()).norm() <=
                 1e-10 * member.tangent().norm());
      BOOST_TEST(std::abs(member.section(0).resultant()[1]) > 1e5);
      BOOST_TEST(element.reference_energy() == 0.5 * u.dot(k_ref * u),
                 boost::test_tools::tolerance(1e-14));
      // the work of the step and revert
      const double work = element.work_increment();
      BOOST_TEST(work == 0.5 * member.resisting_force().dot(u), boost::test_tools::tolerance(1e-14));
      element.revert();
      BOOST_TEST(member.resisting_force().norm() == 0);
      // the deformation observers read: the end rotation relative to the chord
      BOOST_REQUIRE(element.set_trial(u, v));
      BOOST_TEST(element.deformation(u) == member.basic_deformation()[1]);
      element.revert();
    }
}

BOOST_AUTO_TEST_CASE(member_mass_is_the_frame_elements_mass_carried_by_the_offsets)
{
  const Eigen::Vector2d      a(1, 1), b(4, 5);
  const CrdTransformation<2> t(Transformation::linear, a, b);
  Section                    s;
  s.mass_per_length = 250;
  const FrameElement frame(Point2{1, 1}, Point2{4, 5}, s);
  for (const MassMatrixType type : {MassMatrixType::lumped, MassMatrixType::consistent})
    BOOST_TEST((member_mass(t, 250, type) - frame.mass(type)).norm() <=
               1e-12 * frame.mass(type).norm());
  // offsets: the translations' total mass over the flexible length
  const CrdTransformation<2> offset(Transformation::linear, a, b, Eigen::Vector2d(0.3, 0.4),
                                    Eigen::Vector2d(-0.3, -0.4));
  const Eigen::Matrix<double, 6, 6> m = member_mass(offset, 250, MassMatrixType::lumped);
  BOOST_TEST(m(0, 0) + m(3, 3) == 250 * 4.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(m(2, 2) > 0); // the offset carries the end mass's rotary inertia
}

BOOST_AUTO_TEST_CASE(state_determination_allocates_nothing)
{
  SectionVector rigidities(2);
  rigidities << 2e9, 2e7;
  AggregatorSection section(rigidities);
  section.set_law(1, [] {
    return make_material({"Steel01", {{"fy", 1e5}, {"E0", 2e7}, {"b", 0.02}}});
  });
  for (const Transformation kind :
       {Transformation::linear, Transformation::pdelta, Transformation::corotational})
    {
      const CrdTransformation<2> t(kind, Eigen::Vector2d(0, 0), Eigen::Vector2d(3, 0.5));
      MemberElement<2> fb(0, "fb", {0, 1, 2, 3, 4, 5},
                          std::make_unique<ForceBeamColumn<2>>(t, section, 5));
      MemberElement<2> db(0, "db", {0, 1, 2, 3, 4, 5},
                          std::make_unique<DispBeamColumn<2>>(t, section, 5));
      Eigen::VectorXd u(6), w(6), v = Eigen::VectorXd::Zero(6), f(6);
      Eigen::MatrixXd d(6, 6);
      u << 0.003, -0.03, 0.06, 0.012, 0.15, -0.03;
      bool ok = true;
      allocations       = 0;
      count_allocations = true;
      for (NonlinearElement *e :
           {static_cast<NonlinearElement *>(&fb), static_cast<NonlinearElement *>(&db)})
        for (int step = 1; step <= 20; ++step)
          {
            // cycles past yield: trials, a revert, a commit
            Eigen::Ref<Eigen::MatrixXd> dd = d.topLeftCorner(e->rank(), e->rank());
            w  = std::sin(0.7 * step) * u; // into w's storage
            ok = e->set_trial(w, v) && ok;
            e->force_correction(f);
            e->tangent_change(0, dd);
            e->revert();
            ok = e->set_trial(w, v) && ok;
            e->commit();
          }
      count_allocations = false;
      BOOST_TEST(ok);
      BOOST_TEST(allocations == 0);
      // the count sees Eigen's heap and operator new
      count_allocations = true;
      const Eigen::VectorXd heap = Eigen::VectorXd::Zero(100 + allocations);
      const auto            box  = std::make_unique<double>(heap.sum());
      count_allocations          = false;
      BOOST_TEST(allocations == 2);
    }
}
