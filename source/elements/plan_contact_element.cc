// The plan contact element of include/poundfe/elements/plan_contact_element.h.
#include <poundfe/elements/plan_contact_element.h>

namespace poundfe
{
  namespace
  {
    /// Where the outlines do not face each other: open by far (m).
    constexpr double far_apart = 1e3;
  }

  PlanContactElement::PlanContactElement(const unsigned int building, std::string label,
                                         std::vector<int> equations,
                                         const PlanContactGeometry &geometry,
                                         std::unique_ptr<ContactLaw> law)
    : PlanGapElement(building, std::move(label), std::move(equations), std::move(law))
    , geometry(geometry)
  {
    reset();
  }

  bool
  PlanContactElement::set_trial(const LocalVector &u, const LocalVector &v)
  {
    state    = plan_contact_state(geometry, u);
    velocity = v;
    if (!state.defined)
      {
        state.gap = far_apart;
        state.gradient.setZero();
        state.hessian.setZero();
      }
    return law->set_trial(-state.gap, -state.gradient.dot(velocity));
  }

  void
  PlanContactElement::force_correction(LocalVectorOut f) const
  {
    f = -law->force() * state.gradient;
  }

  void
  PlanContactElement::tangent_change(const double damping_factor, LocalMatrixOut d) const
  {
    gap_tangent(damping_factor, state.gradient, state.hessian, velocity, d);
  }

  double
  PlanContactElement::deformation(const Eigen::VectorXd &x) const
  {
    double rate = 0;
    for (unsigned int i = 0; i < 6; ++i)
      if (equations()[i] >= 0)
        rate -= state.gradient[i] * x[equations()[i]];
    return rate;
  }

  double
  PlanGapElement::work_increment() const
  {
    return 0.5 * (committed_force + law->force()) *
           (law->history_variable() - committed_penetration);
  }

  void
  PlanGapElement::commit_law()
  {
    law->commit();
    committed_penetration = law->history_variable();
    committed_force       = law->force();
  }

  void
  PlanContactElement::commit()
  {
    commit_law();
    committed_state = state;
  }

  void
  PlanContactElement::revert()
  {
    law->revert();
    state = committed_state;
  }

  void
  PlanContactElement::reset()
  {
    law->reset();
    velocity.setZero();
    set_trial(Vector6::Zero(), velocity); // the penetration at rest: -(the gap)
    commit();
  }
} // namespace poundfe
