// Filippov systems: a first-order system x' = f(t, x, s) whose field
// depends on the side s_j = sgn h_j(x) of each switching surface
// h_j(x) = n_j . x - c_j = 0 (a relay; a block on a moving belt, whose
// surface is the relative slip velocity x' - v_0 = 0). At each hit of a
// surface j the normal components of the fields on both sides,
//   a = n_j . f(x, s_j = -1),   b = n_j . f(x, s_j = +1),
// decide (Filippov 1988, §2.2; di Bernardo et al. 2008, §2.3):
//   a b > 0          transversal crossing,
//   a > 0 > b        attracting sliding: the motion stays on the surface
//                    with Filippov's convex combination
//                      f_s = (1 - lambda) f_- + lambda f_+,
//                      lambda = a / (a - b) in (0, 1), so n . f_s = 0,
//                    until a or b vanishes (it leaves tangentially into
//                    the side whose field no longer points to the surface),
//   a < 0 < b        repulsive sliding (both fields leave the surface; the
//                    motion continues on the side it was heading to),
//   a = 0 or b = 0   grazing (tangency), to a tolerance.
// The smooth segments are integrated by the Dormand–Prince 5(4) step with
// dense output (dormand_prince.h); each hit or sliding exit is located on
// the dense output by bisection of the event function's sign, and the step
// redone to end there. One surface slides at a time.
// Sources: A.F. Filippov, Differential Equations with Discontinuous
// Righthand Sides, Kluwer 1988; M. di Bernardo, C.J. Budd, A.R. Champneys
// & P. Kowalczyk, Piecewise-smooth Dynamical Systems, Springer 2008,
// §2.3-2.4; the thesis, ch. 3 (§3.3.1, Table 3.2).
#ifndef poundfe_integration_filippov_h
#define poundfe_integration_filippov_h

#include <poundfe/integration/dormand_prince.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace poundfe
{
  struct SwitchingSurface
  {
    std::string name;
    Vector      normal; // n_j
    double      offset = 0; // c_j: h_j(x) = n_j . x - c_j
  };

  enum class SwitchingClass
  {
    crossing,
    attracting_sliding,
    repulsive_sliding,
    grazing,
    sliding_exit
  };

  const char *switching_class_name(SwitchingClass kind);

  /// The class of a hit from the normal components a (side -) and b (side
  /// +), with |a| or |b| <= tolerance * max(|a|, |b|) a tangency.
  SwitchingClass classify_switching(double a, double b, double tolerance);

  struct SwitchingEvent
  {
    double         time = 0;
    Vector         state;
    unsigned int   surface = 0;
    /// -1, +1: the side; 0: sliding on the surface.
    int            region_before = 0, region_after = 0;
    double         value = 0; // h_j at the located event
    double         normal_minus = 0, normal_plus = 0; // a, b
    SwitchingClass kind = SwitchingClass::crossing;
  };

  struct FilippovParameters
  {
    double relative_tolerance = 1e-10;
    double absolute_tolerance = 1e-12;
    double grazing_tolerance  = 1e-8; // relative, of the normal components
    double event_resolution   = 1e-12; // s, times max(1, t)
    unsigned long max_steps   = 10000000;
    /// > 0: the state sampled every this many seconds on the dense output
    /// (samples()), for plots.
    double        sample_interval = 0;
  };

  /// A state of the trajectory at a sample time, and the surface it slides
  /// on then (-1: none).
  struct SwitchingSample
  {
    double time = 0;
    Vector state;
    int    sliding = -1;
  };

  class FilippovSystem
  {
  public:
    /// f(t, x, s): the field on the sides s (one +-1 per surface).
    using Field = std::function<void(double, const Vector &, const std::vector<int> &, Vector &)>;

    FilippovSystem(std::vector<SwitchingSurface> surfaces, Field field,
                   const FilippovParameters &parameters = FilippovParameters());

    /// From x0 at t = 0 to t_end; a start on a surface is classified as a hit.
    void run(const Vector &x0, double t_end);

    const Vector &state() const { return x; }
    const std::vector<SwitchingEvent> &log() const { return events; }
    /// Every sample_interval from t = 0 (empty when it is 0).
    const std::vector<SwitchingSample> &samples() const { return sampled; }
    const std::vector<SwitchingSurface> &switching_surfaces() const { return surfaces; }
    /// The surface whose two one-sided fields are being evaluated on it
    /// (the normal components, the sliding field), or -1: a field may
    /// differ on the surface (static friction) from its side's limit.
    int surface_evaluated() const { return evaluated; }
    /// Per surface name and class name, how many hits.
    std::map<std::string, std::map<std::string, unsigned int>> counts() const;
    /// The switching log: time, state, surface, regions, h, a, b, class.
    std::string log_csv() const;

  private:
    double value(unsigned int j, const Vector &state) const;
    /// a and b of surface j at (t, state), the other sides as they are.
    std::pair<double, double> normal_components(unsigned int j, double t, const Vector &state);
    void   rhs(double t, const Vector &state, Vector &dx);
    /// The signs the step's events watch: each surface's h, or, sliding on
    /// j, the signs of a and b (h_j is then 0).
    void   indicators(double t, const Vector &state, std::vector<int> &out);
    /// A hit of surface j (or the end of sliding on it) at (t, x).
    void   switch_at(unsigned int j, double t);
    /// The samples in (t0, t0 + h] of the step just taken, on its dense output.
    void   sample_step(double t0, double h);

    std::vector<SwitchingSurface> surfaces;
    Field                         field;
    FilippovParameters            parameters;
    DormandPrinceStep             step;
    Vector                        x, k1, f_minus, f_plus, trial;
    std::vector<int>              sides, trial_sides, watched, trial_watched;
    int                           sliding = -1; // the surface slid on, or -1
    int                           evaluated = -1;
    /// Per surface: the state left by its last event may lie a step's local
    /// error on the other side; until it leaves, that is no new hit.
    std::vector<bool>             just_switched;
    std::vector<SwitchingEvent>   events;
    std::vector<SwitchingSample>  sampled;
  };
} // namespace poundfe

#endif
