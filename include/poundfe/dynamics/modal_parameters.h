// The `Modal analysis` section: which eigensolver computes the modes (for
// the output and for Rayleigh damping). Kept apart from dynamics/modal.h so
// that the input aggregate does not pull in the sparse matrix headers.
#ifndef poundfe_dynamics_modal_parameters_h
#define poundfe_dynamics_modal_parameters_h

#include <poundfe/base/choices.h>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  enum class Eigensolver
  {
    automatic,
    dense,
    sparse
  };

  const NameTable<Eigensolver> &eigensolver_names();

  /// `automatic` takes the dense solver up to this many equations: there
  /// it costs under ~0.1 s and gives every mode; above, its O(n^3) time
  /// grows quickly (doc/benchmarks.md) while the sparse one stays near linear.
  constexpr unsigned int dense_eigensolver_limit = 500;

  struct ModalParameters
  {
    Eigensolver eigensolver = Eigensolver::automatic;

    /// Declare the `Modal analysis` section (entered and left here).
    void declare(dealii::ParameterHandler &prm);
  };
} // namespace poundfe

#endif
