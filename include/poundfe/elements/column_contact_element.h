// Contact between the slab edge of one building and a column of a 3D frame
// neighbour between its floors (Model/Dimension = 3; model/
// column_contact_geometry.h gives the gap g(z) and its derivatives in
// z = (w_x, w_y, ux, uy, θz): the column's plan displacement at the slab's
// height, w = W u_c, and the slab's motion), with any contact law F(δ, δ')
// on the penetration δ = -g:
//   z = Bᵀ u_e,  B = [Wᵀ 0; 0 I_3]  ((n_c + 3) x 5, constant)
//   force on the equations   f = -F B ∇g
//   tangent                  B D Bᵀ, D = (k_t + c c_t) ∇g ∇gᵀ
//                                        + c_t ∇g (∇²g z')ᵀ - F ∇²g
// (k_t = dF/dδ, c_t = dF/dδ', c = γ/(β Δt)): rank 5 whatever the number of
// column DOFs, and the force on the column is the consistent nodal load of
// the point load (doc/theory.md §1.13).
// Source: Wriggers, Computational Contact Mechanics, 2nd ed. (2006), §4.1.
#ifndef poundfe_elements_column_contact_element_h
#define poundfe_elements_column_contact_element_h

#include <poundfe/elements/plan_contact_element.h>
#include <poundfe/model/column_contact_geometry.h>

#include <memory>

namespace poundfe
{
  class ColumnContactElement final : public PlanGapElement
  {
  public:
    /// `equations`: the column's DOFs (geometry.column_dofs' equations),
    /// then (ux, uy, θz) of the slab's floor.
    ColumnContactElement(unsigned int building, std::string label, std::vector<int> equations,
                         const ColumnContactGeometry &geometry, std::unique_ptr<ContactLaw> law);

    unsigned int    rank() const override { return 5; }
    Eigen::MatrixXd tangent_basis() const override { return basis; }

    bool set_trial(const LocalVector &u, const LocalVector &v) override;
    void force_correction(LocalVectorOut f) const override;
    void tangent_change(double damping_factor, LocalMatrixOut d) const override;
    void commit() override;
    void revert() override;
    void reset() override;

    /// The rate of penetration -∇g · Bᵀ x for a global velocity x.
    double deformation(const Eigen::VectorXd &x) const override;
    /// The column point at the trial state.
    std::array<double, 2> contact_point() const override
    {
      return {{state.point.x, state.point.y}};
    }
    /// On the column (z's first two entries are its plan motion w).
    std::array<double, 2> force_on_first() const override
    {
      return {{law->force() * state.gradient[0], law->force() * state.gradient[1]}};
    }
    bool in_reach() const override { return state.defined; }

  private:
    ColumnContactGeometry geometry;
    Eigen::MatrixXd       basis; // B
    ColumnContactState    state, committed_state;
    Vector5               velocity = Vector5::Zero(); // z'
  };
} // namespace poundfe

#endif
