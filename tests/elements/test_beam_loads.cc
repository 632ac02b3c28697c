// Element loads on the beam-columns (a uniform load along the member, a
// member's self-weight) against closed forms and statics: a fixed-fixed
// beam's end moments w L^2/12 and mid-span moment w L^2/24 (force-based:
// the sections carry s = b q + s_p; displacement-based and elastic: the
// fixed-end forces q0, p0), in the plane and in space about both axes; a
// column under its own weight (the base reaction w L exactly, the top's
// settlement w L^2/(2 EA)); a portal frame's reactions by statics; the load
// stepped by its factor as in a gravity analysis, the tangent by finite
// differences, revert.
#include "beam_column_frames.h"

#include <poundfe/elements/beam_column.h>
#include <poundfe/elements/member_element.h>
#include <poundfe/sections/elastic_section.h>
#include <poundfe/sections/fibre_section.h>
#include <poundfe/sections/section_builders.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace poundfe;
using namespace beam_column_frames;

namespace
{
  constexpr double load_EA = 200e9 * 0.01, load_EI = 200e9 * 1e-4, load_L = 6.0;

  /// An RC column section (Concrete01 and Steel01 fibres).
  FibreSection
  rc_section()
  {
    RcRectangle r;
    r.depth = r.width     = 0.4;
    r.cover               = 0.04;
    r.bars_top            = 3;
    r.bars_bottom         = 3;
    r.bar_diameter        = 0.02;
    r.stirrup_diameter    = 0.01;
    r.stirrup_spacing     = 0.1;
    r.fibres_y            = 10;
    r.fibres_z            = 4;
    return FibreSection(rc_rectangle(r), 2);
  }

  /// The members of both formulations on `section` from a to b.
  std::vector<std::unique_ptr<BeamColumn<2>>>
  both_formulations(const Eigen::Vector2d &a, const Eigen::Vector2d &b, const SectionLaw &section)
  {
    std::vector<std::unique_ptr<BeamColumn<2>>> members;
    members.push_back(make_member(Formulation::force, Transformation::linear, a, b, section, 5));
    members.push_back(
      make_member(Formulation::displacement, Transformation::linear, a, b, section, 5));
    return members;
  }
} // namespace

BOOST_AUTO_TEST_CASE(fixed_fixed_beam_has_the_closed_form_end_and_mid_span_moments)
{
  // a beam along x held at both ends (u = 0) under w downwards: end
  // reactions w L/2 up, end moments w L^2/12 (hogging), mid-span w L^2/24
  // (sagging); Lobatto's 5 points put one at mid-span
  const double         w = 12e3, L = load_L;
  const ElasticSection section(load_EA, load_EI);
  for (auto &beam : both_formulations({0, 0}, {L, 0}, section))
    {
      beam->set_uniform_load(MemberLoad<2>(0, -w));
      beam->set_load_factor(1);
      BOOST_REQUIRE(beam->set_trial(Eigen::Matrix<double, 6, 1>::Zero()));
      Eigen::Matrix<double, 6, 1> expected;
      expected << 0, w * L / 2, w * L * L / 12, 0, w * L / 2, -w * L * L / 12;
      // round-off of the element's iteration on an exact elastic member
      BOOST_TEST((beam->resisting_force() - expected).cwiseAbs().maxCoeff() <=
                 1e-12 * w * L * L);
      BOOST_TEST(std::abs(beam->basic_force()[1] - w * L * L / 12) <= 1e-12 * w * L * L);
    }
  ForceBeamColumn<2> beam(CrdTransformation<2>(Transformation::linear, {0, 0}, {L, 0}), section,
                          5);
  beam.set_uniform_load(MemberLoad<2>(0, -w));
  beam.set_load_factor(1);
  BOOST_REQUIRE(beam.set_trial(Eigen::Matrix<double, 6, 1>::Zero()));
  BOOST_TEST(std::abs(beam.section(2).resultant()[1] - w * L * L / 24) <= 1e-12 * w * L * L);
  BOOST_TEST(std::abs(beam.section(0).resultant()[1] + w * L * L / 12) <= 1e-12 * w * L * L);
  BOOST_TEST(std::abs(beam.section(4).resultant()[1] + w * L * L / 12) <= 1e-12 * w * L * L);
}

BOOST_AUTO_TEST_CASE(space_beam_carries_loads_about_both_axes)
{
  // a 3D member along x, held at both ends, under w_y and w_z: the end
  // moments w_y L^2/12 about z and w_z L^2/12 about y with OpenSees's signs
  // (q0 = (0, -w_y L^2/12, w_y L^2/12, w_z L^2/12, -w_z L^2/12, 0)); the
  // mid-span sections w L^2/24 (force-based)
  const double               wy = -8e3, wz = 5e3, L = load_L;
  const ElasticSection       section(load_EA, load_EI, 0.6 * load_EI, 0.3 * load_EI);
  const CrdTransformation<3> t(Transformation::linear, Eigen::Vector3d::Zero(),
                               Eigen::Vector3d(L, 0, 0), Eigen::Vector3d::Zero(),
                               Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 1));
  ForceBeamColumn<3> force(t, section, 5);
  DispBeamColumn<3>  displacement(t, section, 3);
  for (BeamColumn<3> *beam : std::initializer_list<BeamColumn<3> *>{&force, &displacement})
    {
      beam->set_uniform_load(MemberLoad<3>(0, wy, wz));
      beam->set_load_factor(1);
      BOOST_REQUIRE(beam->set_trial(Eigen::Matrix<double, 12, 1>::Zero()));
      Eigen::Matrix<double, 6, 1> q;
      q << 0, -wy * L * L / 12, wy * L * L / 12, wz * L * L / 12, -wz * L * L / 12, 0;
      BOOST_TEST((beam->basic_force() - q).cwiseAbs().maxCoeff() <= 1e-12 * 1e4 * L * L);
      // the end shears: half the load each, against it
      const auto &p = beam->resisting_force();
      for (const int end : {0, 6})
        {
          BOOST_TEST(std::abs(p[end + 1] + wy * L / 2) <= 1e-12 * 1e4 * L);
          BOOST_TEST(std::abs(p[end + 2] + wz * L / 2) <= 1e-12 * 1e4 * L);
        }
    }
  BOOST_TEST(std::abs(force.section(2).resultant()[1] + wy * L * L / 24) <= 1e-12 * 1e4 * L * L);
  BOOST_TEST(std::abs(force.section(2).resultant()[2] - wz * L * L / 24) <= 1e-12 * 1e4 * L * L);
}

BOOST_AUTO_TEST_CASE(column_under_its_own_weight_carries_it_to_the_base)
{
  // a cantilever column, fixed at its base, under its weight w = rho A g
  // alone: the base reaction is w L (statics, to Newton's tolerance), the
  // top settles by w L^2/(2 EA) (the integral of N/EA, N = -w (L - x)) on an
  // elastic section, exact for one element of either formulation (the
  // force-based one integrates N exactly, the displacement-based one's
  // linear axial field has exact nodal values); an RC fibre section carries
  // the same reaction
  const double         rho_a_g = 2500 * 0.16 * 9.81, L = 3.5;
  const ElasticSection elastic(load_EA, load_EI);
  const FibreSection   rc = rc_section();
  for (const SectionLaw *section : {static_cast<const SectionLaw *>(&elastic),
                                    static_cast<const SectionLaw *>(&rc)})
    for (auto &column : both_formulations({0, 0}, {0, L}, *section))
      {
        Frame2d frame;
        fix(frame, frame.add_node(0, 0));
        frame.add_node(0, L);
        column->set_uniform_load(self_weight_load(column->transformation(), rho_a_g));
        column->set_load_factor(1);
        frame.members.push_back({std::move(column), {{0, 1}}});
        Eigen::VectorXd       u = Eigen::VectorXd::Zero(6);
        const Eigen::VectorXd f = frame.solve(u, Eigen::VectorXd::Zero(6), rho_a_g * L, 1e-12);
        BOOST_TEST(std::abs(f[1] - rho_a_g * L) <= 1e-12 * rho_a_g * L);
        BOOST_TEST(std::abs(f[0]) <= 1e-12 * rho_a_g * L);
        if (section == &elastic)
          BOOST_TEST(std::abs(u[4] + rho_a_g * L * L / (2 * load_EA)) <=
                     1e-9 * rho_a_g * L * L / (2 * load_EA));
      }
}

BOOST_AUTO_TEST_CASE(portal_frame_reactions_balance_the_members_weight)
{
  // a fixed-base portal (columns of height h, beam of span s) under its
  // members' weight: the reactions balance it (vertical sum, horizontal sum
  // 0, moments about the left base), and by symmetry each base carries its
  // column and half the beam
  const double   h = 3.2, s = 5.5, w_column = 4e3, w_beam = 6e3;
  const FibreSection rc = rc_section();
  for (const Formulation formulation : {Formulation::force, Formulation::displacement})
    {
      Frame2d   frame;
      const int a = frame.add_node(0, 0), b = frame.add_node(s, 0);
      fix(frame, a);
      fix(frame, b);
      const int c = frame.add_node(0, h), d = frame.add_node(s, h);
      const auto add = [&](const int i, const int j, const double w, const unsigned int points) {
        auto m = make_member(formulation, Transformation::linear, frame.nodes[i], frame.nodes[j],
                             rc, points);
        m->set_uniform_load(self_weight_load(m->transformation(), w));
        frame.members.push_back({std::move(m), {{i, j}}});
      };
      add(a, c, w_column, 5);
      add(b, d, w_column, 5);
      add(c, d, w_beam, 5);
      Eigen::VectorXd u = Eigen::VectorXd::Zero(frame.n_dofs());
      Eigen::VectorXd f;
      for (int step = 1; step <= 4; ++step) // load-controlled, as the gravity analysis
        {
          for (auto &m : frame.members)
            m.element->set_load_factor(step / 4.0);
          f = frame.solve(u, Eigen::VectorXd::Zero(frame.n_dofs()), w_beam * s, 1e-12);
        }
      const double total = 2 * w_column * h + w_beam * s, scale = total * s;
      BOOST_TEST(std::abs(f[1] + f[4] - total) <= 1e-10 * total);
      BOOST_TEST(std::abs(f[0] + f[3]) <= 1e-10 * total);
      // about the left base: the reactions' moment against the loads'
      const double moment = f[2] + f[5] + s * f[4] - (w_column * h * s + w_beam * s * s / 2);
      BOOST_TEST(std::abs(moment) <= 1e-10 * scale);
      BOOST_TEST(std::abs(f[1] - (w_column * h + w_beam * s / 2)) <= 1e-8 * total);
    }
}

BOOST_AUTO_TEST_CASE(loaded_element_tangent_matches_finite_differences)
{
  // an inclined RC member under its weight, displaced past cracking (from a
  // committed state on the way, loading on): the tangent against central
  // differences of the resisting force (steps of
  // 1e-9, 1e-6 of the displacements: the differences' own error ~ 1e-6)
  const FibreSection rc = rc_section();
  Eigen::Matrix<double, 6, 1> u;
  u << 1e-3, -2e-3, 4e-3, 3e-3, -6e-3, -2e-3;
  for (const Transformation kind : {Transformation::linear, Transformation::pdelta})
    for (const Formulation formulation : {Formulation::force, Formulation::displacement})
      {
        auto m = make_member(formulation, kind, {0, 0}, {4, 3}, rc, 5);
        m->set_uniform_load(self_weight_load(m->transformation(), 5e3));
        m->set_load_factor(1);
        // committed short of u, so that u and u +- du continue its loading
        // (no fibre's law reverses between them)
        BOOST_REQUIRE(m->set_trial(0.95 * u));
        m->commit();
        BOOST_REQUIRE(m->set_trial(u));
        const Eigen::Matrix<double, 6, 6> k = m->tangent();
        m->revert();
        Eigen::Matrix<double, 6, 6>       numeric;
        const double                      step = 1e-9;
        for (int j = 0; j < 6; ++j)
          {
            Eigen::Matrix<double, 6, 1> du = Eigen::Matrix<double, 6, 1>::Zero();
            du[j]                          = step;
            BOOST_REQUIRE(m->set_trial(u + du));
            const Eigen::Matrix<double, 6, 1> plus = m->resisting_force();
            m->revert();
            BOOST_REQUIRE(m->set_trial(u - du));
            const Eigen::Matrix<double, 6, 1> minus = m->resisting_force();
            m->revert();
            numeric.col(j) = (plus - minus) / (2 * step);
          }
        BOOST_TEST((k - numeric).norm() <= 1e-5 * k.norm());
      }
}

BOOST_AUTO_TEST_CASE(load_factor_steps_reach_the_state_of_the_whole_load)
{
  // an elastic member: the load in ten factors ends where the whole load at
  // once does (path independent); revert restores the committed state, the
  // factor included; reset leaves the load at factor 0
  const ElasticSection        section(load_EA, load_EI);
  Eigen::Matrix<double, 6, 1> u;
  u << 0, 0, 0, 1e-4, -3e-3, 2e-3;
  for (const Formulation formulation : {Formulation::force, Formulation::displacement})
    {
      auto stepped = make_member(formulation, Transformation::linear, {0, 0}, {5, 1}, section, 5);
      auto whole   = make_member(formulation, Transformation::linear, {0, 0}, {5, 1}, section, 5);
      for (auto *m : {stepped.get(), whole.get()})
        m->set_uniform_load(self_weight_load(m->transformation(), 7e3));
      for (int step = 1; step <= 10; ++step)
        {
          stepped->set_load_factor(step / 10.0);
          BOOST_REQUIRE(stepped->set_trial(u * step / 10.0));
          stepped->commit();
        }
      whole->set_load_factor(1);
      BOOST_REQUIRE(whole->set_trial(u));
      const double scale = whole->resisting_force().cwiseAbs().maxCoeff();
      BOOST_TEST((stepped->resisting_force() - whole->resisting_force()).cwiseAbs().maxCoeff() <=
                 1e-10 * scale);
      const Eigen::Matrix<double, 6, 1> committed = stepped->resisting_force();
      stepped->set_load_factor(0.3);
      BOOST_REQUIRE(stepped->set_trial(0.5 * u));
      stepped->revert();
      BOOST_TEST((stepped->resisting_force() - committed).cwiseAbs().maxCoeff() == 0);
      stepped->reset();
      BOOST_TEST(stepped->current_load_factor() == 0);
      BOOST_REQUIRE(stepped->set_trial(Eigen::Matrix<double, 6, 1>::Zero()));
      BOOST_TEST(stepped->resisting_force().cwiseAbs().maxCoeff() == 0);
    }
}
