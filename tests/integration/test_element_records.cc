// ElementRecords::accept (integration/element_records.h) asks each element
// for what it needs once per accepted step: a gap's or friction element's
// rate at the step's end (its log closes the entry with it, and it is the
// committed rate of the next step) and every element's supplied work. An
// element that counts the calls checks it, and that the numbers noted are
// those the element gives.
#include <poundfe/integration/element_records.h>

#include <boost/test/unit_test.hpp>

using namespace poundfe;

namespace
{
  /// One DOF; deformation u_0 scaled by `scale`; counts the calls an
  /// accepted step makes.
  class CountingElement : public NonlinearElement
  {
  public:
    CountingElement(const ElementKind kind, const double scale)
      : NonlinearElement(kind, 0, "counting", {0})
      , scale(scale)
    {}

    unsigned int    rank() const override { return 1; }
    Eigen::MatrixXd tangent_basis() const override { return Eigen::MatrixXd::Ones(1, 1); }
    bool            has_symmetric_tangent() const override { return true; }
    bool set_trial(const LocalVector &, const LocalVector &) override { return true; }
    void force_correction(LocalVectorOut f) const override { f.setZero(); }
    void tangent_change(double, LocalMatrixOut d) const override { d.setZero(); }
    double work_increment() const override { return 0.25; }
    double supplied_work_increment() const override
    {
      ++supplied_calls;
      return 0.5;
    }
    double reference_energy() const override { return 0; }
    void   commit() override {}
    void   revert() override {}
    void   reset() override {}
    double force() const override { return 0; }
    double deformation(const Eigen::VectorXd &u) const override
    {
      ++deformation_calls;
      return scale * u[0];
    }
    double stored_energy() const override { return 0; }

    mutable unsigned int deformation_calls = 0, supplied_calls = 0;

  private:
    double scale;
  };
} // namespace

BOOST_AUTO_TEST_CASE(accept_asks_each_element_once)
{
  NonlinearElements elements;
  auto &gap      = elements.emplace_back<CountingElement>(ElementKind::gap, 2.0);
  auto &friction = elements.emplace_back<CountingElement>(ElementKind::friction, 3.0);
  auto &hinge    = elements.emplace_back<CountingElement>(ElementKind::hinge, 5.0);
  ElementRecords records(&elements);
  records.start(elements);
  for (CountingElement *e : {&gap, &friction, &hinge})
    e->deformation_calls = e->supplied_calls = 0;

  const Eigen::VectorXd v_next = Eigen::VectorXd::Constant(1, 0.125);
  double belt = 0;
  records.accept(elements, 0.0, 0.01, v_next, nullptr, belt);
  for (CountingElement *e : {&gap, &friction, &hinge})
    {
      BOOST_TEST(e->deformation_calls == 1u);
      BOOST_TEST(e->supplied_calls == 1u);
    }
  // the committed rates and the sums are the elements' own numbers
  BOOST_TEST(records.committed_rate(0) == 0.25);
  BOOST_TEST(records.committed_rate(1) == 0.375);
  BOOST_TEST(records.committed_rate(2) == 0.625);
  BOOST_TEST(belt == 1.5);
  for (unsigned int h = 0; h < 3; ++h)
    {
      BOOST_TEST(records.work()[h] == 0.25);
      BOOST_TEST(records.supplied_work()[h] == 0.5);
    }
}
