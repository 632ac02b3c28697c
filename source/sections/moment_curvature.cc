// Moment–curvature analysis of a fibre section at constant axial force
// (equations in the header; the method of e.g. Mander et al. 1988 §5 and
// OpenSees's MomentCurvature.tcl example, with Newton on eps0 instead of a
// load-controlled then displacement-controlled static analysis).
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/sections/moment_curvature.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace poundfe
{
  double
  MomentCurvatureResult::ductility() const
  {
    return yielded && first_yield.curvature > 0 ? ultimate.curvature / first_yield.curvature : 0;
  }

  namespace
  {
    /// A threshold of one material's fibres: `excess` >= 0 once reached.
    struct StrainWatch
    {
      std::string  what;
      unsigned int material;
      double       low, high; // reached when a strain <= low or >= high
      bool         ends;      // a failure limit: the curve ends there
      bool         fired = false;
    };

    class MomentCurvatureRun
    {
    public:
      MomentCurvatureRun(FibreSection &section, const MomentCurvatureSettings &settings);
      MomentCurvatureResult run();

    private:
      /// N(eps0, kappa) - N at the trial state it leaves; ok false if a fibre refuses.
      double residual(double x, double curvature, bool &ok);
      /// Sets the trial state in equilibrium at `curvature`: Newton on eps0,
      /// bisection where Newton cannot (softening); false if none is found.
      bool solve(double curvature);
      bool bracket_and_bisect(double curvature, double below, double above);
      MomentCurvaturePoint point() const;
      double excess(const StrainWatch &w) const;
      /// The curvature in (from, to] where w is first reached, the section
      /// left in that trial state.
      double locate(const StrainWatch &w, double from, double to);
      /// Fires the watches reached in the step (from, to]; true if the
      /// curve ends (its last point then appended).
      bool check_watches(double from, double to);
      void add_watches();
      /// Whether the curve ends at its new point p (the reason kept).
      bool ends_at(const MomentCurvaturePoint &p);

      FibreSection                  &section;
      const MomentCurvatureSettings &settings;
      const double                   c, s; // the direction of the curvature
      double                         force_scale = 0;
      double                         eps0        = 0; // Newton's start: the last solution
      double                         committed_eps0 = 0; // eps0 of the committed state
      std::vector<StrainWatch>       watches;
      std::string                    refusal; // the last fibre that refused its strain
      MomentCurvatureResult          result;
    };

    MomentCurvatureRun::MomentCurvatureRun(FibreSection &section,
                                           const MomentCurvatureSettings &settings)
      : section(section)
      , settings(settings)
      , c(std::cos(settings.angle * std::acos(-1.0) / 180))
      , s(section.n_resultants() == 4 ? std::sin(settings.angle * std::acos(-1.0) / 180) : 0.0)
    {
      Assert(settings.target_curvature > 0 && settings.steps > 0, dealii::ExcInternalError());
      section.reset();
      const FibreGeometry &g = section.geometry();
      for (unsigned int i = 0; i < g.fibres.size(); ++i)
        force_scale += g.fibres[i].area * section.fibre_material(i).initial_stiffness() * 1e-3;
      force_scale = std::max(force_scale, std::abs(settings.axial_force));
      add_watches();
    }

    void
    MomentCurvatureRun::add_watches()
    {
      const FibreGeometry &g   = section.geometry();
      const double         inf = std::numeric_limits<double>::infinity();
      for (unsigned int m = 0; m < g.materials.size(); ++m)
        {
          const SectionMaterial &material = g.materials[m];
          const auto fibre = std::find_if(g.fibres.begin(), g.fibres.end(),
                                          [&](const Fibre &f) { return f.material == m; });
          if (fibre == g.fibres.end())
            continue;
          const UniaxialLaw &law = section.fibre_material(fibre - g.fibres.begin());
          const double       ey  = law.yield_deformation();
          if (material.role() == MaterialRole::steel && ey > 0)
            watches.push_back({"first yield of " + material.name, m, -ey, ey, false});
          const auto epscu = material.law.values.find("epscu");
          if (material.role() == MaterialRole::concrete && epscu != material.law.values.end())
            watches.push_back({material.name + " reached epscu " + rounded(-std::abs(epscu->second), 4),
                               m, -std::abs(epscu->second), inf, false});
          const double low  = std::isnan(material.min_strain) ? -inf : material.min_strain;
          const double high = std::isnan(material.max_strain) ? inf : material.max_strain;
          if (low > -inf || high < inf)
            watches.push_back({material.name + " reached its strain limit", m, low, high, true});
        }
    }

    double
    MomentCurvatureRun::residual(const double x, const double curvature, bool &ok)
    {
      SectionVector e = SectionVector::Zero(section.n_resultants());
      e(0)            = x;
      e(1)            = curvature * c;
      if (e.size() == 4)
        e(2) = curvature * s;
      ok = section.set_trial(e);
      if (!ok)
        refusal = section.failure();
      return ok ? section.resultant()(0) - settings.axial_force : 0.0;
    }

    bool
    MomentCurvatureRun::solve(const double curvature)
    {
      // Newton, keeping the bracket of eps0 it passes on the way
      double x = eps0, below = -HUGE_VAL, above = HUGE_VAL;
      bool   ok = true;
      for (unsigned int it = 0; it < settings.max_iterations; ++it)
        {
          const double r = residual(x, curvature, ok);
          if (!ok)
            return false;
          if (std::abs(r) <= settings.tolerance * force_scale)
            return eps0 = x, true;
          (r < 0 ? below : above) = x;
          const double k = section.tangent()(0, 0);
          if (!(k > 0))
            break; // softening: N(eps0) falls here, Newton would climb away
          x -= r / k;
        }
      return bracket_and_bisect(curvature, below, above);
    }

    bool
    MomentCurvatureRun::bracket_and_bisect(const double curvature, double below, double above)
    {
      // widen the bracket from the last solution until N changes sign
      bool ok = true;
      for (double step = 1e-4; !(std::isfinite(below) && std::isfinite(above)) && step < 1;
           step *= 2)
        {
          const double x = std::isfinite(below) ? below + step : above - step;
          const double r = residual(x, curvature, ok);
          if (!ok)
            return false;
          (r < 0 ? below : above) = x;
        }
      if (!(std::isfinite(below) && std::isfinite(above)))
        return false;
      for (unsigned int it = 0; it < 200; ++it)
        {
          const double x = 0.5 * (below + above), r = residual(x, curvature, ok);
          if (!ok)
            return false;
          if (std::abs(r) <= settings.tolerance * force_scale)
            return eps0 = x, true;
          (r < 0 ? below : above) = x;
        }
      return false;
    }

    MomentCurvaturePoint
    MomentCurvatureRun::point() const
    {
      MomentCurvaturePoint p;
      const SectionVector &e = section.deformation();
      const SectionVector &r = section.resultant();
      const SectionMatrix &k = section.tangent();
      p.curvature    = e.size() == 4 ? c * e(1) + s * e(2) : e(1);
      p.axial_strain = e(0);
      p.moment_z     = r(1);
      p.moment_y     = r.size() == 4 ? r(2) : 0.0;
      p.moment       = c * p.moment_z + s * p.moment_y;
      const double k_k0 = c * k(1, 0) + (e.size() == 4 ? s * k(2, 0) : 0.0);
      const double k_kk = c * c * k(1, 1) +
                          (e.size() == 4 ? 2 * c * s * k(1, 2) + s * s * k(2, 2) : 0.0);
      // no axial stiffness left (every fibre on a plateau): eps0 is free and
      // the tangent at fixed eps0 stands in for the condensed one
      p.tangent = k(0, 0) > 0 ? k_kk - k_k0 * k_k0 / k(0, 0) : k_kk;
      const FibreGeometry &g = section.geometry();
      p.steel_strain_max     = -std::numeric_limits<double>::infinity();
      p.steel_strain_min     = std::numeric_limits<double>::infinity();
      p.concrete_strain      = std::numeric_limits<double>::infinity();
      bool steel = false, concrete = false;
      for (unsigned int i = 0; i < g.fibres.size(); ++i)
        {
          const MaterialRole role   = g.materials[g.fibres[i].material].role();
          const double       strain = section.fibre_strain(i);
          if (role == MaterialRole::concrete)
            {
              concrete          = true;
              p.concrete_strain = std::min(p.concrete_strain, strain);
            }
          else if (role == MaterialRole::steel)
            {
              steel              = true;
              p.steel_strain_max = std::max(p.steel_strain_max, strain);
              p.steel_strain_min = std::min(p.steel_strain_min, strain);
            }
        }
      if (!steel)
        p.steel_strain_max = p.steel_strain_min = 0;
      if (!concrete)
        p.concrete_strain = 0;
      return p;
    }

    double
    MomentCurvatureRun::excess(const StrainWatch &w) const
    {
      const FibreGeometry &g      = section.geometry();
      double               beyond = -std::numeric_limits<double>::infinity();
      for (unsigned int i = 0; i < g.fibres.size(); ++i)
        if (g.fibres[i].material == w.material)
          {
            const double strain = section.fibre_strain(i);
            beyond = std::max({beyond, w.low - strain, strain - w.high});
          }
      return beyond;
    }

    double
    MomentCurvatureRun::locate(const StrainWatch &w, double from, double to)
    {
      // the trial state at `to` has reached w, the committed one at `from` not
      double g_to = excess(w);
      // from the committed state's own eps0, its first trial is that state
      section.revert();
      eps0 = committed_eps0;
      AssertThrow(solve(from), dealii::ExcInternalError());
      double       g_from = excess(w);
      const double scale  = std::max(std::isfinite(w.low) ? std::abs(w.low) : 0.0,
                                     std::isfinite(w.high) ? std::abs(w.high) : 0.0);
      for (unsigned int it = 0; it < 100 && to - from > 1e-13 * to; ++it)
        {
          // the secant, kept off the ends so that it cannot stall at one
          const double middle =
            std::clamp(from + (to - from) * (-g_from) / (g_to - g_from),
                       from + 0.01 * (to - from), to - 0.01 * (to - from));
          section.revert();
          eps0 = committed_eps0;
          if (!solve(middle))
            break;
          const double g = excess(w);
          if (std::abs(g) <= 1e-11 * scale)
            return middle;
          (g < 0 ? from : to)     = middle;
          (g < 0 ? g_from : g_to) = g;
        }
      section.revert();
      eps0 = committed_eps0;
      AssertThrow(solve(to), dealii::ExcInternalError());
      return to;
    }

    bool
    MomentCurvatureRun::check_watches(const double from, const double to)
    {
      struct Reached
      {
        double               curvature;
        MomentCurvaturePoint at;
        StrainWatch         *watch;
      };
      std::vector<Reached> reached;
      const double         eps0_to = eps0; // the solution at `to`
      for (StrainWatch &w : watches)
        if (!w.fired && excess(w) >= 0)
          {
            const double k = locate(w, from, to);
            reached.push_back({k, point(), &w});
            section.revert();
            eps0 = eps0_to;
            AssertThrow(solve(to), dealii::ExcInternalError());
          }
      std::stable_sort(reached.begin(), reached.end(),
                [](const Reached &a, const Reached &b) { return a.curvature < b.curvature; });
      for (const Reached &r : reached)
        {
          r.watch->fired = true;
          result.events.push_back({r.watch->what, r.at});
          if (r.watch->what.rfind("first yield", 0) == 0 && !result.yielded)
            {
              result.yielded     = true;
              result.first_yield = r.at;
            }
          if (r.watch->ends)
            {
              result.points.push_back(r.at);
              result.stop_reason = r.watch->what;
              return true;
            }
        }
      return false;
    }

    bool
    MomentCurvatureRun::ends_at(const MomentCurvaturePoint &p)
    {
      if (settings.drop_fraction > 0 && p.moment < settings.drop_fraction * result.peak.moment)
        result.stop_reason =
          "the moment fell below " + number_text(settings.drop_fraction) + " of the peak";
      else if (settings.stop_steel_strain > 0 &&
               std::max(p.steel_strain_max, -p.steel_strain_min) >= settings.stop_steel_strain)
        result.stop_reason = "a steel strain reached " + number_text(settings.stop_steel_strain);
      return !result.stop_reason.empty();
    }

    MomentCurvatureResult
    MomentCurvatureRun::run()
    {
      if (!solve(0))
        throw InputError("", 0, "Axial force",
                         "the section cannot carry N = " + number_text(settings.axial_force) +
                           " N at zero curvature");
      section.commit();
      committed_eps0 = eps0;
      result.points.push_back(point());
      const double step = settings.target_curvature / settings.steps;
      double       done = 0;
      while (done < settings.target_curvature * (1 - 1e-12))
        {
          double next = std::min(done + step, settings.target_curvature);
          unsigned int cuts = 0;
          for (; !solve(next) && cuts < 10; ++cuts)
            {
              section.revert();
              next = done + (next - done) / 2;
            }
          if (cuts == 10)
            {
              section.revert();
              result.stop_reason = refusal.empty() ?
                                     "the section cannot carry N beyond this curvature" :
                                     "no equilibrium beyond this curvature: " + refusal;
              break;
            }
          if (check_watches(done, next))
            break;
          section.commit();
          committed_eps0 = eps0;
          done = next;
          result.points.push_back(point());
          const MomentCurvaturePoint &p = result.points.back();
          if (p.moment > result.peak.moment)
            result.peak = p;
          if (ends_at(p))
            break;
        }
      if (result.stop_reason.empty())
        result.stop_reason = "the target curvature";
      result.ultimate = result.points.back();
      if (result.ultimate.moment > result.peak.moment)
        result.peak = result.ultimate;
      return result;
    }
  } // namespace

  MomentCurvatureResult
  moment_curvature(FibreSection &section, const MomentCurvatureSettings &settings)
  {
    return MomentCurvatureRun(section, settings).run();
  }
} // namespace poundfe
