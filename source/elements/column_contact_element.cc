// The floor-to-column contact element of
// include/poundfe/elements/column_contact_element.h.
#include <poundfe/base/lean_assert.h>
#include <poundfe/elements/column_contact_element.h>

namespace poundfe
{
  namespace
  {
    /// Where the column is beyond the slab's edge: open by far (m).
    constexpr double column_far_apart = 1e3;
  }

  ColumnContactElement::ColumnContactElement(const unsigned int building, std::string label,
                                             std::vector<int> equations,
                                             const ColumnContactGeometry &geometry,
                                             std::unique_ptr<ContactLaw> law)
    : PlanGapElement(building, std::move(label), std::move(equations), std::move(law))
    , geometry(geometry)
  {
    const unsigned int n_column = geometry.column_dofs.size();
    AssertDimension(n_dofs(), n_column + 3);
    AssertDimension(geometry.weights.size(), 2 * n_column);
    basis = Eigen::MatrixXd::Zero(n_column + 3, 5);
    for (unsigned int r = 0; r < 2; ++r)
      for (unsigned int j = 0; j < n_column; ++j)
        basis(j, r) = geometry.weights[r * n_column + j];
    basis.bottomRightCorner<3, 3>().setIdentity();
    reset();
  }

  bool
  ColumnContactElement::set_trial(const LocalVector &u, const LocalVector &v)
  {
    state    = column_contact_state(geometry, basis.transpose() * u);
    velocity = basis.transpose() * v;
    if (!state.defined)
      {
        state.gap = column_far_apart;
        state.gradient.setZero();
        state.hessian.setZero();
      }
    return law->set_trial(-state.gap, -state.gradient.dot(velocity));
  }

  void
  ColumnContactElement::force_correction(LocalVectorOut f) const
  {
    f = -law->force() * (basis * state.gradient);
  }

  void
  ColumnContactElement::tangent_change(const double damping_factor, LocalMatrixOut d) const
  {
    gap_tangent(damping_factor, state.gradient, state.hessian, velocity, d);
  }

  double
  ColumnContactElement::deformation(const Eigen::VectorXd &x) const
  {
    const Eigen::VectorXd gradient = basis * state.gradient;
    double                rate     = 0;
    for (unsigned int i = 0; i < n_dofs(); ++i)
      if (equations()[i] >= 0)
        rate -= gradient[i] * x[equations()[i]];
    return rate;
  }

  void
  ColumnContactElement::commit()
  {
    commit_law();
    committed_state = state;
  }

  void
  ColumnContactElement::revert()
  {
    law->revert();
    state = committed_state;
  }

  void
  ColumnContactElement::reset()
  {
    law->reset();
    velocity.setZero();
    const Eigen::VectorXd rest = Eigen::VectorXd::Zero(n_dofs());
    set_trial(rest, rest); // the penetration at rest: -(the gap)
    commit();
  }
} // namespace poundfe
