// The pushover engine (dynamics/pushover.h): the load pattern, the push by
// displacement control with the arc-length fallback, and what each point of
// the curve records.
#include <poundfe/dynamics/pushover.h>
#include <poundfe/dynamics/modal.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/integration/static_analysis.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <tuple>

namespace poundfe
{
  namespace
  {
    /// The ux equations of building b with the height above its base of
    /// the first node on each (nodes that share an equation count once).
    std::vector<std::pair<unsigned int, double>>
    lateral_equations(const Model &model, const unsigned int b)
    {
      const Building &building = model.buildings[b];
      double          base     = 0;
      for (unsigned int n = building.first_node; n < building.first_node + building.n_nodes; ++n)
        base = n == building.first_node ? model.nodes[n].position.y :
                                          std::min(base, model.nodes[n].position.y);
      std::vector<std::pair<unsigned int, double>> result;
      std::set<int>                                seen;
      for (unsigned int n = building.first_node; n < building.first_node + building.n_nodes; ++n)
        {
          const int eq = model.equation(Model::dof(n, Component::ux));
          if (eq >= 0 && seen.insert(eq).second)
            result.emplace_back(eq, model.nodes[n].position.y - base);
        }
      return result;
    }

    /// The first mode of building b and its period (its own, or computed
    /// on the state's tangent when the analysis kept none).
    std::pair<Vector, double>
    first_mode_of(const Analysis &analysis, const unsigned int b)
    {
      const auto range = analysis.model.equation_range(b);
      const unsigned int n = range[1] - range[0];
      if (analysis.building_modes.size() > b && analysis.building_modes[b].n_modes() > 0)
        return {analysis.building_modes[b].shapes.col(0), analysis.building_modes[b].period(0)};
      const SparseMatrix &k =
        analysis.gravity.active ? analysis.gravity.tangent : analysis.system.stiffness;
      const Modes modes = compute_modes(block(analysis.system.mass, range), block(k, range),
                                        analysis.system.influence.segment(range[0], n), 1);
      return {modes.shapes.col(0), modes.period(0)};
    }

    /// ASCE 41-17's C0 of the control building b (its first mode phi's
    /// participation factor phi^T M r / phi^T M phi times phi at the control
    /// equation), its period T_i and its mass r^T M r along x.
    void
    asce41_first_mode(const Analysis &analysis, const unsigned int b,
                      const unsigned int control_equation, PushoverResult &result)
    {
      const auto         range         = analysis.model.equation_range(b);
      const auto         [phi, period] = first_mode_of(analysis, b);
      const SparseMatrix mass          = block(analysis.system.mass, range);
      const Vector r  = analysis.system.influence.segment(range[0], range[1] - range[0]);
      const Vector Mr = mass * r, Mphi = mass * phi;
      result.first_period  = period;
      result.building_mass = r.dot(Mr);
      result.first_mode_c0 = phi[control_equation - range[0]] * phi.dot(Mr) / phi.dot(Mphi);
    }

    /// The control node's ux equation and its height above the base.
    std::pair<unsigned int, double>
    control_of(const Model &model, const PushoverParameters &parameters, const InputFile &input)
    {
      const Building &building = model.buildings[parameters.control_building - 1];
      const unsigned int n_floors = building.floors.size();
      if (parameters.control_floor > n_floors || n_floors == 0)
        input.fail("Pushover/Control floor",
                   "building '" + building.name + "' has " + std::to_string(n_floors) +
                     " floors, there is no floor " + std::to_string(parameters.control_floor));
      const Floor &floor =
        building.floors[parameters.control_floor == 0 ? n_floors - 1 : parameters.control_floor - 1];
      const int eq = model.equation(Model::dof(floor.nodes.front(), Component::ux));
      if (eq < 0)
        input.fail("Pushover/Control floor", "the floor's first joint has no free ux");
      double height = 0;
      for (const Floor &f : building.floors)
        if (f.level <= floor.level)
          height += f.storey_height;
      return {unsigned(eq), height};
    }
  } // namespace

  Vector
  lateral_load_pattern(const Analysis &analysis, const PushoverParameters &parameters,
                       const unsigned int control_equation, Vector &shapes)
  {
    const Model &model = analysis.model;
    const Vector mass  = analysis.system.mass * analysis.system.influence; // M r on ux
    Vector       pattern = Vector::Zero(model.n_equations());
    shapes               = Vector::Zero(model.n_equations());
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      {
        const LoadPattern kind  = parameters.patterns[b];
        const Vector      mode  = kind == LoadPattern::mode ? first_mode_of(analysis, b).first : Vector();
        const unsigned int first = model.equation_range(b)[0];
        double             sum   = 0;
        for (const auto &[eq, z] : lateral_equations(model, b))
          {
            const double phi = kind == LoadPattern::uniform ? 1.0 :
                               kind == LoadPattern::triangular ? z :
                                                                 mode[eq - first];
            shapes[eq]  = phi;
            pattern[eq] = mass[eq] * phi;
            sum += pattern[eq];
          }
        AssertThrow(sum != 0, dealii::ExcMessage("a load pattern without mass"));
        for (const auto &[eq, z] : lateral_equations(model, b))
          pattern[eq] /= sum;
        if (b + 1 == parameters.control_building)
          {
            const double at_control = shapes[control_equation];
            for (const auto &[eq, z] : lateral_equations(model, b))
              shapes[eq] /= at_control;
          }
        else
          for (const auto &[eq, z] : lateral_equations(model, b))
            shapes[eq] = 0;
      }
    return pattern;
  }

  namespace
  {
    /// The push: points of the curve as they are committed.
    class Push
    {
    public:
      Push(const Analysis &analysis, const PushoverParameters &parameters, const InputFile &input,
           const SectionLimitParameters *limits);
      PushoverResult run();

    private:
      /// To the control displacement `goal`; false when it cannot go on.
      bool excursion(double goal);
      void record(bool arc_length);
      void fail(const std::string &why);

      const Analysis           &analysis;
      const Model              &model;
      const PushoverParameters &parameters;
      PushoverResult            result;
      NonlinearElements         elements;
      Vector                    constant, pattern, shapes;
      StaticSolver              solver;
      PathFollower              follower;
      PathPoint                 point;
      std::vector<unsigned int> reported; // the elements in the curve
      std::vector<std::vector<std::pair<unsigned int, double>>> lateral; // per building
      std::shared_ptr<SectionLimitStates> section_limits; // with fibre members
    };

    PathSettings
    path_settings_of(const PushoverParameters &parameters)
    {
      PathSettings settings;
      settings.tolerance      = parameters.tolerance;
      settings.max_iterations = parameters.max_iterations;
      return settings;
    }

    Push::Push(const Analysis &analysis_, const PushoverParameters &parameters_,
               const InputFile &input, const SectionLimitParameters *limits)
      : analysis(analysis_)
      , model(analysis_.model)
      , parameters(parameters_)
      , elements(make_nonlinear_elements(analysis_.model))
      , solver(analysis_.system.stiffness, &elements)
      , follower(solver, constant, pattern, path_settings_of(parameters_))
    {
      if (model.dimension != 2)
        input.fail("Model/Dimension", "the pushover command is for 2D models");
      std::tie(result.control_equation, result.control_height) =
        control_of(model, parameters, input);
      result.control_name = equation_name(model, result.control_equation);
      pattern             = lateral_load_pattern(analysis, parameters, result.control_equation, shapes);
      constant            = Vector::Zero(model.n_equations());
      point.u             = Vector::Zero(model.n_equations());
      if (analysis.gravity.active)
        {
          restore_static_state(analysis.gravity.path, analysis.gravity.path_factors, elements);
          constant = analysis.gravity.held;
          point.u  = analysis.gravity.displacement;
        }
      const Vector mass = analysis.system.mass * analysis.system.influence;
      double       sum_m_phi2 = 0;
      for (unsigned int eq = 0; eq < shapes.size(); ++eq)
        {
          result.equivalent_mass += mass[eq] * shapes[eq];
          sum_m_phi2 += mass[eq] * shapes[eq] * shapes[eq];
        }
      result.gamma = result.equivalent_mass / sum_m_phi2;
      if (parameters.asce41())
        asce41_first_mode(analysis, parameters.control_building - 1, result.control_equation, result);
      for (unsigned int b = 0; b < model.buildings.size(); ++b)
        {
          lateral.push_back(lateral_equations(model, b));
          for (unsigned int i = 0; i < model.buildings[b].floors.size(); ++i)
            result.storeys.push_back(model.buildings[b].name + " storey " + std::to_string(i + 1));
        }
      for (unsigned int h = 0; h < elements.size(); ++h)
        if (elements[h].kind == ElementKind::hinge || elements[h].kind == ElementKind::storey ||
            elements[h].kind == ElementKind::member)
          {
            reported.push_back(h);
            result.elements.push_back(elements[h].label);
          }
      if (limits)
        {
          section_limits = std::make_shared<SectionLimitStates>(model, elements, *limits);
          if (section_limits->empty())
            section_limits.reset();
          else // the columns' axial forces change with the overturning moment
            section_limits->follow_axial_force();
        }
    }

    void
    Push::record(const bool arc_length)
    {
      PushoverPoint p;
      p.lambda               = point.lambda;
      p.control_displacement = point.u[result.control_equation];
      p.arc_length           = arc_length;
      const Vector load = constant + point.lambda * pattern;
      // each building's base shear: the loads on its floors less what its
      // gaps and links carry to the neighbour
      Vector carried = Vector::Zero(load.size());
      for (const NonlinearElement &e : elements)
        if (e.kind == ElementKind::gap || e.kind == ElementKind::link)
          {
            Vector local(e.n_dofs());
            e.force_correction(local);
            for (unsigned int i = 0; i < e.n_dofs(); ++i)
              if (e.equations()[i] >= 0)
                carried[e.equations()[i]] += local[i];
          }
      for (unsigned int b = 0; b < model.buildings.size(); ++b)
        {
          double shear = 0;
          for (const auto &[eq, z] : lateral[b])
            shear += load[eq] - carried[eq];
          p.base_shears.push_back(shear);
          double below = 0;
          for (const Floor &floor : model.buildings[b].floors)
            {
              const int    eq = model.equation(Model::dof(floor.nodes.front(), Component::ux));
              const double u  = eq >= 0 ? point.u[eq] : 0.0;
              p.drifts.push_back((u - below) / floor.storey_height);
              below = u;
            }
        }
      for (const unsigned int h : reported)
        {
          p.element_forces.push_back(elements[h].force());
          p.element_deformations.push_back(elements[h].deformation(point.u));
        }
      if (section_limits)
        {
          if (!result.points.empty()) // the start is observed by initialize_at
            section_limits->observe_at(p.control_displacement);
          for (unsigned int b = 0; b < model.buildings.size(); ++b)
            for (const int worst : section_limits->storey_worst_limits(model, b))
              p.storey_damage.push_back(worst);
        }
      result.points.push_back(std::move(p));
    }

    void
    Push::fail(const std::string &why)
    {
      std::ostringstream s;
      s << "pushover: no equilibrium beyond the control displacement "
        << point.u[result.control_equation] << " m (" << result.control_name << ", load factor "
        << point.lambda << "): " << why;
      const std::string element = solver.most_strained_element(point.u);
      if (!element.empty())
        s << "; most strained element " << element;
      result.completed = false;
      result.failure   = s.str();
    }

    bool
    Push::excursion(const double goal)
    {
      const unsigned int c         = result.control_equation;
      const double       start     = point.u[c];
      const double       direction = goal >= start ? 1.0 : -1.0;
      const double       nominal   = std::abs(goal - start) / parameters.n_steps;
      double             step = nominal, length = 0;
      unsigned int       level = 0, count = 0;
      bool               arc   = false;
      point.increment.resize(0); // a new excursion: no direction yet
      while (direction * (goal - point.u[c]) > 1e-12 * std::max(std::abs(goal - start), 1e-12))
        {
          if (++count > 100 * parameters.n_steps + 1000)
            {
              fail("the target is not reached in " + std::to_string(count - 1) + " steps");
              return false;
            }
          const bool done = arc ? follower.arc_length_step(length, c, direction, point) :
                                  follower.displacement_step(
                                    c, direction * std::min(step, std::abs(goal - point.u[c])),
                                    point);
          result.iterations += follower.iterations();
          if (done)
            {
              result.arc_length_steps += arc;
              record(arc);
              if (level > 0) // grow back towards the given size
                {
                  (arc ? length : step) *= 2;
                  --level;
                }
              continue;
            }
          if (level < parameters.max_step_cuts)
            {
              (arc ? length : step) /= 2;
              ++level;
              ++result.step_cuts;
              continue;
            }
          if (arc || !parameters.arc_length)
            {
              fail(follower.failure().empty() ? "no convergence at the smallest step" :
                                                follower.failure());
              return false;
            }
          // displacement control cannot pass (a peak, a snap-back): arc length
          arc    = true;
          length = point.increment.size() > 0 ? point.increment.norm() : nominal;
          level  = 0;
        }
      return true;
    }

    PushoverResult
    Push::run()
    {
      if (section_limits) // the start: gravity's axial forces give the yield curvatures
        section_limits->initialize_at(point.u[result.control_equation]);
      record(false);
      for (const double drift : parameters.targets())
        if (!excursion(drift * result.control_height))
          break;
      result.section_limits = section_limits;
      return std::move(result);
    }
  } // namespace

  PushoverResult
  run_pushover(const Analysis &analysis, const PushoverParameters &parameters,
               const InputFile &input, const SectionLimitParameters *limits)
  {
    Push push(analysis, parameters, input, limits);
    return push.run();
  }
} // namespace poundfe
