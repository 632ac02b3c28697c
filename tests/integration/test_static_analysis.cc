// Static analyses (integration/static_analysis.h) on two springs in series:
// a softening spring F(u1) = k u1 exp(-u1 / u0) from the ground to DOF 1 and
// a linear one k2 from DOF 1 to DOF 2, loaded by lambda at DOF 2. On the
// equilibrium path lambda = F(u1), u2 = u1 + lambda / k2: with k2 < k / e^2
// u2 turns back (a snap-back), which arc length follows and displacement
// control of u2 cannot. And load control of a linear system in one step.
#include <poundfe/integration/static_analysis.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <memory>

using namespace poundfe;

namespace
{
  constexpr double k_soft = 1.0, u_soft = 1.0, k_series = 0.05;

  /// F(u) = k u exp(-u / u0) on one DOF against the ground, K_ref = 0.
  class SofteningSpring : public NonlinearElement
  {
  public:
    SofteningSpring()
      : NonlinearElement(ElementKind::spring, 0, "softening", {0})
    {}
    unsigned int    rank() const override { return 1; }
    Eigen::MatrixXd tangent_basis() const override { return Eigen::MatrixXd::Ones(1, 1); }
    bool            has_symmetric_tangent() const override { return true; }
    bool set_trial(const LocalVector &u, const LocalVector &) override
    {
      trial = u[0];
      return true;
    }
    void force_correction(LocalVectorOut f) const override { f[0] = force(); }
    void tangent_change(double, LocalMatrixOut d) const override
    {
      d(0, 0) = k_soft * (1 - trial / u_soft) * std::exp(-trial / u_soft);
    }
    double work_increment() const override { return 0; }
    double reference_energy() const override { return 0; }
    void   commit() override { committed = trial; }
    void   revert() override { trial = committed; }
    void   reset() override { trial = committed = 0; }
    double force() const override { return k_soft * trial * std::exp(-trial / u_soft); }
    double deformation(const Eigen::VectorXd &u) const override { return u[0]; }
    double stored_energy() const override { return 0; }

  private:
    double trial = 0, committed = 0;
  };

  SparseMatrix
  series_stiffness()
  {
    SparseMatrix k(2, 2);
    k.insert(0, 0) = k.insert(1, 1) = k_series;
    k.insert(0, 1) = k.insert(1, 0) = -k_series;
    return k;
  }
} // namespace

BOOST_AUTO_TEST_SUITE(static_analysis)

// Arc length from rest: every point on the analytic path to 1e-8, through
// the peak of lambda (u1 = 1) and the snap-back of u2 (u1 from about 1.5
// to 3.9, where du2/du1 = 1 + (k / k2)(1 - u1) exp(-u1) < 0).
BOOST_AUTO_TEST_CASE(arc_length_follows_a_snap_back)
{
  const SparseMatrix K = series_stiffness();
  NonlinearElements  elements;
  elements.emplace_back<SofteningSpring>();
  StaticSolver solver(K, &elements);
  const Vector constant = Vector::Zero(2), reference = (Vector(2) << 0, 1).finished();
  PathFollower follower(solver, constant, reference, PathSettings{1e-12, 30});
  PathPoint    point;
  point.u = Vector::Zero(2);
  unsigned int backwards = 0;
  double       previous_u2 = 0;
  for (unsigned int step = 0; step < 400 && point.u[0] < 6; ++step)
    {
      BOOST_REQUIRE(follower.arc_length_step(0.25, 1, 1.0, point));
      const double u1 = point.u[0], lambda = k_soft * u1 * std::exp(-u1 / u_soft);
      BOOST_TEST(point.lambda == lambda, boost::test_tools::tolerance(1e-8));
      BOOST_TEST(std::abs(point.u[1] - (u1 + lambda / k_series)) <= 1e-8 * (1 + point.u[1]));
      backwards += point.u[1] < previous_u2;
      previous_u2 = point.u[1];
    }
  BOOST_TEST(point.u[0] >= 6); // past the snap-back, on the descending branch
  BOOST_TEST(backwards >= 3);
}

// Displacement control of u2 in the same steps cannot stay on the path
// past the turning point of u2 (u2 = 8.16 at u1 = 1.49): either a step fails
// or u1 jumps across the snap-back in one step (to the far branch).
BOOST_AUTO_TEST_CASE(displacement_control_cannot_pass_the_snap_back)
{
  const SparseMatrix K = series_stiffness();
  NonlinearElements  elements;
  elements.emplace_back<SofteningSpring>();
  StaticSolver solver(K, &elements);
  const Vector constant = Vector::Zero(2), reference = (Vector(2) << 0, 1).finished();
  PathFollower follower(solver, constant, reference, PathSettings{1e-12, 30});
  PathPoint    point;
  point.u        = Vector::Zero(2);
  bool traced    = true;
  for (unsigned int step = 0; step < 60 && traced; ++step)
    {
      const double before = point.u[0];
      traced = follower.displacement_step(1, 0.25, point) && point.u[0] - before < 0.5;
    }
  BOOST_TEST(!traced);
}

// Load control of a linear system: u = K^-1 p at every load step.
BOOST_AUTO_TEST_CASE(load_control_of_a_linear_system)
{
  SparseMatrix K(2, 2);
  K.insert(0, 0) = 3;
  K.insert(1, 1) = 2;
  K.insert(0, 1) = K.insert(1, 0) = -1;
  StaticSolver      solver(K, nullptr);
  const Vector      p = (Vector(2) << 1, 2).finished();
  StaticState       state;
  LoadControlSettings settings;
  settings.n_steps = 3;
  load_control(solver, p, 0, 1, settings, "test", state);
  BOOST_REQUIRE_EQUAL(state.path.size(), 3u);
  const Vector exact = Eigen::MatrixXd(K).lu().solve(p);
  BOOST_TEST((state.displacement - exact).norm() <= 1e-14 * exact.norm());
  BOOST_TEST((state.path[0] - exact / 3).norm() <= 1e-14 * exact.norm());
}

BOOST_AUTO_TEST_SUITE_END()
