// The time loop of one model (deal.II step-23/26 style): set up the
// initial state, advance the Newmark-Newton integrator step by step and let
// each observer read the state, then let the observers finish.
#include <poundfe/dynamics/time_history.h>
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/excitation/stochastic_load.h>
#include <poundfe/integration/dormand_prince.h>
#include <poundfe/integration/moreau_jean.h>
#include <poundfe/integration/newmark.h>
#include <poundfe/integration/static_analysis.h>
#include <poundfe/output/recorders.h>

#include <deal.II/base/mpi.h>

#include <chrono>
#include <sstream>

namespace poundfe
{
  namespace
  {
    double
    end_time_of(const TimeIntegrationParameters &time_integration, const Excitation &excitation)
    {
      if (time_integration.end_time > 0)
        return time_integration.end_time;
      return excitation.ground_motion().duration();
    }

    /// The entry that sets the ground motion's duration, and so the end of a
    /// run without an End time: the record or the stochastic motion's Duration.

    /// Time integration/Method = dopri: its integrator, refused (InputError)
    /// when the model is beyond it; null for newmark.
    std::unique_ptr<DormandPrinceIntegrator>
    make_dormand_prince(const LinearSystem &system, const TimeHistoryParameters &parameters,
                        NonlinearElements &elements)
    {
      const TimeIntegrationParameters &time_integration = parameters.time_integration;
      if (time_integration.method != TimeIntegrationMethod::dopri)
        return nullptr;
      const DormandPrinceParameters dopri = time_integration.dormand_prince();
      if (const std::string why =
            DormandPrinceIntegrator::unsupported(system, &elements, dopri.max_equations);
          !why.empty())
        parameters.input.fail("Time integration/Method", "dopri " + why);
      return std::make_unique<DormandPrinceIntegrator>(system, dopri, &elements);
    }

    /// Contact/Model = nonsmooth: Moreau-Jean's integrator on the model's
    /// gaps, refused (InputError naming the entry) for what it does not take
    /// yet; null for penalty.
    std::unique_ptr<MoreauJeanIntegrator>
    make_moreau_jean(const Analysis &analysis, const TimeHistoryParameters &parameters,
                     NonlinearElements &elements)
    {
      const TimeIntegrationParameters &time_integration = parameters.time_integration;
      if (time_integration.contact_model != ContactModel::nonsmooth)
        return nullptr;
      const InputFile           &input      = parameters.input;
      const MoreauJeanParameters moreau_jean = time_integration.moreau_jean_parameters();
      if (analysis.gravity.active)
        input.fail("Contact/Model", "nonsmooth does not take a gravity analysis first "
                                    "(Model/Gravity analysis) yet");
      if (const std::string why = MoreauJeanIntegrator::unsupported(analysis.system, &elements,
                                                                    moreau_jean);
          !why.empty())
        input.fail("Contact/Model", "nonsmooth " + why);
      std::vector<UnilateralContact> contacts;
      if (const std::string why = unilateral_contacts(analysis.model, elements,
                                                      time_integration.restitution, contacts);
          !why.empty())
        input.fail("Contact/Model", "nonsmooth " + why);
      if (const std::string why = MoreauJeanIntegrator::unsupported(analysis.system, contacts);
          !why.empty())
        input.fail("Contact/Model", "nonsmooth " + why);
      if (moreau_jean.friction_coefficient > 0)
        for (UnilateralContact &contact : contacts)
          {
            if (contact.on_column)
              input.fail("Contact/Friction coefficient",
                         "acts along contacts between two slabs in plan; friction between a "
                         "slab and a column is not set up (gap " + contact.label +
                           "): set Contact/Friction coefficient = 0 or Contact/Floor to column "
                           "in plan = false");
            if (!contact.in_plan)
              input.fail("Contact/Friction coefficient",
                         "acts along contacts in plan (Model/Dimension = 3), where the slabs "
                         "slide along the edge they touch; gap " + contact.label +
                           " closes along one direction only, with no sliding to resist");
            contact.friction = moreau_jean.friction_coefficient;
          }
      return std::make_unique<MoreauJeanIntegrator>(analysis.system, moreau_jean,
                                                    std::move(contacts), &elements);
    }
  } // namespace

  namespace
  {
    /// Whether row `row` of member m's map u_e = T q is the one DOF of
    /// `node` alone (a joint's own ux or uz): then the member's end is at it.
    bool
    row_is_own_dof_of(const Member3D &m, const unsigned int row, const unsigned int node)
    {
      const unsigned int n = m.dofs.size();
      unsigned int       nonzero = 0, own = 0;
      for (unsigned int j = 0; j < n; ++j)
        if (m.map[row * n + j] != 0)
          {
            ++nonzero;
            own += m.dofs[j] / n_dofs_per_node == node;
          }
      return nonzero == 1 && own == 1;
    }

    /// Where a node of a 3D model is, site (x, y, z): Node::position holds
    /// only (x, z) there. A floor's master is at the floor's mass centre; a
    /// joint's node at the end of a member that moves with it alone; a
    /// hinge's at the member end it releases. false: none of these.
    bool
    site_point_of_node(const Model &model, const unsigned int node, std::array<double, 3> &at)
    {
      const Node     &n        = model.nodes[node];
      const Building &building = model.buildings[n.building];
      for (unsigned int i = 0; i < building.floors.size() && i < building.plan.size(); ++i)
        if (building.floors[i].nodes.size() == 1 && building.floors[i].nodes[0] == node)
          {
            at = {{building.plan[i].mass_centre.x, building.plan[i].mass_centre.y, n.position.y}};
            return true;
          }
      const bool hinge = n.generalized && !n.joint_translation_z;
      for (const Member3D &m : model.members_3d)
        for (unsigned int k = 0; k < 2; ++k)
          {
            if (m.ends[k][0] != n.position.x || m.ends[k][2] != n.position.y)
              continue;
            const unsigned int first = 6 * k;
            bool               moves = false;
            if (hinge)
              for (unsigned int j = 0; j < m.dofs.size(); ++j)
                for (unsigned int r = first + 3; r < first + 6; ++r)
                  moves |= m.dofs[j] / n_dofs_per_node == node && m.map[r * m.dofs.size() + j] != 0;
            else
              moves = row_is_own_dof_of(m, first, node) || row_is_own_dof_of(m, first + 2, node);
            if (moves)
              {
                at = m.ends[k];
                return true;
              }
          }
      return false;
    }

    /// "A3 node 12 at (6, 3) rz" (2D), "A node 7 at (6, 4.5, 3.6) uz" (3D):
    /// the DOF `dof` of `model`, its component named as the recorders name it.
    std::string
    dof_name(const Model &model, const unsigned int dof)
    {
      const unsigned int    index = dof / n_dofs_per_node;
      const Node           &node  = model.nodes[index];
      std::array<double, 3> at{};
      std::ostringstream    s;
      s << model.buildings[node.building].name << " node " << index << " at (";
      if (model.dimension == 3 && site_point_of_node(model, index, at))
        s << at[0] << ", " << at[1] << ", " << at[2];
      else
        s << node.position.x << ", " << node.position.y;
      s << ") " << node_components(model, index)[dof % n_dofs_per_node];
      return s.str();
    }
  } // namespace

  std::vector<std::string>
  equation_names(const Model &model)
  {
    std::vector<std::string> names(model.n_equations());
    for (unsigned int dof = 0; dof < model.n_dofs(); ++dof)
      {
        const int eq = model.equation(dof);
        if (eq >= 0 && names[eq].empty())
          names[eq] = dof_name(model, dof);
      }
    return names;
  }

  std::string
  equation_name(const Model &model, const unsigned int equation)
  {
    for (unsigned int dof = 0; dof < model.n_dofs(); ++dof)
      if (model.equation(dof) == int(equation))
        return dof_name(model, dof);
    return "";
  }

  Excitation
  make_excitation(const Analysis &analysis, const TimeHistoryParameters &parameters)
  {
    const InputFile              &input         = parameters.input;
    const GroundMotionParameters &ground_motion = parameters.ground_motion;
    const double                  dt = parameters.time_integration.newmark.time_step;
    Excitation excitation(analysis.system, make_ground_motion(ground_motion, input, dt),
                          make_nodal_forces(parameters.nodal_forces, ground_motion, dt, input,
                                            analysis.model));
    add_horizontal_component(excitation, analysis.system, analysis.model, ground_motion, input, dt);
    add_vertical_component(excitation, analysis.system, analysis.model, ground_motion, input, dt);
    if (!parameters.nodal_forces.white_noise.empty())
      {
        const StochasticLoad load(ground_motion, dt, excitation);
        std::vector<double>  xi;
        load.standard_normals(ground_motion.realization, xi);
        load.apply(xi, excitation);
      }
    return excitation;
  }

  TimeHistory::TimeHistory(const Analysis &analysis_, const TimeHistoryParameters &parameters,
                           const std::string &linear_solver)
    : analysis(analysis_)
    , input(parameters.input)
    , time_integration(parameters.time_integration)
    , ground_motion(parameters.ground_motion)
    , elements(make_nonlinear_elements(analysis_.model))
    , integrator(std::make_unique<NewmarkIntegrator>(
        analysis_.system, linear_solver.empty() ? time_integration.linear_solver : linear_solver,
        time_integration.newmark, &elements))
    , dopri(make_dormand_prince(analysis_.system, parameters, elements))
    , rigid(make_moreau_jean(analysis_, parameters, elements))
    , stepper(dopri ? static_cast<TimeStepper &>(*dopri) :
                      rigid ? static_cast<TimeStepper &>(*rigid) : *integrator)
    , view(analysis_.model, analysis_.system, elements, stepper)
    , initial(initial_state(parameters.initial_conditions, analysis_.model, parameters.input))
  {
    integrator->set_equation_names(equation_names(analysis_.model));
    integrator->equilibrate_massless_start(!parameters.initial_conditions.at_rest());
    if (analysis_.gravity.active)
      {
        if (dopri)
          parameters.input.fail("Model/Gravity analysis/Type",
                                "a gravity analysis first is not available with Time "
                                "integration/Method = dopri; use newmark");
        const std::vector<Vector> &path    = analysis_.gravity.path;
        const std::vector<double> &factors = analysis_.gravity.path_factors;
        integrator->set_element_preload(
          [&path, &factors](NonlinearElements &e) { restore_static_state(path, factors, e); });
        integrator->hold_gravity_state(analysis_.gravity.held, analysis_.gravity.displacement);
      }
    // known before the observers are made (the recorders choose their columns)
    view.set_vertical_ground_motion(parameters.ground_motion.has_vertical());
  }

  TimeHistory::~TimeHistory() = default;

  TimeHistory::TimeHistory(const Analysis &analysis_, const TimeHistoryParameters &parameters,
                           LockstepStepper &lockstep_stepper)
    : analysis(analysis_)
    , input(parameters.input)
    , time_integration(parameters.time_integration)
    , ground_motion(parameters.ground_motion)
    , stepper(lockstep_stepper)
    , lockstep(&lockstep_stepper)
    , view(analysis_.model, analysis_.system, lockstep_stepper.observed_elements(), stepper)
    , initial(initial_state(parameters.initial_conditions, analysis_.model, parameters.input))
  {
    AssertThrow(!analysis_.gravity.active,
                dealii::ExcMessage("a partitioned run refuses a gravity analysis first"));
    lockstep_stepper.set_observed(view);
    view.set_vertical_ground_motion(parameters.ground_motion.has_vertical());
  }

  std::string
  TimeHistory::tangent_update() const
  {
    Assert(integrator, dealii::ExcMessage("a lockstep stepper's run: its own tangent update"));
    return tangent_update_names().name(integrator->tangent_update());
  }

  std::string
  TimeHistory::linear_solver_name() const
  {
    Assert(integrator, dealii::ExcMessage("a lockstep stepper's run: its own linear solver"));
    return integrator->linear_solver_name();
  }

  void
  TimeHistory::replace_nonlinear_elements(const Model &model)
  {
    Assert(!lockstep, dealii::ExcMessage("a lockstep stepper's elements are its own"));
    NonlinearElements fresh = make_nonlinear_elements(model);
    AssertDimension(fresh.size(), elements.size());
    elements = std::move(fresh); // the same object: the integrator points to it
  }

  unsigned long
  TimeHistory::n_steps(const Excitation &excitation) const
  {
    return n_steps_of({input, time_integration, ground_motion, {}, {}}, excitation);
  }

  unsigned long
  n_steps_of(const TimeHistoryParameters &parameters, const Excitation &excitation)
  {
    const TimeIntegrationParameters &time_integration = parameters.time_integration;
    const InputFile                 &input            = parameters.input;
    const double end = end_time_of(time_integration, excitation);
    if (!(end > 0))
      throw InputError(input.file, input.line_of("Time integration/End time"),
                       "Time integration/End time",
                       "needs a positive end time when there is no ground motion");
    // what set the end: End time, else the record or the stochastic motion's
    // duration (Ground motion/Record/File or Ground motion/Stochastic/Duration)
    const std::string end_path =
      time_integration.end_time > 0 ?
        "Time integration/End time" :
        (parameters.ground_motion.type == GroundMotionType::record ?
           "Ground motion/Record/File" :
           "Ground motion/Stochastic/Duration");
    return time_integration.n_steps_to(end, input, end_path);
  }

  bool
  stop_requested(const MPI_Comm communicator)
  {
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (!initialized || dealii::Utilities::MPI::n_mpi_processes(communicator) == 1)
      return interruption_requested();
    return dealii::Utilities::MPI::logical_or(interruption_requested(), communicator);
  }

  RunStatus
  TimeHistory::run(const Excitation &excitation, const Observers &observers,
                   const bool interruptible)
  {
    if (analysis.gravity.active) // displacements are totals: the gravity state's and more
      return run(Vector(initial.displacement + analysis.gravity.displacement), initial.velocity,
                 excitation, observers, interruptible);
    return run(initial.displacement, initial.velocity, excitation, observers, interruptible);
  }

  bool
  TimeHistory::stops_before(const unsigned long step, const unsigned long n,
                            const bool interruptible, RunStatus &status) const
  {
    if (lockstep) // the ranks agree, also once after the last step
      return lockstep->agreed_stop(interruptible, status);
    if (step > n || !(interruptible && stop_requested(MPI_COMM_WORLD)))
      return false;
    status.kind = RunStatus::Kind::interrupted;
    return true;
  }

  void
  TimeHistory::observe(const Observation call, const Observers &observers)
  {
    if (lockstep)
      lockstep->observe(call, observers, view);
    else
      for (StepObserver *observer : observers)
        (observer->*call)(view);
  }

  RunStatus
  TimeHistory::run(const Vector &u0, const Vector &v0, const Excitation &excitation,
                   const Observers &observers, const bool interruptible)
  {
    const unsigned long n = n_steps(excitation);
    const double        dt = time_integration.newmark.time_step;
    const Vector       *held = analysis.gravity.active ? &analysis.gravity.held : nullptr;
    // the gravity loads held constant (OpenSees's loadConst)
    const LoadFunction  load = [&excitation, held](const double t, Vector &p) {
      excitation.load(t, p);
      if (held)
        p += *held;
    };
    Vector p0(analysis.system.n_equations());
    load(0, p0);
    stepper.initialize(p0, u0, v0);
    view.set_step(0, excitation.ground_acceleration_vector(0));
    observe(&StepObserver::initialize, observers);

    RunStatus     status;
    unsigned long step = 0;
    stepper.set_substep_callback([&]() {
      view.set_step(step, excitation.ground_acceleration_vector(stepper.time()));
      observe(&StepObserver::observe_substep, observers);
    });
    struct Forget // the callback refers to this call's locals
    {
      TimeStepper &stepper;
      ~Forget() { stepper.set_substep_callback(nullptr); }
    } forget{stepper};
    const auto start = std::chrono::steady_clock::now();
    try
      {
        for (step = 1; !stops_before(step, n, interruptible, status) && step <= n; ++step)
          {
            throw_if_interrupted(); // a command that stops at safe points (sweep, ...)
            stepper.advance(load);
            view.set_step(step, excitation.ground_acceleration_vector(step * dt));
            observe(&StepObserver::observe_step, observers);
          }
      }
    catch (const RunStopped &) // an observer's interruption: finished as one
      {
        status.kind = RunStatus::Kind::interrupted;
      }
    catch (const NumericalError &e)
      {
        status.kind    = RunStatus::Kind::failed;
        status.message = e.what();
      }
    catch (const OutputError &e) // a full disk: stop, and say so in what still fits
      {
        status.kind          = RunStatus::Kind::failed;
        status.output_failed = true;
        status.message       = e.what();
      }
    status.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    status.steps     = stepper.steps();
    status.end_time  = stepper.time();
    if (!lockstep || lockstep->merged(observers, view, status))
      finish_observers(observers, view, status);
    return status;
  }

  void
  finish_observers(const Observers &observers, const ResponseView &state, RunStatus &status)
  {
    // Every observer finishes (or removes) its files even when one cannot:
    // the summary, last, then reports the file that failed.
    for (StepObserver *observer : observers)
      try
        {
          observer->finish(state, status);
        }
      catch (const OutputError &e)
        {
          if (status.message.find(e.what()) == std::string::npos) // not a file's second word
            status.message += std::string(status.output_failed ? "; " : "") + e.what();
          status.kind          = RunStatus::Kind::failed;
          status.output_failed = true;
        }
  }
} // namespace poundfe
