// A nonlinear element acting on two deformation measures
//   d = (d_1, d_2) = B^T u_e,  d_a = sum_i b_ai u[e_i]  (an equation < 0 is the ground),
// with the bidirectional Bouc-Wen law F(d) (laws/bidirectional_bouc_wen.h):
// a storey's pair of perpendicular resisting planes of a 3D shear building
// (d the drifts along the two planes, B their rows a(C) of
// model/torsional_shear_building.h), or a 3D member end's hinge about its two
// bending axes (d the two relative rotations, B = I). Its contribution to
// the equations is B F and its tangent B K_t B^T (K_t = dF/dd, 2x2 and
// unsymmetric): in the terms of elements/nonlinear_element.h, B_e = B
// (n x 2) and D_e = K_t - K_ref, K_ref = diag(k_1, k_2) the law's initial
// stiffness, which is assembled into the linear K once (as for the uniaxial
// hinges and storeys); only B (F - K_ref d) and D_e are evaluated per
// iteration.
// Scalar outputs (force(), deformation(), history_variable()) are the
// resultants |F|, |d| and |z| (ductility |d| / u_y of the first axis); the
// components are force_component(a).
#ifndef poundfe_elements_biaxial_element_h
#define poundfe_elements_biaxial_element_h

#include <poundfe/elements/nonlinear_element.h>
#include <poundfe/laws/bidirectional_bouc_wen.h>

#include <array>
#include <string>
#include <vector>

namespace poundfe
{
  class BiaxialElement final : public NonlinearElement
  {
  public:
    /// `coefficients[a][i]`: b_ai, the weight of equations[i] in d_a.
    BiaxialElement(ElementKind kind, unsigned int building, std::string label,
                   const std::vector<int>                   &equations,
                   const std::array<std::vector<double>, 2> &coefficients,
                   const BidirectionalBoucWen               &law);

    unsigned int    rank() const override { return 2; }
    Eigen::MatrixXd tangent_basis() const override { return basis; }
    bool            has_symmetric_tangent() const override { return false; }

    bool   set_trial(const LocalVector &u, const LocalVector &v) override;
    void   force_correction(LocalVectorOut f) const override;
    void   tangent_change(double damping_factor, LocalMatrixOut d) const override;
    double work_increment() const override;
    double reference_energy() const override;
    void   commit() override;
    void   revert() override;
    void   reset() override;
    std::string failure() const override { return law.failure(); }

    double force() const override { return law.force().norm(); }
    double deformation(const Eigen::VectorXd &u) const override;
    double history_variable() const override { return law.history().norm(); }
    double stored_energy() const override { return law.stored_energy(); }
    double yield_deformation() const override { return law.yield_deformation(0); }
    double initial_stiffness() const override { return law.initial_stiffness(0); }

    /// F_a, the force (moment) along the a-th deformation.
    double force_component(const unsigned int a) const override { return law.force()[a]; }
    const BidirectionalBoucWen &bidirectional_law() const { return law; }

  private:
    /// B^T x of a local vector (ground DOFs skipped).
    Eigen::Vector2d local_deformation(const LocalVector &x) const;

    Eigen::MatrixXd      basis; // B, n x 2; rows of ground DOFs are 0
    Eigen::Matrix2d      reference_stiffness;
    BidirectionalBoucWen law;
    Eigen::Vector2d      committed_deformation, committed_force, trial_deformation;
  };
} // namespace poundfe

#endif
