// A nonlinear element acting on one deformation measure
//   d = s0 u[e0] + s1 u[e1] (+ ...)  (an equation < 0 is the ground),
// two-terminal (hinges, storeys, gaps) or on any number of DOFs (a resisting
// plane of a 3D shear building: d = a · (q_bottom, q_top)),
// with a history-dependent law F(d, d_dot). Its contribution to the
// equations is b F with b = (s0 at e0, s1 at e1), and its tangent is the
// rank-one term b (dF/dd + c dF/dd_dot) b^T, c = gamma/(beta dt): in the
// terms of elements/nonlinear_element.h, B_e = b and D_e the scalar
// k_t - k_ref + c c_t. The part k_ref b b^T (the law's initial stiffness,
// for hinges and storeys) is assembled into the linear K once; only
// F - k_ref d and the tangent change are evaluated per iteration.
#ifndef poundfe_elements_uniaxial_element_h
#define poundfe_elements_uniaxial_element_h

#include <poundfe/elements/nonlinear_element.h>
#include <poundfe/laws/uniaxial_law.h>

#include <array>
#include <memory>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <vector>

namespace poundfe
{
  class UniaxialElement final : public NonlinearElement
  {
  public:
    /// `reference_stiffness`: k_ref, the part of the law's stiffness that is
    /// in the linear K.
    UniaxialElement(ElementKind kind, unsigned int building, std::string label,
                    const std::array<int, 2> &equations, std::unique_ptr<UniaxialLaw> law,
                    double reference_stiffness = 0,
                    const std::array<double, 2> &signs = {{1.0, -1.0}});
    /// On any number of DOFs: d = sum_i coefficients[i] u[equations[i]].
    UniaxialElement(ElementKind kind, unsigned int building, std::string label,
                    const std::vector<int> &equations, const std::vector<double> &coefficients,
                    std::unique_ptr<UniaxialLaw> law, double reference_stiffness = 0);

    unsigned int    rank() const override { return 1; }
    Eigen::MatrixXd tangent_basis() const override;
    bool            has_symmetric_tangent() const override { return true; }

    void   set_trial_time(double time) override { law->set_trial_time(time); }
    bool   set_trial(const LocalVector &u, const LocalVector &v) override;
    void   force_correction(LocalVectorOut f) const override;
    void   tangent_change(double damping_factor, LocalMatrixOut d) const override;
    double work_increment() const override;
    double reference_energy() const override;
    double supplied_work_increment() const override { return law->supplied_work_increment(); }
    bool   dissipates() const override { return law->dissipates(); }
    void   commit() override;
    void   revert() override;
    void   reset() override;
    /// The law's reason, or the deformation it refused when it gives none.
    std::string failure() const override;
    bool   is_active() const override { return law->is_active(); }
    bool   was_active() const override { return law->was_active(); }
    int    phase() const override { return law->phase(); }
    int    committed_phase() const override { return law->committed_phase(); }
    double contact_duration(const double closing_rate) const override
    {
      return law->contact_duration(closing_rate);
    }

    /// set_trial, force_correction and tangent_change in one call that is
    /// not virtual (the integrator's loop over its uniaxial elements: no
    /// virtual call per element per iteration but the law's): the local
    /// DOFs read from the global u and v through `equations` (those of
    /// equations(), -1 the ground), f_e - K_ref,e u_e into f (n_dofs()
    /// entries), D_e into d. The same operations in the same order as the
    /// three calls, so the same bits. False as set_trial.
    bool evaluate(const int *equations, const Eigen::VectorXd &u, const Eigen::VectorXd &v,
                  double damping_factor, double *f, double &d);

    double force() const override { return law->force(); }
    double deformation(const Eigen::VectorXd &u) const override;
    double history_variable() const override { return law->history_variable(); }
    double stored_energy() const override { return law->stored_energy(); }
    double yield_deformation() const override { return law->yield_deformation(); }
    double initial_stiffness() const override { return law->initial_stiffness(); }

    /// The deformation and its rate at the last trial state (set_trial or
    /// evaluate; after revert, the committed deformation and rate): once
    /// Newton has converged, deformation(u) and deformation(v) of the accepted
    /// state, the same sums in the same order and so the same bits, not formed again.
    double trial_deformation_value() const { return trial_deformation; }
    double trial_rate_value() const { return trial_rate; }
    /// The law through the final class: calls on it are the law's only.
    const UniaxialLaw &uniaxial_law() const { return *law; }

  private:
    /// b^T x of a local vector (ground DOFs skipped, as in deformation()).
    double local_deformation(const LocalVector &x) const;

    std::vector<double>          signs; // the coefficients of d
    double                       reference_stiffness;
    std::unique_ptr<UniaxialLaw> law;
    std::vector<unsigned int>    free_dofs; // local DOFs whose equation >= 0, in order
    // For the work of a step: the committed deformation and force, the trial deformation.
    double committed_deformation = 0, committed_force = 0, trial_deformation = 0;
    // of the last set_trial or evaluate, and of the last commit (revert restores it)
    double trial_rate = 0, committed_rate = 0;
  };

  /// `element` as the UniaxialElement it is, else null (const kept): a
  /// comparison of type_info, cheaper than a dynamic_cast and the same answer,
  /// the class being final. For the lists of the per-step and per-iteration
  /// loops, which then call through the final class: the law's virtual call
  /// only, not the element's and then the law's; the same functions, so the
  /// same bits.
  template <typename Element>
  auto *
  as_uniaxial(Element &element)
  {
    static_assert(std::is_base_of_v<NonlinearElement, std::remove_const_t<Element>>);
    using Uniaxial =
      std::conditional_t<std::is_const_v<Element>, const UniaxialElement, UniaxialElement>;
    return typeid(element) == typeid(UniaxialElement) ? static_cast<Uniaxial *>(&element) :
                                                        nullptr;
  }
} // namespace poundfe

#endif
