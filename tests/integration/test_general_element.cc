// The general element path (elements/nonlinear_element.h) with an element
// no uniaxial element can represent: two DOFs and a rank-two tangent change
// that is nonsymmetric in its stiffness and in its damping,
//   f = K_c u + c3 (u_1 - u_2)^3 (1, -1)^T + C_c u',
//   K_c = [[k, q], [-q, k]]  (q: a circulatory, follower-type coupling),
//   C_c = [[c, 0], [c', c]],
// with K_ref = 0, B_e = I_2 and
//   D_e = K_c + 3 c3 (u_1 - u_2)^2 [[1, -1], [-1, 1]] + gamma/(beta dt) C_c.
// Two of them (one with a DOF on the ground) act on a three-storey shear
// building with Bouc-Wen storeys, so ranks 1 and 2 are mixed. Checks: the
// Woodbury step against Newton with a dense LU of the integrator's tangent;
// the two tangent updates give the same trajectory and the same Newton
// iterations; the global tangent against central differences.
#include <poundfe/input/engine_parameters.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/integration/newmark.h>
#include <poundfe/model/parameters.h>

#include <Eigen/Dense>

#include <boost/test/unit_test.hpp>

#include <cmath>

#include "test_utilities.h"

using namespace poundfe;

namespace
{
  class CoupledSpring : public NonlinearElement
  {
  public:
    CoupledSpring(std::vector<int> equations, const double k, const double q, const double c3,
                  const double c, const double c_cross)
      : NonlinearElement(ElementKind::storey, 0, "coupled", std::move(equations))
      , c3(c3)
    {
      stiffness << k, q, -q, k;
      damping << c, 0, c_cross, c;
      reset();
    }

    unsigned int    rank() const override { return 2; }
    Eigen::MatrixXd tangent_basis() const override { return Eigen::MatrixXd::Identity(2, 2); }
    bool            has_symmetric_tangent() const override { return false; }

    bool set_trial(const LocalVector &u, const LocalVector &v) override
    {
      trial_u = u;
      trial_v = v;
      return true;
    }
    void force_correction(LocalVectorOut f) const override { f = force_of(trial_u, trial_v); }
    void tangent_change(const double damping_factor, LocalMatrixOut d) const override
    {
      const double    s = 3 * c3 * std::pow(trial_u[0] - trial_u[1], 2);
      Eigen::Matrix2d cubic;
      cubic << s, -s, -s, s;
      d = stiffness + cubic + damping_factor * damping;
    }
    double work_increment() const override
    {
      return 0.5 * (committed_f + force_of(trial_u, trial_v)).dot(trial_u - committed_u);
    }
    double reference_energy() const override { return 0; }
    void   commit() override
    {
      committed_u = trial_u;
      committed_v = trial_v;
      committed_f = force_of(trial_u, trial_v);
    }
    void revert() override
    {
      trial_u = committed_u;
      trial_v = committed_v;
    }
    void reset() override
    {
      committed_u = committed_v = committed_f = Eigen::Vector2d::Zero();
      revert();
    }

    double force() const override { return force_of(trial_u, trial_v)[0]; }
    double deformation(const Eigen::VectorXd &u) const override
    {
      return (equations()[0] >= 0 ? u[equations()[0]] : 0.0) -
             (equations()[1] >= 0 ? u[equations()[1]] : 0.0);
    }
    double stored_energy() const override
    {
      // the symmetric, conservative part; the circulatory q and C_c do work
      return 0.5 * stiffness(0, 0) * trial_u.squaredNorm() +
             0.25 * c3 * std::pow(trial_u[0] - trial_u[1], 4);
    }

  private:
    Eigen::Vector2d force_of(const Eigen::Vector2d &u, const Eigen::Vector2d &v) const
    {
      const double d = u[0] - u[1];
      return stiffness * u + c3 * d * d * d * Eigen::Vector2d(1, -1) + damping * v;
    }

    Eigen::Matrix2d stiffness, damping;
    double          c3;
    Eigen::Vector2d trial_u, trial_v, committed_u, committed_v, committed_f;
  };

  InputParameters
  building_input(const std::string &tangent_update)
  {
    InputParameters p = poundfe_test::shear_building_input(3, 1e4, 2e7, 0.02);
    p.model.buildings[0].storey_yield_drifts = {0.004};
    p.time_integration.newmark.time_step             = 0.005;
    p.time_integration.newmark.newton.tangent_update =
      tangent_update_names().value(tangent_update);
    return p;
  }

  NonlinearElements
  elements_of(const Analysis &analysis)
  {
    NonlinearElements elements = make_nonlinear_elements(analysis.model); // 3 Bouc-Wen storeys
    elements.emplace_back<CoupledSpring>(std::vector<int>{0, 2}, 4e6, 2e6, 2e10, 2e4, 3e3);
    elements.emplace_back<CoupledSpring>(std::vector<int>{1, -1}, 3e6, -1.5e6, 1e10, 1e4, -5e3);
    return elements;
  }

  /// The input's Newmark settings, with the defaults' Newton settings otherwise.
  NewmarkParameters
  newmark_of(const InputParameters &input)
  {
    NewmarkParameters parameters;
    parameters.time_step             = input.time_integration.newmark.time_step;
    parameters.newton.tangent_update = input.time_integration.newmark.newton.tangent_update;
    return parameters;
  }

  void
  harmonic_load(const double t, Vector &p)
  {
    for (int i = 0; i < p.size(); ++i)
      p[i] = 1.2e5 * (i + 1) * std::sin(18 * t);
  }

  struct History
  {
    std::vector<Vector> u;
    IterationStatistics statistics;
  };

  History
  run(const std::string &tangent_update, const std::string &solver, const unsigned int n_steps)
  {
    const InputParameters input    = building_input(tangent_update);
    const Analysis        analysis = prepare_analysis(input);
    NonlinearElements     elements = elements_of(analysis);
    NewmarkIntegrator integrator(analysis.system, solver, newmark_of(input), &elements);
    BOOST_TEST(tangent_update_names().name(integrator.tangent_update()) == tangent_update);
    Vector load(analysis.system.n_equations());
    harmonic_load(0, load);
    integrator.initialize(load);
    History history;
    for (unsigned int i = 0; i < n_steps; ++i)
      {
        integrator.advance(harmonic_load);
        history.u.push_back(integrator.displacement());
      }
    history.statistics = integrator.statistics();
    return history;
  }
} // namespace

BOOST_AUTO_TEST_CASE(woodbury_step_matches_newton_with_a_dense_lu)
{
  // Advance one step with the Woodbury solves; redo it by Newton on the
  // integrator's residual with a dense LU of its tangent.
  const InputParameters input    = building_input("woodbury");
  const Analysis        analysis = prepare_analysis(input);
  NonlinearElements     elements = elements_of(analysis);
  NewmarkIntegrator     integrator(analysis.system, "eigen-ldlt", newmark_of(input), &elements);
  const unsigned int    n = analysis.system.n_equations();
  Vector                load(n);
  harmonic_load(0, load);
  integrator.initialize(load);
  for (unsigned int i = 0; i < 150; ++i)
    integrator.advance(harmonic_load);
  double z = 0;
  for (unsigned int h = 0; h < 3; ++h)
    z = std::max(z, std::abs(elements[h].history_variable()));
  BOOST_TEST(z > 0.5); // the storeys have yielded

  harmonic_load(151 * input.time_integration.newmark.time_step, load);
  Vector          u = integrator.displacement(), r;
  Eigen::MatrixXd tangent;
  for (unsigned int it = 0; it < 20; ++it)
    {
      integrator.residual_and_tangent(load, u, r, tangent);
      const Vector du = tangent.partialPivLu().solve(r);
      u += du;
      if (du.norm() < 1e-14 * u.norm())
        break;
    }
  integrator.advance(load);
  const double difference = (integrator.displacement() - u).norm() / u.norm();
  BOOST_TEST_MESSAGE("Woodbury step against dense-LU Newton: relative difference " << difference);
  BOOST_TEST(difference < 1e-9);
  // the tangent really is nonsymmetric there
  const double asymmetry = (tangent - tangent.transpose()).norm() / tangent.norm();
  BOOST_TEST_MESSAGE("|T - T^T| / |T| = " << asymmetry);
  BOOST_TEST(asymmetry > 1e-3);
}

BOOST_AUTO_TEST_CASE(woodbury_and_refactorisation_agree_for_a_nonsymmetric_element)
{
  const unsigned int n_steps = 600;
  const History      a       = run("woodbury", "eigen-ldlt", n_steps);
  const History      b       = run("refactorize", "umfpack", n_steps);
  double             worst = 0, scale = 0;
  for (unsigned int i = 0; i < n_steps; ++i)
    {
      worst = std::max(worst, (a.u[i] - b.u[i]).lpNorm<Eigen::Infinity>());
      scale = std::max(scale, a.u[i].lpNorm<Eigen::Infinity>());
    }
  BOOST_TEST_MESSAGE("Woodbury against refactorize: max difference "
                     << worst / scale << " of the peak " << scale << " m; Newton iterations "
                     << a.statistics.iterations << " / " << b.statistics.iterations << " in "
                     << a.statistics.steps << " steps");
  BOOST_TEST(worst < 1e-9 * scale);
  BOOST_TEST(scale > 0.004); // well past the yield drift
  // the same increments: Newton needs the same iterations (quadratic
  // convergence only with the consistent nonsymmetric tangent)
  BOOST_TEST(a.statistics.iterations == b.statistics.iterations);
  BOOST_TEST(double(a.statistics.iterations) / a.statistics.steps < 4.0);
}

BOOST_AUTO_TEST_CASE(refactorising_a_nonsymmetric_tangent_with_ldlt_is_refused)
{
  const InputParameters input    = building_input("refactorize");
  const Analysis        analysis = prepare_analysis(input);
  NonlinearElements     elements = elements_of(analysis);
  BOOST_CHECK_THROW(NewmarkIntegrator(analysis.system, "eigen-ldlt", newmark_of(input), &elements),
                    InputError);
}

BOOST_AUTO_TEST_CASE(global_tangent_of_the_nonsymmetric_element_matches_central_differences)
{
  for (const std::string update : {"woodbury", "refactorize"})
    {
      const InputParameters input    = building_input(update);
      const Analysis        analysis = prepare_analysis(input);
      NonlinearElements     elements = elements_of(analysis);
      NewmarkIntegrator     integrator(analysis.system, "umfpack", newmark_of(input), &elements);
      const unsigned int    n = analysis.system.n_equations();
      Vector                load(n);
      harmonic_load(0, load);
      integrator.initialize(load);
      for (unsigned int i = 0; i < 150; ++i)
        integrator.advance(harmonic_load);
      harmonic_load(151 * input.time_integration.newmark.time_step, load);
      const double worst = poundfe_test::tangent_error_by_central_differences(integrator, load, 5);
      BOOST_TEST_MESSAGE(update << ": worst column error of the tangent " << worst);
      BOOST_TEST(worst < 1e-6);
    }
}
