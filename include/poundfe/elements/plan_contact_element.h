// Contact between the slab outlines of two floors in plan (Model/Dimension
// = 3): one end of the overlap of two facing edges, a corner of one floor
// against the edge of the other (model/plan_contact_geometry.h gives the gap
// g(q) and its derivatives), with any contact law F(δ, δ') of laws/ on the
// penetration δ = -g:
//   force on the equations   f = -F ∇g
//   tangent                  df/dq + c df/dq' = (k_t + c c_t) ∇g ∇gᵀ
//                                               + c_t ∇g (∇²g q')ᵀ - F ∇²g
// (k_t = dF/dδ, c_t = dF/dδ', c = γ/(β Δt)). The normal turns with the
// floors, so the tangent is not a fixed rank-one term: B_e is the identity
// on the six DOFs (rank 6) and D_e the whole 6 x 6 tangent.
// Source: Wriggers, Computational Contact Mechanics, 2nd ed. (2006), §4.1
// (node-to-segment penalty contact and its linearisation); doc/theory.md §1.13.
#ifndef poundfe_elements_plan_contact_element_h
#define poundfe_elements_plan_contact_element_h

#include <poundfe/elements/nonlinear_element.h>
#include <poundfe/laws/contact_law.h>
#include <poundfe/model/plan_contact_geometry.h>

#include <memory>

namespace poundfe
{
  /// What the contact elements in plan share (this one and elements/
  /// column_contact_element.h): a contact law on the penetration δ = -g(q)
  /// that the derived element measures, the law's state and the work done
  /// on it, and the tangent
  ///   D = (k_t + c c_t) ∇g ∇gᵀ + c_t ∇g (∇²g q')ᵀ - F ∇²g.
  class PlanGapElement : public NonlinearElement
  {
  public:
    PlanGapElement(const unsigned int building, std::string label, std::vector<int> equations,
                   std::unique_ptr<ContactLaw> law)
      : NonlinearElement(ElementKind::gap, building, std::move(label), std::move(equations))
      , law(std::move(law))
    {}

    bool        has_symmetric_tangent() const override { return false; }
    double      work_increment() const override;
    double      reference_energy() const override { return 0; }
    std::string failure() const override { return law->failure(); }
    bool        is_active() const override { return law->is_active(); }
    bool        was_active() const override { return law->was_active(); }
    double      contact_duration(const double closing_rate) const override
    {
      return law->contact_duration(closing_rate);
    }
    double force() const override { return law->force(); }
    double history_variable() const override { return law->history_variable(); }
    /// The contact force on the gap's first body in plan at the trial state,
    /// F dg/du_1 (N, site axes): along the normal, opening the gap (zero
    /// while open); the second body gets its opposite at the same point.
    virtual std::array<double, 2> force_on_first() const = 0;
    /// Whether the trial state has a contact point (the edges overlap, the
    /// column point lies along the slab's edge); else contact_point() is
    /// meaningless and the gap open.
    virtual bool in_reach() const = 0;
    double stored_energy() const override { return law->stored_energy(); }
    bool   dissipates() const override { return law->dissipates(); }

  protected:
    /// Commit the law and remember its penetration and force.
    void commit_law();

    template <typename Vector, typename Matrix>
    void
    gap_tangent(const double damping_factor, const Vector &gradient, const Matrix &hessian,
                const Vector &velocity, LocalMatrixOut d) const
    {
      const double k = law->tangent(), c = law->damping_tangent();
      d              = (k + damping_factor * c) * gradient * gradient.transpose() +
          c * gradient * (hessian * velocity).transpose() - law->force() * hessian;
    }

    std::unique_ptr<ContactLaw> law;

  private:
    double committed_penetration = 0, committed_force = 0;
  };

  class PlanContactElement final : public PlanGapElement
  {
  public:
    /// `equations`: (ux, uy, θz) of floor 1, then of floor 2.
    PlanContactElement(unsigned int building, std::string label, std::vector<int> equations,
                       const PlanContactGeometry &geometry, std::unique_ptr<ContactLaw> law);

    unsigned int    rank() const override { return 6; }
    Eigen::MatrixXd tangent_basis() const override { return Eigen::MatrixXd::Identity(6, 6); }

    bool   set_trial(const LocalVector &u, const LocalVector &v) override;
    void   force_correction(LocalVectorOut f) const override;
    void   tangent_change(double damping_factor, LocalMatrixOut d) const override;
    void   commit() override;
    void   revert() override;
    void   reset() override;

    /// The rate of penetration -∇g · x for a global velocity x (linearised
    /// at the trial state, as the integrator's event and impact logic needs).
    double deformation(const Eigen::VectorXd &x) const override;
    /// The contact point (the corner) at the trial state.
    std::array<double, 2> contact_point() const override
    {
      return {{state.point.x, state.point.y}};
    }
    std::array<double, 2> force_on_first() const override
    {
      return {{law->force() * state.gradient[0], law->force() * state.gradient[1]}};
    }
    bool in_reach() const override { return state.defined; }

  private:
    PlanContactGeometry geometry;
    PlanContactState    state, committed_state;
    Vector6             velocity = Vector6::Zero();
  };
} // namespace poundfe

#endif
