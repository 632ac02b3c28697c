// A two-terminal nonlinear element acting on one deformation measure
//   d = s0 u[e0] + s1 u[e1]        (an equation < 0 is the ground),
// with a history-dependent law F(d, d_dot). Its contribution to the
// equations is b F with b = (s0 at e0, s1 at e1), and its tangent is the
// rank-one term b (dF/dd + gamma/(beta dt) dF/dd_dot) b^T. The part
// k_ref b b^T (the law's initial stiffness, for hinges and storeys) is
// assembled into the linear K once; only F - k_ref d and the tangent change
// k_t - k_ref are evaluated per iteration.
#ifndef poundfe_elements_uniaxial_element_h
#define poundfe_elements_uniaxial_element_h

#include <poundfe/laws/uniaxial_law.h>

#include <Eigen/Core>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  enum class ElementKind
  {
    hinge,  // moment-rotation at a member end
    storey, // force-drift of a shear-building storey
    gap     // contact
  };

  struct UniaxialElement
  {
    ElementKind                  kind     = ElementKind::hinge;
    unsigned int                 building = 0;
    std::string                  label;
    std::array<int, 2>           equations{{-1, -1}};
    std::array<double, 2>        signs{{1.0, -1.0}};
    double                       reference_stiffness = 0; // in the linear K
    std::unique_ptr<UniaxialLaw> law;

    template <typename VectorType>
    double
    deformation(const VectorType &u) const
    {
      double d = 0;
      for (unsigned int i = 0; i < 2; ++i)
        if (equations[i] >= 0)
          d += signs[i] * u[equations[i]];
      return d;
    }

    // What observers and outputs read (the law's trial state, which is the
    // committed state between steps).
    double force() const { return law->force(); }
    double history_variable() const { return law->history_variable(); }
    double stored_energy() const { return law->stored_energy(); }
    double yield_deformation() const { return law->yield_deformation(); }
    double initial_stiffness() const { return law->initial_stiffness(); }
  };

  using UniaxialElements = std::vector<UniaxialElement>;
} // namespace poundfe

#endif
