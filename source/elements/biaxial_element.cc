// A two-deformation element around the bidirectional Bouc-Wen law
// (include/poundfe/elements/biaxial_element.h; doc/theory.md §2).
#include <poundfe/base/lean_assert.h>
#include <poundfe/elements/biaxial_element.h>

namespace poundfe
{
  BiaxialElement::BiaxialElement(const ElementKind kind, const unsigned int building,
                                 std::string label, const std::vector<int> &equations,
                                 const std::array<std::vector<double>, 2> &coefficients,
                                 const BidirectionalBoucWen               &law)
    : NonlinearElement(kind, building, std::move(label), equations)
    , basis(Eigen::MatrixXd::Zero(equations.size(), 2))
    , law(law)
  {
    for (unsigned int a = 0; a < 2; ++a)
      {
        AssertDimension(coefficients[a].size(), equations.size());
        for (unsigned int i = 0; i < equations.size(); ++i)
          if (equations[i] >= 0)
            basis(i, a) = coefficients[a][i];
      }
    reference_stiffness = Eigen::Vector2d(law.initial_stiffness(0), law.initial_stiffness(1))
                            .asDiagonal();
    reset();
  }

  Eigen::Vector2d
  BiaxialElement::local_deformation(const LocalVector &x) const
  {
    return basis.transpose() * x; // ground rows of B are 0
  }

  double
  BiaxialElement::deformation(const Eigen::VectorXd &u) const
  {
    Eigen::Vector2d d = Eigen::Vector2d::Zero();
    for (unsigned int i = 0; i < n_dofs(); ++i)
      if (equations()[i] >= 0)
        d += basis.row(i).transpose() * u[equations()[i]];
    return d.norm();
  }

  bool
  BiaxialElement::set_trial(const LocalVector &u, const LocalVector & /*v*/)
  {
    trial_deformation = local_deformation(u);
    return law.set_trial(trial_deformation);
  }

  void
  BiaxialElement::force_correction(LocalVectorOut f) const
  {
    f = basis * (law.force() - reference_stiffness * trial_deformation);
  }

  void
  BiaxialElement::tangent_change(const double /*damping_factor*/, LocalMatrixOut d) const
  {
    d = law.tangent() - reference_stiffness;
  }

  double
  BiaxialElement::work_increment() const
  {
    return 0.5 * (committed_force + law.force()).dot(trial_deformation - committed_deformation);
  }

  double
  BiaxialElement::reference_energy() const
  {
    return 0.5 * trial_deformation.dot(reference_stiffness * trial_deformation);
  }

  void
  BiaxialElement::commit()
  {
    law.commit();
    committed_deformation = trial_deformation;
    committed_force       = law.force();
  }

  void
  BiaxialElement::revert()
  {
    law.revert();
    trial_deformation = committed_deformation;
  }

  void
  BiaxialElement::reset()
  {
    law.reset();
    committed_deformation = trial_deformation = Eigen::Vector2d::Zero();
    committed_force                           = law.force();
  }
} // namespace poundfe
