// The Filippov switching analysis of a small model (integration/
// filippov.h): the state x = (u, v) of the model's n equations and
//   x' = (v, M^-1 (p(t) - C v - K u - f_s(u, v) - f_g(u, v, s) - f_f(u, v, s))),
// f_s the elastic springs, f_g the contacts, f_f the friction elements; the
// sides s of the switching surfaces (each linear in x):
//   gap j         g_j = d_j(u) - gap_j = 0 (d_j the closure): s = +1 in
//                 contact (the law's force), -1 open (none);
//   gap j's rate  d_j(v) = 0, watched in contact only (s > 0 on g_j): the
//                 deepest penetration, where a law whose damping acts on
//                 approach only (Jankowski 2005) changes branch (the thesis's
//                 g2 of Fig. 3.7 and Table 3.1); the field does not depend on
//                 this side;
//   friction k    r'_k = v_k - v0_k = 0 (the slip velocity against the belt):
//                 f_f = s mu N(u, v), mu = mu(r'_k) (kinetic, or Stribeck)
//                 in slip and mu = mu_s for the two fields on the surface
//                 (normal components, sliding field): the stick set of
//                 Filippov's convex method is bounded by the static
//                 coefficient (the switch model of Leine, van Campen, de
//                 Kraker & van den Steen 1998), and a slip that leaves it
//                 starts with the kinetic one.
// Stick is then Filippov's attracting sliding on r' = 0, with lambda = a /
// (a - b): the friction force of the convex combination, mu_s N (1 - 2
// lambda), is the reaction that keeps r' = 0, and the stick ends (sliding
// exit) when it reaches +-mu_s N.
// Sources: A.F. Filippov 1988, §2.2; R.I. Leine, D.H. van Campen, A. de
// Kraker & L. van den Steen, Nonlinear Dynamics 16 (1998) 41-54 (the switch
// model); R. Jankowski, Earthquake Eng. Struct. Dyn. 34 (2005) 595-611; the
// thesis, §3.3.4 and Fig. 3.7; doc/theory.md §1.19.
#ifndef poundfe_integration_model_switching_h
#define poundfe_integration_model_switching_h

#include <poundfe/assembly/linear_system.h>
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/integration/filippov.h>
#include <poundfe/integration/time_stepper.h>
#include <poundfe/model/model.h>

#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  class ModelSwitching
  {
  public:
    /// Why the analysis cannot take this model (more than max_equations
    /// equations, an equation without mass, an element other than a
    /// contact, an elastic spring or a friction element, a law whose force
    /// needs more than the state); empty when it can.
    static std::string unsupported(const LinearSystem &system, const Model &model,
                                   const NonlinearElements &elements, unsigned int max_equations);

    /// `elements` are evaluated (set_trial, revert), never committed.
    ModelSwitching(const LinearSystem &system, const Model &model, NonlinearElements &elements,
                   LoadFunction load, const FilippovParameters &parameters);

    /// From (u0, v0) at t = 0 to t_end.
    void run(const Vector &u0, const Vector &v0, double t_end);

    /// The hits, without those of a gap's rate surface while the gap is open.
    std::vector<SwitchingEvent> events() const;
    /// Per surface name and class, how many of events().
    std::map<std::string, std::map<std::string, unsigned int>> counts() const;
    const FilippovSystem &system() const { return *filippov; }
    unsigned int n_equations() const { return n; }
    /// The surfaces' kinds: "gap", "rate" or "slip".
    const std::vector<std::string> &surface_kinds() const { return kinds; }

  private:
    void field(double t, const Vector &x, const std::vector<int> &sides, Vector &dx);

    const LinearSystem        &linear;
    NonlinearElements         &elements;
    LoadFunction               load;
    unsigned int               n = 0;
    Eigen::MatrixXd            mass_inverse;
    std::vector<std::string>   kinds;
    /// Per element: its surface (gap or slip; -1: a spring) and its friction law.
    std::vector<int>           surface_of;
    std::vector<std::unique_ptr<Friction>> friction;
    std::vector<FrictionLawParameters>     friction_laws;
    std::unique_ptr<FilippovSystem> filippov;
    Vector                     force, local_u, local_v, correction;
  };
} // namespace poundfe

#endif
