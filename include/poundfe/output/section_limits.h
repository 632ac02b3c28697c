// Limit states of the fibre sections of a member (doc/theory.md §13.5):
// at each integration point the peak curvature and its ductility
//   mu_kappa = max(kappa_max / kappa_y+, -kappa_min / kappa_y-),
// in space about each bending axis (kappa_z and kappa_y, each with its own
// yield curvatures, found on the section bent about that axis alone) and
// mu_kappa the larger of the two,
// kappa_y± the first yield of a bar at the gravity axial force by the
// moment-curvature engine (sections/moment_curvature.h) bending either way,
// and the extreme fibre strains against four strain limits, after the
// limit states of Priestley, Calvi & Kowalsky (2007), Displacement-Based
// Seismic Design of Structures, IUSS Press, ch. 4 (their strain limits):
//   spalling  the most compressed concrete fibre reaches eps_sp (default
//             -0.004, their serviceability concrete strain),
//   crushing  the most compressed core fibre reaches eps_cu (default the
//             section's own crushing limit: Mander's eps_cu of the builders),
//   bar yield a steel fibre reaches +-eps_y (default the law's fy / E),
//   fracture  a steel fibre reaches eps_f in tension (default 0.6 eps_su,
//             their damage-control steel strain, eps_su the bar's rupture
//             strain; 0.05 without one).
// The first time of each is interpolated linearly within the step that
// reaches it. The damage state of a section is the worst limit it reached,
// in the order none < yield < spalling < crushing < fracture.
#ifndef poundfe_output_section_limits_h
#define poundfe_output_section_limits_h

#include <poundfe/base/input_file.h>
#include <poundfe/sections/fibre_section.h>

#include <array>
#include <limits>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  /// The limits in the order of their damage state.
  enum class SectionLimit : unsigned int
  {
    bar_yield,
    spalling,
    crushing,
    bar_fracture
  };
  constexpr unsigned int n_section_limits = 4;
  /// "bar_yield", "spalling", "crushing", "bar_fracture".
  const char *section_limit_name(SectionLimit limit);
  /// The damage state after the worst limit reached (-1: none): "none",
  /// "yield", "spalling", "crushing", "fracture".
  const char *damage_state_name(int worst_limit);

  /// The `Section limits` section: each strain limit given, or NaN (the
  /// section's own).
  struct SectionLimitParameters
  {
    double      spalling_strain = -0.004;
    std::string crushing_text = "section", yield_text = "section", fracture_text = "section";
    double      crushing_strain = std::numeric_limits<double>::quiet_NaN(); // < 0
    double      yield_strain    = std::numeric_limits<double>::quiet_NaN(); // > 0
    double      fracture_strain = std::numeric_limits<double>::quiet_NaN(); // > 0

    /// Declare the section (entered and left here).
    void declare(dealii::ParameterHandler &prm);
    /// Parse the texts; InputError naming the entry for a limit of the
    /// wrong sign, zero or not a number.
    void finalize(const InputFile &input);
  };

  /// The limits of one section, signed (compression negative); NaN: not
  /// checked (no core fibres with a crushing limit, no steel).
  struct SectionStrainLimits
  {
    std::array<double, n_section_limits> strain;
    /// kappa_y for positive and negative curvature (1/m, both > 0); about
    /// z in space.
    double yield_curvature_positive = 0, yield_curvature_negative = 0;
    /// A section in space: the same about its local y axis (0 in the plane).
    double yield_curvature_y_positive = 0, yield_curvature_y_negative = 0;
  };

  /// The bending axis of a section in space (the plane's is z).
  enum class BendingAxis
  {
    z,
    y
  };

  /// The section's limits: the parameters' where given, else its own.
  SectionStrainLimits section_strain_limits(const FibreSection &section,
                                            const SectionLimitParameters &parameters);
  /// kappa_y at the axial force N bending one way (+1: positive curvature,
  /// -1: negative), by the moment-curvature engine on a clone (the first
  /// yield of a bar at `yield_strain`, the curve stopped there); without a
  /// yield before the curve ends, Priestley et al.'s 2.1 eps_y / h (h: the
  /// fibres' depth). In space about `axis` (y: the fibres' z taken as
  /// their depth, kappa_y positive where z > 0 stretches).
  double section_yield_curvature(const FibreSection &section, double axial_force,
                                 double yield_strain, int sense,
                                 BendingAxis axis = BendingAxis::z);

  /// EA: the fibres' areas times their laws' initial moduli (the scale of
  /// the axial force that moves kappa_y, SectionLimitStates).
  double section_axial_stiffness(const FibreSection &section);

  /// What each fibre of a section is for the limits: concrete, core (a
  /// concrete with a crushing limit, SectionMaterial::min_strain), steel.
  enum class FibreKind : unsigned char
  {
    other,
    concrete,
    core,
    steel
  };
  std::vector<FibreKind> fibre_kinds(const FibreGeometry &geometry);

  /// The extreme strains of a section's fibres: the most compressed
  /// concrete fibre (core included), the most compressed core fibre (any
  /// concrete without core), the extreme steel strains (0: none such).
  struct ExtremeStrains
  {
    double concrete = 0, core = 0, steel_max = 0, steel_min = 0;
  };
  ExtremeStrains extreme_strains(const FibreSection &section, const std::vector<FibreKind> &kinds);

  /// The peaks and first times of one section over a run.
  class SectionLimitTracker
  {
  public:
    SectionLimitTracker(const FibreSection &section, const SectionStrainLimits &limits);

    /// The section's state at `time` (after each accepted step or substep).
    void observe(const FibreSection &section, double time);

    /// kappa_y± (from section_yield_curvature at the gravity state, or at
    /// the current axial force: SectionLimitStates::follow_axial_force);
    /// the states observed from now on are measured against them.
    void set_yield_curvatures(double positive, double negative);
    /// The same about y (a section in space).
    void set_yield_curvatures_y(double positive, double negative);

    const SectionStrainLimits &limits() const { return strain_limits; }
    double peak_curvature_positive() const { return kappa_max; }
    double peak_curvature_negative() const { return kappa_min; }
    /// About y (a section in space; 0 in the plane).
    double peak_curvature_y_positive() const { return kappa_y_max; }
    double peak_curvature_y_negative() const { return kappa_y_min; }
    /// mu_kappa: the largest over the states observed of kappa / kappa_y+
    /// and -kappa / kappa_y-, each with the yield curvatures set when it
    /// was observed (fixed ones: max(kappa_max / kappa_y+, -kappa_min /
    /// kappa_y-)); in space the larger of the two axes'; NaN without yield
    /// curvatures (no bars).
    double curvature_ductility() const;
    /// Whether the section is in space (N, Mz, My, T).
    bool in_space() const { return space; }
    /// About z alone, and about y alone (NaN in the plane).
    double curvature_ductility_z() const;
    double curvature_ductility_y() const;
    /// The peak extreme strains (concrete, core, steel_min most negative).
    const ExtremeStrains &peaks() const { return peak; }
    /// The peak demand of limit l over its limit strain (NaN: not checked).
    double ratio(SectionLimit l) const;
    /// When limit l was first reached (NaN: never).
    double first_time(SectionLimit l) const { return first[static_cast<unsigned int>(l)]; }
    /// The worst limit reached (-1: none).
    int worst_limit() const;

  private:
    /// The demand on limit l in the limit's sign: the extreme strain it is
    /// checked against.
    double demand(const ExtremeStrains &strains, unsigned int l) const;

    std::vector<FibreKind>               kinds;
    SectionStrainLimits                  strain_limits;
    double                               kappa_max = 0, kappa_min = 0, ductility = 0;
    double                               kappa_y_max = 0, kappa_y_min = 0, ductility_y = 0;
    bool                                 space = false; // a section in space
    ExtremeStrains                       peak, previous;
    double                               previous_time = 0;
    bool                                 started       = false;
    std::array<double, n_section_limits> first;
  };
} // namespace poundfe

#endif
