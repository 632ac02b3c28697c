// The `Initial conditions` section: the state (u0, v0) a time history starts
// from instead of rest, in the relative coordinates of the equations of
// motion. Given per floor of a building (ux of every node on the floor: a
// list with one value per floor, or `all <value>` for every floor), per
// equation (`<index> = <value>`, the model's free DOFs numbered from 0,
// building by building, floors bottom to top for shear buildings), or as
// the whole state vector y0 = [u0; v0] of a small oscillator (the thesis's
// Fig. 3.7 starts at y0 = [3, 0]). The integrator then takes the consistent
// acceleration M a0 = p(0) - C v0 - K u0 - f(u0, v0) (nonlinear elements at
// u0: a gap already closed pushes back at t = 0) and counts the kinetic and
// strain energy at t = 0 as supplied (integration/newmark.h).
// Source: Chopra, Dynamics of Structures, 4th ed., §2.1-2.2 (free vibration
// from u(0), u'(0)), §5.4 (Newmark's a0).
#ifndef poundfe_dynamics_initial_conditions_h
#define poundfe_dynamics_initial_conditions_h

#include <poundfe/assembly/linear_system.h>
#include <poundfe/base/input_file.h>
#include <poundfe/model/model.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  struct InitialConditionParameters
  {
    /// 'building: v1 v2 ... vN' or 'building: all v', ';'-separated.
    std::vector<std::string> floor_displacements, floor_velocities;
    /// 'index = value', ';'-separated.
    std::vector<std::string> equation_displacements, equation_velocities;
    /// u0 then v0 on every equation (2 n values); empty: not given.
    std::vector<double> state;

    void declare(dealii::ParameterHandler &prm);
    /// Checks what needs no model: the form of every entry, finite values,
    /// State alone. Throws InputError.
    void finalize(const InputFile &input) const;
    /// Whether every entry is empty (the run starts from rest).
    bool at_rest() const;
  };

  /// u0 and v0 on the model's equations (zero where nothing is given).
  struct InitialState
  {
    Vector displacement, velocity;
  };

  /// The state the parameters describe on `model`. Throws InputError for a
  /// building, floor or equation the model does not have, or a list of the
  /// wrong length.
  InitialState initial_state(const InitialConditionParameters &parameters, const Model &model,
                             const InputFile &input);
} // namespace poundfe

#endif
