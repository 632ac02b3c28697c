// The settings of Moreau–Jean's rigid-contact stepper
// (integration/moreau_jean.h), apart from its class so that the input's
// parameters need not see the stepper.
#ifndef poundfe_integration_moreau_jean_parameters_h
#define poundfe_integration_moreau_jean_parameters_h

#include <poundfe/integration/lcp_solver.h>

#include <string>

namespace poundfe
{
  struct MoreauJeanParameters
  {
    double       time_step = 0.001;
    double       theta     = 0.5;
    LcpOptions   lcp;
    /// Coulomb's coefficient of the contacts in plan (Contact/Friction
    /// coefficient; copied to each contact), and with it the solver of the
    /// friction-contact problem.
    double                 friction_coefficient = 0;
    FrictionContactOptions friction;
    /// Newton on the smooth part: |dv| <= tolerance (|v+| + velocity_scale).
    double       newton_tolerance  = 1e-10;
    double       velocity_scale    = 1e-6; // m/s
    unsigned int newton_iterations = 50;
    /// J is dense (LU with partial pivoting) up to this many equations;
    /// beyond, sparse, factored by `linear_solver` (Time integration/Linear
    /// solver: one that runs on one process).
    unsigned int max_dense_equations = 500;
    std::string  linear_solver       = "eigen-ldlt";
  };
} // namespace poundfe

#endif
