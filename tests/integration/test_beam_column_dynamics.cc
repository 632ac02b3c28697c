// Beam-columns in the Newmark-Newton integrator through their
// NonlinearElement adapter: a cantilever column (one force-based element,
// its tip's sway on the first floor of a three-storey shear building, its
// other DOFs on the ground) with K_ref = 0, so the whole force goes
// through the correction. Elastic: the trajectory of the building whose
// first storey is stiffer by the column's 12EI/h^3; yielding: the Woodbury
// and refactorising tangent updates give one trajectory, linear (rank 3)
// and corotational (rank 6).
#include <poundfe/input/engine_parameters.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/elements/member_element.h>
#include <poundfe/integration/newmark.h>
#include <poundfe/laws/material_registry.h>
#include <poundfe/sections/aggregator_section.h>
#include <poundfe/sections/elastic_section.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

#include "test_utilities.h"

using namespace poundfe;

namespace
{
  constexpr double column_h = 3, column_ei = 1e7 * column_h * column_h * column_h / 12,
                   column_k = 1e7; // 12 EI/h^3

  InputParameters
  storeys_input(const std::vector<double> &stiffnesses)
  {
    InputParameters p = poundfe_test::shear_building_input(3, 1e4, 2e7, 0);
    p.model.buildings[0].storey_stiffnesses = stiffnesses;
    p.time_integration.newmark.time_step   = 0.005;
    return p;
  }

  void
  column_load(const double t, Vector &p)
  {
    for (int i = 0; i < p.size(); ++i)
      p[i] = 1.5e5 * (i + 1) * std::sin(15 * t);
  }

  /// The floors' displacements over n steps, with the column when given.
  std::vector<Vector>
  trajectory(const InputParameters &input, const SectionLaw *section, const Transformation kind,
             const TangentUpdate update, const unsigned int n_steps)
  {
    const Analysis    analysis = prepare_analysis(input);
    NonlinearElements elements;
    if (section)
      elements.emplace_back<MemberElement<2>>(
        0, "column", std::vector<int>{-1, -1, -1, 0, -1, -1},
        std::make_unique<ForceBeamColumn<2>>(
          CrdTransformation<2>(kind, Eigen::Vector2d(0, 0), Eigen::Vector2d(0, column_h)),
          *section, 5),
        ReferenceStiffness::none);
    NewmarkParameters parameters;
    parameters.time_step             = input.time_integration.newmark.time_step;
    parameters.newton.tangent_update = update;
    NewmarkIntegrator integrator(analysis.system, "eigen-ldlt", parameters,
                                 elements.empty() ? nullptr : &elements);
    Vector load(analysis.system.n_equations());
    column_load(0, load);
    integrator.initialize(load);
    std::vector<Vector> u;
    for (unsigned int i = 0; i < n_steps; ++i)
      {
        integrator.advance(column_load);
        u.push_back(integrator.displacement());
      }
    return u;
  }

  double
  largest_difference(const std::vector<Vector> &a, const std::vector<Vector> &b)
  {
    double difference = 0, scale = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        difference = std::max(difference, (a[i] - b[i]).lpNorm<Eigen::Infinity>());
        scale      = std::max(scale, b[i].lpNorm<Eigen::Infinity>());
      }
    return difference / scale;
  }
} // namespace

BOOST_AUTO_TEST_CASE(an_elastic_column_adds_its_sway_stiffness)
{
  const ElasticSection section(1e12, column_ei);
  const auto with_column = trajectory(storeys_input({2e7}), &section, Transformation::linear,
                                      TangentUpdate::woodbury, 300);
  const auto reference   = trajectory(storeys_input({2e7 + column_k, 2e7, 2e7}), nullptr,
                                      Transformation::linear, TangentUpdate::woodbury, 300);
  const double difference = largest_difference(with_column, reference);
  BOOST_TEST_MESSAGE("elastic column against the stiffer storey: " << difference);
  BOOST_TEST(difference < 1e-8);
  // and the column is not nothing
  const auto without = trajectory(storeys_input({2e7}), nullptr, Transformation::linear,
                                  TangentUpdate::woodbury, 300);
  BOOST_TEST(largest_difference(without, reference) > 0.05);
}

BOOST_AUTO_TEST_CASE(a_yielding_column_steps_alike_with_both_tangent_updates)
{
  SectionVector rigidities(2);
  rigidities << 1e12, column_ei;
  AggregatorSection section(rigidities);
  // yields at a first-floor drift of about 5 mm
  const double my = 0.5 * column_k * 0.005 * column_h;
  section.set_law(1, [=] {
    return make_material({"Steel01", {{"fy", my}, {"E0", column_ei}, {"b", 0.02}}});
  });
  for (const Transformation kind : {Transformation::linear, Transformation::corotational})
    {
      const auto woodbury = trajectory(storeys_input({2e7}), &section, kind,
                                       TangentUpdate::woodbury, 300);
      const auto refactorized = trajectory(storeys_input({2e7}), &section, kind,
                                           TangentUpdate::refactorize, 300);
      const double difference = largest_difference(woodbury, refactorized);
      double       peak       = 0;
      for (const Vector &u : woodbury)
        peak = std::max(peak, std::abs(u[0]));
      BOOST_TEST_MESSAGE("kind " << int(kind) << ": Woodbury against refactorised "
                                 << difference << ", peak first-floor drift " << peak);
      BOOST_TEST(peak > 0.01); // past yield
      BOOST_TEST(difference < 1e-7);
    }
}
