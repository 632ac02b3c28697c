#include <poundfe/dynamics/modal_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace poundfe
{
  const NameTable<Eigensolver> &
  eigensolver_names()
  {
    static const NameTable<Eigensolver> table({{Eigensolver::automatic, "auto"},
                                               {Eigensolver::dense, "dense"},
                                               {Eigensolver::sparse, "sparse"}});
    return table;
  }

  void
  ModalParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Modal analysis");
    add_choice(prm, "Eigensolver", eigensolver,
               "Modes (output and Rayleigh damping): dense (every mode, O(n^3)), sparse "
               "(shift-invert Lanczos, ARPACK, for the few lowest modes of large models), or "
               "auto: dense up to " +
                 std::to_string(dense_eigensolver_limit) + " equations, sparse above. Unit: -.",
               eigensolver_names());
    prm.leave_subsection();
  }
} // namespace poundfe
