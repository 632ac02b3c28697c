#include <poundfe/base/exceptions.h>
#include <poundfe/base/lean_assert.h>
#include <poundfe/base/numbers.h>
#include <poundfe/elements/uniaxial_element.h>

namespace poundfe
{
  UniaxialElement::UniaxialElement(const ElementKind kind, const unsigned int building,
                                   std::string label, const std::array<int, 2> &equations,
                                   std::unique_ptr<UniaxialLaw> law,
                                   const double                 reference_stiffness,
                                   const std::array<double, 2> &signs)
    : UniaxialElement(kind, building, std::move(label),
                      std::vector<int>{equations[0], equations[1]},
                      std::vector<double>{signs[0], signs[1]}, std::move(law), reference_stiffness)
  {}

  UniaxialElement::UniaxialElement(const ElementKind kind, const unsigned int building,
                                   std::string label, const std::vector<int> &equations,
                                   const std::vector<double>   &coefficients,
                                   std::unique_ptr<UniaxialLaw> law,
                                   const double                 reference_stiffness)
    : NonlinearElement(kind, building, std::move(label), equations)
    , signs(coefficients)
    , reference_stiffness(reference_stiffness)
    , law(std::move(law))
  {
    Assert(this->law, dealii::ExcMessage("a uniaxial element needs a law"));
    AssertDimension(equations.size(), coefficients.size());
    // an index list, not a std::vector<bool> of ground DOFs: local_deformation
    // runs at every Newton iteration, and a bit vector costs shifts and masks
    for (unsigned int i = 0; i < equations.size(); ++i)
      if (equations[i] >= 0)
        free_dofs.push_back(i);
    reset();
  }

  Eigen::MatrixXd
  UniaxialElement::tangent_basis() const
  {
    return Eigen::Map<const Eigen::VectorXd>(signs.data(), signs.size());
  }

  double
  UniaxialElement::local_deformation(const LocalVector &x) const
  {
    double d = 0;
    for (const unsigned int i : free_dofs)
      d += signs[i] * x[i];
    return d;
  }

  double
  UniaxialElement::deformation(const Eigen::VectorXd &u) const
  {
    const std::vector<int> &e = equations();
    if (signs.size() == 2 && free_dofs.size() == 2) // as evaluate's: the same bits
      return (0.0 + signs[0] * u[e[0]]) + signs[1] * u[e[1]];
    double d = 0;
    for (unsigned int i = 0; i < signs.size(); ++i)
      if (e[i] >= 0)
        d += signs[i] * u[e[i]];
    return d;
  }

  bool
  UniaxialElement::set_trial(const LocalVector &u, const LocalVector &v)
  {
    trial_deformation = local_deformation(u);
    trial_rate        = local_deformation(v);
    return law->set_trial(trial_deformation, trial_rate);
  }

  bool
  UniaxialElement::evaluate(const int *equations, const Eigen::VectorXd &u,
                            const Eigen::VectorXd &v, const double damping_factor, double *f,
                            double &d)
  {
    // A two-terminal element between two free DOFs (a gap, a hinge, a storey
    // above the first) takes the same sums unrolled: 0 + s0 u0 + s1 u1 in
    // this order, so the same bits, without the loops' set-up.
    const bool two_free = signs.size() == 2 && free_dofs.size() == 2;
    double     deformation = 0, rate = 0; // as local_deformation of the gathered u and v
    if (two_free)
      {
        const int e0 = equations[0], e1 = equations[1];
        deformation = (0.0 + signs[0] * u[e0]) + signs[1] * u[e1];
        rate        = (0.0 + signs[0] * v[e0]) + signs[1] * v[e1];
      }
    else
      for (const unsigned int i : free_dofs)
        {
          deformation += signs[i] * u[equations[i]];
          rate += signs[i] * v[equations[i]];
        }
    trial_deformation = deformation;
    trial_rate        = rate;
    if (!law->set_trial(deformation, rate))
      return false;
    const double correction = law->force() - reference_stiffness * trial_deformation;
    if (two_free)
      {
        f[0] = signs[0] * correction;
        f[1] = signs[1] * correction;
      }
    else
      for (unsigned int i = 0; i < signs.size(); ++i)
        f[i] = signs[i] * correction;
    d = law->tangent() - reference_stiffness + damping_factor * law->damping_tangent();
    return true;
  }

  std::string
  UniaxialElement::failure() const
  {
    const std::string why = law->failure();
    if (!why.empty())
      return why;
    return "its law refused a deformation of " + number_text(trial_deformation) +
           " (it gave no reason)";
  }

  void
  UniaxialElement::force_correction(LocalVectorOut f) const
  {
    const double correction = law->force() - reference_stiffness * trial_deformation;
    for (unsigned int i = 0; i < signs.size(); ++i)
      f[i] = signs[i] * correction;
  }

  void
  UniaxialElement::tangent_change(const double damping_factor, LocalMatrixOut d) const
  {
    d(0, 0) = law->tangent() - reference_stiffness + damping_factor * law->damping_tangent();
  }

  double
  UniaxialElement::work_increment() const
  {
    return 0.5 * (committed_force + law->force()) * (trial_deformation - committed_deformation);
  }

  double
  UniaxialElement::reference_energy() const
  {
    return 0.5 * reference_stiffness * trial_deformation * trial_deformation;
  }

  void
  UniaxialElement::commit()
  {
    law->commit();
    committed_deformation = trial_deformation;
    committed_force       = law->force();
    committed_rate        = trial_rate;
  }

  void
  UniaxialElement::revert()
  {
    law->revert();
    trial_deformation = committed_deformation;
    trial_rate        = committed_rate;
  }

  void
  UniaxialElement::reset()
  {
    law->reset();
    committed_deformation = trial_deformation = trial_rate = committed_rate = 0;
    committed_force                           = law->force();
  }
} // namespace poundfe
