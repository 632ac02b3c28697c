// The values of the Bifurcation section, each one's input read and checked
// (input/sweep.h) with a time step that lands on every forcing period, and
// the diagram's points at those values (dynamics/bifurcation.h).
#ifndef poundfe_input_bifurcation_input_h
#define poundfe_input_bifurcation_input_h

#include <poundfe/dynamics/bifurcation.h>
#include <poundfe/input/input_parameters.h>

#include <vector>

namespace poundfe
{
  /// A value's input with dt' = T / round(T / dt) and the end time
  /// (transient + sampled) T, so that steps land on every k T.
  struct BifurcationValue
  {
    double          value = 0, period = 0;
    unsigned long   steps_per_period = 1;
    InputParameters input;
  };

  /// The input `input` names (with its Bifurcation section), read with the
  /// parameter at `value`, the forcing period's time step and end time.
  /// Throws InputError.
  BifurcationValue bifurcation_value(const InputParameters &input, double value);

  /// One point: the value's input prepared once and run once, from rest.
  /// Throws InputError.
  BifurcationPoint bifurcation_point(const InputParameters &input, double value);

  /// Every value of the input's Bifurcation section, in order (each input
  /// read and checked before any is run; with Continuation each value
  /// starts from the previous one's final state). Throws InputError.
  std::vector<BifurcationPoint> bifurcation_points(const InputParameters &input);
} // namespace poundfe

#endif
