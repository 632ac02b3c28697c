// The limit states of a run's fibre members (output/section_limits.h): an
// observer that follows every integration point of every fibre member,
// plane or in space (about both bending axes),
// through the accepted steps and substeps, from the gravity state at t = 0
// (where each section's yield curvature is found at its own axial force),
// and reports per member the worst over its sections, and per storey the
// damage state of its worst member (the columns below a floor and the
// beams of that floor make a storey). The pushover keeps one after its
// elements are gone: its records (peaks, first times, damage states) need
// no element; only observing does.
#ifndef poundfe_output_section_limit_states_h
#define poundfe_output_section_limit_states_h

#include <poundfe/elements/member_element.h>
#include <poundfe/output/observer.h>
#include <poundfe/output/section_limits.h>

#include <string>
#include <vector>

namespace poundfe
{
  class JsonWriter;

  class SectionLimitStates : public StepObserver
  {
  public:
    /// The sections of a member and where it stands.
    struct MemberLimits
    {
      const NonlinearElement          *element = nullptr; // a MemberElement<2> or <3>
      std::string                      label;
      unsigned int                     building = 0, storey = 1; // storey: 1-based
      std::vector<SectionLimitTracker> sections;                 // one per integration point
      /// Per section: the axial force its kappa_y± (both axes) were found
      /// at (NaN: not yet) and the change of it that finds them again.
      std::vector<double> yield_axial_force, axial_force_tolerance;
      /// The worst limit over its sections (-1: none).
      int worst_limit() const;
    };

    /// Every member of `elements` on fibre sections (none: empty()).
    SectionLimitStates(const Model &model, const NonlinearElements &elements,
                       const SectionLimitParameters &parameters);

    bool empty() const { return limits.empty(); }
    /// From now on, each state observed first finds every section's yield
    /// curvatures again at its current axial force (a pushover: the
    /// columns' axial forces change with the overturning moment), so that
    /// its ductility is measured against the yield curvature of that
    /// state; without it they stay those of the state initialize() saw.
    /// Found again only once N has moved by more than
    /// `yield_force_tolerance` EA eps_y since they were last found (EA the
    /// section's initial axial stiffness, eps_y its bar yield strain), so
    /// that kappa_y± stay within 1e-3 of those at the current N: an
    /// uncracked elastic section yields at kappa_y = (eps_y - N / EA) / y_s
    /// (y_s the extreme bar's distance), so a change dN moves kappa_y by
    /// dN / (EA eps_y - N) of itself, 1e-4 / (1 - N / (EA eps_y)); an RC
    /// section, cracked at yield, is up to 5.3 times as sensitive (the RC
    /// column of unit/output from -1.5 MN to +100 kN): 5.3e-4 at most.
    void follow_axial_force() { axial_force_followed = true; }
    static constexpr double yield_force_tolerance = 1e-4;
    /// The yield curvatures at the state given (the gravity state), then
    /// its strains.
    void initialize(const ResponseView &state) override { initialize_at(state.time()); }
    void observe_step(const ResponseView &state) override { observe_at(state.time()); }
    void observe_substep(const ResponseView &state) override { observe_step(state); }
    /// The same at the members' current state, `when` the time of a run or
    /// the control displacement of a pushover (the first times' axis).
    void initialize_at(double when);
    void observe_at(double when);

    const std::vector<MemberLimits> &members() const { return limits; }
    /// Building b's worst limit per storey (-1: none), bottom up.
    std::vector<int> storey_worst_limits(const Model &model, unsigned int b) const;
    /// "section_limit_states" of summary.json: the limits' definitions, and
    /// per member its peaks, ratios, first times and damage state; each
    /// limit's first time under the key `first_key` (a pushover's is a
    /// control displacement).
    void write_json(JsonWriter &json, const Model &model,
                    const std::string &first_key = "first_time_s") const;

  private:
    /// Each section's kappa_y± at its current axial force.
    void find_yield_curvatures();

    std::vector<MemberLimits> limits;
    bool                      axial_force_followed = false;
  };
} // namespace poundfe

#endif
