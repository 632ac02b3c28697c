// The Filippov switching analysis of a small model: its surfaces and its
// field on each side; equations and sources in integration/model_switching.h.
#include <poundfe/assembly/modal_damping.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/integration/dormand_prince.h>
#include <poundfe/integration/element_kind_text.h>
#include <poundfe/integration/model_switching.h>

#include <deal.II/base/exceptions.h>

#include <Eigen/Cholesky>

#include <cmath>

namespace poundfe
{
  namespace
  {
    /// The surface n . x = offset over x = (u, v) of a rank-1 element's
    /// deformation (on u, or on v with `on_velocity`).
    SwitchingSurface
    element_surface(const NonlinearElement &e, const unsigned int n, const bool on_velocity,
                    const double offset, const std::string &name)
    {
      SwitchingSurface s{name, Vector::Zero(2 * n), offset};
      const Eigen::MatrixXd basis = e.tangent_basis();
      for (unsigned int i = 0; i < e.n_dofs(); ++i)
        if (e.equations()[i] >= 0)
          s.normal[(on_velocity ? n : 0) + e.equations()[i]] = basis(i, 0);
      return s;
    }
  } // namespace

  std::string
  ModelSwitching::unsupported(const LinearSystem &system, const Model &model,
                              const NonlinearElements &elements, const unsigned int max_equations)
  {
    const unsigned int n = system.n_equations();
    if (n > max_equations)
      return "takes models of up to " + std::to_string(max_equations) +
             " equations; this one has " + std::to_string(n);
    const Eigen::MatrixXd mass(system.mass);
    for (unsigned int i = 0; i < n; ++i)
      if (!(mass(i, i) > 0))
        return "needs mass on every equation; equation " + std::to_string(i) + " has none";
    if (!model.gaps.empty() && model.contact.law == "hertz-damp")
      return "needs a contact force of the state alone; hertz-damp's damping depends on each "
             "impact's approach velocity (take jankowski or kelvin-voigt)";
    if (!model.gaps.empty() && model.bumper.law != BumperLaw::none)
      return "takes bare gaps; a bumper keeps a history";
    for (const Spring &spring : model.springs)
      if (spring.law.kind == SpringKind::sd && spring.law.height == 0)
        return "takes smooth springs; " + spring.label + " is a discontinuous SD spring (H = 0)";
    for (const NonlinearElement &e : elements)
      if (!((e.kind == ElementKind::gap || e.kind == ElementKind::spring ||
             e.kind == ElementKind::friction) &&
            e.rank() == 1))
        return "takes contacts, elastic springs and friction; " + e.label + " is " +
               element_kind_text(e);
    return {};
  }

  ModelSwitching::ModelSwitching(const LinearSystem &system, const Model &model,
                                 NonlinearElements &elements_, LoadFunction load_,
                                 const FilippovParameters &parameters)
    : linear(system)
    , elements(elements_)
    , load(std::move(load_))
    , n(system.n_equations())
  {
    Assert(unsupported(system, model, elements, 1u << 30).empty(),
           dealii::ExcMessage(unsupported(system, model, elements, 1u << 30)));
    Eigen::LLT<Eigen::MatrixXd> factor(Eigen::MatrixXd(system.mass));
    mass_inverse = factor.solve(Eigen::MatrixXd::Identity(n, n));
    std::vector<SwitchingSurface> surfaces;
    unsigned int                  n_gaps = 0, n_friction = 0;
    for (unsigned int h = 0; h < elements.size(); ++h)
      {
        const NonlinearElement &e = elements[h];
        surface_of.push_back(e.kind == ElementKind::spring ? -1 : int(surfaces.size()));
        friction.emplace_back();
        friction_laws.emplace_back();
        if (e.kind == ElementKind::gap)
          {
            const double gap = model.gaps[n_gaps++].initial_gap;
            surfaces.push_back(element_surface(e, n, false, gap, e.label + " gap"));
            surfaces.push_back(element_surface(e, n, true, 0, e.label + " rate"));
            kinds.insert(kinds.end(), {"gap", "rate"});
          }
        else if (e.kind == ElementKind::friction)
          {
            const FrictionLawParameters &law = model.friction_surfaces[n_friction++].law;
            friction.back()      = std::make_unique<Friction>(law);
            friction_laws.back() = law;
            surfaces.push_back(element_surface(e, n, true, law.belt_velocity, e.label + " slip"));
            kinds.push_back("slip");
          }
      }
    filippov = std::make_unique<FilippovSystem>(
      std::move(surfaces),
      [this](double t, const Vector &x, const std::vector<int> &s, Vector &dx) {
        field(t, x, s, dx);
      },
      parameters);
  }

  void
  ModelSwitching::field(const double t, const Vector &x, const std::vector<int> &sides,
                        Vector &dx)
  {
    force.setZero(n);
    load(t, force);
    const Vector u = x.head(n), v = x.segment(n, n);
    force -= damping_product(linear, v) + linear.stiffness * u;
    for (unsigned int h = 0; h < elements.size(); ++h)
      {
        NonlinearElement &e = elements[h];
        const int         j = surface_of[h];
        if (e.kind == ElementKind::friction)
          {
            // the side's Coulomb force; mu_s on the surface (the stick set)
            const FrictionLawParameters &p = friction_laws[h];
            const double slip = e.deformation(v) - p.belt_velocity;
            double       derivative = 0;
            const double mu = filippov->surface_evaluated() == j ?
                                p.static_coefficient :
                                friction[h]->coefficient(slip, derivative);
            const double f  = sides[j] * mu * p.normal(e.deformation(u), e.deformation(v)).n;
            const Eigen::MatrixXd basis = e.tangent_basis();
            for (unsigned int i = 0; i < e.n_dofs(); ++i)
              if (e.equations()[i] >= 0)
                force[e.equations()[i]] -= basis(i, 0) * f;
            continue;
          }
        if (e.kind == ElementKind::gap && sides[j] < 0)
          continue; // open: no contact force
        local_u.resize(e.n_dofs());
        local_v.resize(e.n_dofs());
        for (unsigned int i = 0; i < e.n_dofs(); ++i)
          {
            local_u[i] = e.equations()[i] < 0 ? 0.0 : u[e.equations()[i]];
            local_v[i] = e.equations()[i] < 0 ? 0.0 : v[e.equations()[i]];
          }
        e.set_trial_time(t);
        if (!e.set_trial(local_u, local_v))
          throw NumericalError("t = " + number_text(t) + " s: " + e.label + ": " + e.failure());
        correction.resize(e.n_dofs());
        e.force_correction(correction);
        e.revert();
        for (unsigned int i = 0; i < e.n_dofs(); ++i)
          if (e.equations()[i] >= 0)
            force[e.equations()[i]] -= correction[i];
      }
    dx.resize(2 * n);
    dx.head(n)       = v;
    dx.segment(n, n) = mass_inverse * force;
  }

  void
  ModelSwitching::run(const Vector &u0, const Vector &v0, const double t_end)
  {
    Vector x0(2 * n);
    x0 << u0, v0;
    filippov->run(x0, t_end);
  }

  std::vector<SwitchingEvent>
  ModelSwitching::events() const
  {
    std::vector<SwitchingEvent> kept;
    const std::vector<SwitchingSurface> &surfaces = filippov->switching_surfaces();
    for (const SwitchingEvent &e : filippov->log())
      {
        // a rate surface's gap is the surface before it
        const SwitchingSurface &gap = surfaces[e.surface == 0 ? 0 : e.surface - 1];
        if (kinds[e.surface] != "rate" || gap.normal.dot(e.state) - gap.offset > 0)
          kept.push_back(e);
      }
    return kept;
  }

  std::map<std::string, std::map<std::string, unsigned int>>
  ModelSwitching::counts() const
  {
    std::map<std::string, std::map<std::string, unsigned int>> c;
    for (const SwitchingSurface &s : filippov->switching_surfaces())
      c[s.name];
    for (const SwitchingEvent &e : events())
      ++c[filippov->switching_surfaces()[e.surface].name][switching_class_name(e.kind)];
    return c;
  }
} // namespace poundfe
