// The `Time integration` section: the Newmark and Newton settings the
// integrator takes as they are, the end time, the linear solver, and the
// local iteration of the hysteretic laws. `Contact/Event refinement` also
// belongs here (it sets how the integrator refines a step with a contact
// event), although users find it in the Contact section.
#ifndef poundfe_integration_time_integration_parameters_h
#define poundfe_integration_time_integration_parameters_h

#include <poundfe/base/choices.h>
#include <poundfe/base/input_file.h>
#include <poundfe/integration/dormand_prince.h>
#include <poundfe/integration/moreau_jean_parameters.h>
#include <poundfe/integration/newmark.h>

#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  /// Bouc-Wen z over a step: the theta of the one-step rule.
  enum class HysteresisIntegration
  {
    trapezoidal,   // theta = 1/2, second order
    backward_euler // theta = 1, first order, most robust
  };

  const NameTable<HysteresisIntegration> &hysteresis_integration_names();

  /// How the time history is integrated.
  enum class TimeIntegrationMethod
  {
    newmark, // Newmark-Newton, every model (integration/newmark.h)
    dopri    // adaptive Dormand-Prince 5(4) with events, small models (dormand_prince.h)
  };

  const NameTable<TimeIntegrationMethod> &time_integration_method_names();

  /// Contact/Model: how the gaps act. penalty: each gap element's contact
  /// law, stepped by Method; nonsmooth: rigid unilateral contact with
  /// Newton's restitution, stepped by Moreau-Jean's scheme
  /// (integration/moreau_jean.h), only in a build with Siconos Numerics.
  enum class ContactModel
  {
    penalty,
    nonsmooth
  };

  const NameTable<ContactModel> &contact_model_names();

  /// How `mpirun -np P poundfe run` spreads one run over its ranks.
  enum class RunPartition
  {
    none,     // every rank runs the whole analysis (a distributed Linear solver splits the matrix)
    buildings // each rank steps its own buildings (dynamics/partitioned_history.h, theory §3.5d)
  };

  const NameTable<RunPartition> &run_partition_names();

  struct TimeIntegrationParameters
  {
    NewmarkParameters     newmark{0.001, 0.5, 0.25, NewtonParameters(), IterativeSolverParameters()};
    TimeIntegrationMethod method = TimeIntegrationMethod::newmark;
    /// dopri's tolerances (its time_step is newmark.time_step: see dormand_prince()).
    DormandPrinceParameters dopri;
    /// Contact/Model, Contact/Theta, Contact/LCP solver; the restitution is
    /// Contact/Coefficient of restitution (InputParameters::finalize copies
    /// it) and the time step newmark's: see moreau_jean_parameters().
    ContactModel          contact_model = ContactModel::penalty;
    MoreauJeanParameters  moreau_jean;
    double                restitution = 0.65;
    double                end_time      = 0.0; // 0 = length of the ground motion
    std::string           linear_solver = "eigen-ldlt"; // one of linear_solver_names()
    RunPartition          partition     = RunPartition::none;
    HysteresisIntegration hysteresis_integration = HysteresisIntegration::trapezoidal;
    double                law_tolerance          = 1e-12;
    unsigned int          law_max_iterations     = 30;
    /// Most time steps a run may take: End time / Time step (or the
    /// record's duration / Time step) beyond it is refused before the run.
    unsigned int          max_steps = 10000000;

    /// The number of steps to `end` (s): refused, naming `end_path` (what
    /// set the end), when it is not finite or exceeds max_steps.
    unsigned long n_steps_to(double end, const InputFile &input, const std::string &end_path) const;

    /// dopri's parameters with the analysis time step.
    DormandPrinceParameters dormand_prince() const;

    /// Moreau-Jean's parameters with the analysis time step.
    MoreauJeanParameters moreau_jean_parameters() const;

    /// theta of the hysteretic laws' one-step rule.
    double hysteresis_theta() const;

    /// Declare the `Time integration` section (entered and left here).
    void declare(dealii::ParameterHandler &prm);
    /// `Event refinement`, in the current subsection (`Contact`).
    void declare_event_refinement(dealii::ParameterHandler &prm);
    /// Throws InputError.
    void check(const InputFile &input) const;
    /// Contact/Model and Contact/Theta against this build and the method
    /// (part of check()).
    void check_contact_model(const InputFile &input) const;
  };
} // namespace poundfe

#endif
