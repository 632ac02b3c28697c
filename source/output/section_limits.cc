// The limit states of fibre sections (output/section_limits.h): the
// `Section limits` entries, each section's limits and yield curvature, and
// the tracker of its peaks and first times.
#include <poundfe/output/section_limits.h>
#include <poundfe/output/section_states.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/elements/member_element.h>
#include <poundfe/sections/moment_curvature.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace poundfe
{
  namespace
  {
    constexpr double not_checked = std::numeric_limits<double>::quiet_NaN();

    /// A limit's entry: "section" (NaN) or a number of the limit's sign.
    double
    limit_from_text(const InputFile &input, const std::string &entry, const std::string &text,
                    const double sign)
    {
      const std::string t = trimmed(text);
      if (t == "section")
        return not_checked;
      char        *end   = nullptr;
      const double value = std::strtod(t.c_str(), &end);
      if (t.empty() || end != t.c_str() + t.size() || !std::isfinite(value))
        input.fail("Section limits/" + entry, "'" + text + "' is neither 'section' nor a number");
      if (!(value * sign > 0))
        input.fail("Section limits/" + entry, "'" + text + "' must be " +
                                                (sign > 0 ? "positive (tension)" :
                                                            "negative (compression)"));
      return value;
    }

    /// The yield strain of the section's first steel fibre's law (0: no steel).
    double
    law_yield_strain(const FibreSection &section, const std::vector<FibreKind> &kinds)
    {
      for (unsigned int i = 0; i < kinds.size(); ++i)
        if (kinds[i] == FibreKind::steel)
          return section.fibre_material(i).yield_deformation();
      return 0;
    }

    bool
    has(const std::vector<FibreKind> &kinds, const FibreKind kind)
    {
      return std::find(kinds.begin(), kinds.end(), kind) != kinds.end();
    }

    /// The fibres as a plane section bending one way about `axis`: about z
    /// its fibres' y (sense -1: y -> -y, whose positive curvature is the
    /// original's negative one); about y their depth -z (a fibre's strain
    /// is eps0 + z kappa_y, the plane's eps0 - y kappa), sense -1: +z.
    FibreGeometry
    bent_about(const FibreGeometry &geometry, const BendingAxis axis, const int sense)
    {
      FibreGeometry m = geometry;
      for (Fibre &f : m.fibres)
        {
          const double depth = axis == BendingAxis::z ? f.y : -f.z;
          f.y                = sense > 0 ? depth : -depth;
          f.z                = 0;
        }
      return m;
    }

    double
    depth_of(const FibreGeometry &geometry)
    {
      double low = 0, high = 0;
      for (unsigned int i = 0; i < geometry.fibres.size(); ++i)
        {
          low  = i ? std::min(low, geometry.fibres[i].y) : geometry.fibres[i].y;
          high = i ? std::max(high, geometry.fibres[i].y) : geometry.fibres[i].y;
        }
      return high - low;
    }
  } // namespace

  const char *
  section_limit_name(const SectionLimit limit)
  {
    static const char *names[] = {"bar_yield", "spalling", "crushing", "bar_fracture"};
    return names[static_cast<unsigned int>(limit)];
  }

  const char *
  damage_state_name(const int worst_limit)
  {
    static const char *names[] = {"none", "yield", "spalling", "crushing", "fracture"};
    Assert(worst_limit >= -1 && worst_limit < int(n_section_limits), dealii::ExcInternalError());
    return names[worst_limit + 1];
  }

  void
  SectionLimitParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Section limits");
    prm.add_parameter("Spalling strain", spalling_strain,
                      "Compressive strain of the most compressed concrete fibre at which the "
                      "cover spalls (negative; Priestley, Calvi & Kowalsky 2007: -0.004). "
                      "Unit: dimensionless.");
    prm.add_parameter("Crushing strain", crushing_text,
                      "Compressive strain of the most compressed core fibre at which the core "
                      "crushes (negative), or 'section': the section's own crushing limit (the "
                      "builders' Mander eps_cu, a material's min=). Unit: dimensionless.");
    prm.add_parameter("Bar yield strain", yield_text,
                      "Strain magnitude at which a bar yields (positive), or 'section': its "
                      "law's fy / E. Unit: dimensionless.");
    prm.add_parameter("Bar fracture strain", fracture_text,
                      "Tensile strain at which a bar fractures (positive), or 'section': 0.6 "
                      "eps_su of the bar's rupture strain (Priestley, Calvi & Kowalsky 2007), "
                      "0.05 without one. Unit: dimensionless.");
    prm.leave_subsection();
  }

  void
  SectionLimitParameters::finalize(const InputFile &input)
  {
    if (!(spalling_strain < 0))
      input.fail("Section limits/Spalling strain",
                 number_text(spalling_strain) + " must be negative (compression)");
    crushing_strain = limit_from_text(input, "Crushing strain", crushing_text, -1);
    yield_strain    = limit_from_text(input, "Bar yield strain", yield_text, +1);
    fracture_strain = limit_from_text(input, "Bar fracture strain", fracture_text, +1);
  }

  std::vector<FibreKind>
  fibre_kinds(const FibreGeometry &geometry)
  {
    std::vector<FibreKind> kinds;
    for (const Fibre &fibre : geometry.fibres)
      {
        const SectionMaterial &m = geometry.materials[fibre.material];
        switch (m.role())
          {
            case MaterialRole::concrete:
              kinds.push_back(std::isnan(m.min_strain) ? FibreKind::concrete : FibreKind::core);
              break;
            case MaterialRole::steel:
              kinds.push_back(FibreKind::steel);
              break;
            default:
              kinds.push_back(FibreKind::other);
          }
      }
    return kinds;
  }

  ExtremeStrains
  extreme_strains(const FibreSection &section, const std::vector<FibreKind> &kinds)
  {
    ExtremeStrains e;
    bool           concrete = false, core = false, steel = false;
    for (unsigned int i = 0; i < kinds.size(); ++i)
      {
        const double eps = section.fibre_strain(i);
        if (kinds[i] == FibreKind::concrete || kinds[i] == FibreKind::core)
          {
            e.concrete = concrete ? std::min(e.concrete, eps) : eps;
            concrete   = true;
          }
        if (kinds[i] == FibreKind::core)
          {
            e.core = core ? std::min(e.core, eps) : eps;
            core   = true;
          }
        if (kinds[i] == FibreKind::steel)
          {
            e.steel_max = steel ? std::max(e.steel_max, eps) : eps;
            e.steel_min = steel ? std::min(e.steel_min, eps) : eps;
            steel       = true;
          }
      }
    if (!core) // no concrete with a crushing limit: a given one applies to all
      e.core = e.concrete;
    return e;
  }

  const FibreSection *
  fibre_section_of(const NonlinearElement &element, const unsigned int i)
  {
    const auto at = [i](const auto *member) -> const FibreSection * {
      return member && i < member->member().n_points() ?
               dynamic_cast<const FibreSection *>(&member->member().section(i)) :
               nullptr;
    };
    if (const auto *plane = dynamic_cast<const MemberElement<2> *>(&element))
      return at(plane);
    return at(dynamic_cast<const MemberElement<3> *>(&element));
  }

  BeamIntegration
  fibre_member_integration(const FibreMember &fibre)
  {
    return fibre.force_based ? lobatto_integration(fibre.n_points) :
                               legendre_integration(fibre.n_points);
  }

  SectionStateEntries
  section_state_entries(const FibreSection &section, const std::vector<FibreKind> &kinds)
  {
    const ExtremeStrains e = extreme_strains(section, kinds);
    return {{section.resultant()[0], section.resultant()[1], section.deformation()[0],
             section.deformation()[1], e.concrete, e.steel_max, e.steel_min}};
  }

  unsigned int
  n_section_state_values(const FibreSection &section)
  {
    return n_section_state_entries + (section.n_resultants() == 4 ? 2 : 0);
  }

  void
  section_state_values(const FibreSection &section, const std::vector<FibreKind> &kinds,
                       double *to)
  {
    const SectionStateEntries entries = section_state_entries(section, kinds);
    std::copy(entries.begin(), entries.end(), to);
    if (section.n_resultants() == 4) // (N, Mz, My, T), (eps0, kz, ky, theta)
      {
        to[n_section_state_entries]     = section.resultant()[2];
        to[n_section_state_entries + 1] = section.deformation()[2];
      }
  }

  SectionStrainLimits
  section_strain_limits(const FibreSection &section, const SectionLimitParameters &parameters)
  {
    const FibreGeometry         &g     = section.geometry();
    const std::vector<FibreKind> kinds = fibre_kinds(g);
    const bool concrete = has(kinds, FibreKind::concrete) || has(kinds, FibreKind::core);
    const bool steel    = has(kinds, FibreKind::steel);
    double     own_crushing = 0, own_rupture = 0; // the first reached of the section's own
    for (unsigned int i = 0; i < kinds.size(); ++i)
      {
        const SectionMaterial &m = g.materials[g.fibres[i].material];
        if (kinds[i] == FibreKind::core)
          own_crushing = own_crushing == 0 ? m.min_strain : std::max(own_crushing, m.min_strain);
        if (kinds[i] == FibreKind::steel && m.max_strain > 0)
          own_rupture = own_rupture == 0 ? m.max_strain : std::min(own_rupture, m.max_strain);
      }
    SectionStrainLimits l;
    auto &s = l.strain;
    s[unsigned(SectionLimit::spalling)] = concrete ? parameters.spalling_strain : not_checked;
    s[unsigned(SectionLimit::crushing)] = // a given limit: on every concrete fibre without core
      !concrete || (!has(kinds, FibreKind::core) && std::isnan(parameters.crushing_strain)) ?
      not_checked :
      std::isnan(parameters.crushing_strain) ? own_crushing : parameters.crushing_strain;
    const double yield = std::isnan(parameters.yield_strain) ? law_yield_strain(section, kinds) :
                                                               parameters.yield_strain;
    s[unsigned(SectionLimit::bar_yield)] = steel && yield > 0 ? yield : not_checked;
    s[unsigned(SectionLimit::bar_fracture)] =
      !steel ? not_checked :
      !std::isnan(parameters.fracture_strain) ? parameters.fracture_strain :
      own_rupture > 0                          ? 0.6 * own_rupture :
                                                 0.05;
    return l;
  }

  double
  section_yield_curvature(const FibreSection &section, const double axial_force,
                          const double yield_strain, const int sense, const BendingAxis axis)
  {
    const FibreGeometry g     = bent_about(section.geometry(), axis, sense);
    const double        depth = depth_of(g);
    Assert(yield_strain > 0 && depth > 0, dealii::ExcInternalError());
    const double estimate = 2.1 * yield_strain / depth; // Priestley et al. (2007) §4.2
    FibreSection bending(g, 2);
    MomentCurvatureSettings settings;
    settings.axial_force      = axial_force;
    settings.target_curvature = 10 * estimate;
    settings.steps            = 400;
    settings.drop_fraction    = 0;
    // the points up to the first yield are those of the whole curve: the
    // same kappa_y at a tenth of the cost (the curve ran to 10 estimates)
    settings.stop_steel_strain = yield_strain;
    MomentCurvatureResult result;
    try
      {
        result = moment_curvature(bending, settings);
      }
    catch (const InputError &) // N beyond the section's capacity
      {
        return estimate;
      }
    const auto &p = result.points;
    for (unsigned int k = 1; k < p.size(); ++k)
      {
        const double now  = std::max(p[k].steel_strain_max, -p[k].steel_strain_min);
        const double then = std::max(p[k - 1].steel_strain_max, -p[k - 1].steel_strain_min);
        if (now >= yield_strain)
          {
            const double s = now > then ? (yield_strain - then) / (now - then) : 1;
            return p[k - 1].curvature + std::clamp(s, 0.0, 1.0) *
                                          (p[k].curvature - p[k - 1].curvature);
          }
      }
    return estimate;
  }

  double
  section_axial_stiffness(const FibreSection &section)
  {
    const FibreGeometry &g  = section.geometry();
    double               ea = 0;
    for (unsigned int i = 0; i < g.fibres.size(); ++i)
      ea += g.fibres[i].area * section.fibre_material(i).initial_stiffness();
    return ea;
  }

  SectionLimitTracker::SectionLimitTracker(const FibreSection        &section,
                                           const SectionStrainLimits &limits)
    : kinds(fibre_kinds(section.geometry()))
    , strain_limits(limits)
    , space(section.n_resultants() == 4)
  {
    first.fill(not_checked);
  }

  void
  SectionLimitTracker::set_yield_curvatures(const double positive, const double negative)
  {
    Assert(positive > 0 && negative > 0, dealii::ExcInternalError());
    strain_limits.yield_curvature_positive = positive;
    strain_limits.yield_curvature_negative = negative;
  }

  void
  SectionLimitTracker::set_yield_curvatures_y(const double positive, const double negative)
  {
    Assert(space && positive > 0 && negative > 0, dealii::ExcInternalError());
    strain_limits.yield_curvature_y_positive = positive;
    strain_limits.yield_curvature_y_negative = negative;
  }

  double
  SectionLimitTracker::demand(const ExtremeStrains &e, const unsigned int l) const
  {
    switch (static_cast<SectionLimit>(l))
      {
        case SectionLimit::spalling:
          return e.concrete;
        case SectionLimit::crushing:
          return e.core;
        case SectionLimit::bar_yield:
          return std::max(e.steel_max, -e.steel_min);
        case SectionLimit::bar_fracture:
          return e.steel_max;
      }
    return 0;
  }

  void
  SectionLimitTracker::observe(const FibreSection &section, const double time)
  {
    // against the yield curvatures of this state
    const auto follow = [](const double kappa, const double up, const double down, double &high,
                           double &low, double &mu) {
      high = std::max(high, kappa);
      low  = std::min(low, kappa);
      if (up > 0 && down > 0)
        mu = std::max({mu, kappa / up, -kappa / down});
    };
    const SectionStrainLimits &l = strain_limits;
    follow(section.deformation()[1], l.yield_curvature_positive, l.yield_curvature_negative,
           kappa_max, kappa_min, ductility);
    if (space) // (eps0, kappa_z, kappa_y, theta)
      follow(section.deformation()[2], l.yield_curvature_y_positive,
             l.yield_curvature_y_negative, kappa_y_max, kappa_y_min, ductility_y);
    const ExtremeStrains now = extreme_strains(section, kinds);
    peak.concrete  = std::min(peak.concrete, now.concrete);
    peak.core      = std::min(peak.core, now.core);
    peak.steel_max = std::max(peak.steel_max, now.steel_max);
    peak.steel_min = std::min(peak.steel_min, now.steel_min);
    for (unsigned int l = 0; l < n_section_limits; ++l)
      {
        const double limit = strain_limits.strain[l];
        if (std::isnan(limit) || !std::isnan(first[l]))
          continue;
        const double r = demand(now, l) / limit;
        if (r < 1)
          continue;
        const double r0 = started ? demand(previous, l) / limit : r;
        const double s  = r > r0 ? std::clamp((1 - r0) / (r - r0), 0.0, 1.0) : 1.0;
        first[l]        = started ? previous_time + s * (time - previous_time) : time;
      }
    previous      = now;
    previous_time = time;
    started       = true;
  }

  double
  SectionLimitTracker::curvature_ductility_z() const
  {
    const double up   = strain_limits.yield_curvature_positive;
    const double down = strain_limits.yield_curvature_negative;
    if (!(up > 0 && down > 0)) // a section without bars
      return std::numeric_limits<double>::quiet_NaN();
    return ductility;
  }

  double
  SectionLimitTracker::curvature_ductility_y() const
  {
    const double up   = strain_limits.yield_curvature_y_positive;
    const double down = strain_limits.yield_curvature_y_negative;
    if (!(space && up > 0 && down > 0)) // in the plane, or without bars
      return std::numeric_limits<double>::quiet_NaN();
    return ductility_y;
  }

  double
  SectionLimitTracker::curvature_ductility() const
  {
    return space ? std::max(curvature_ductility_z(), curvature_ductility_y()) :
                      curvature_ductility_z();
  }

  double
  SectionLimitTracker::ratio(const SectionLimit l) const
  {
    const unsigned int i = static_cast<unsigned int>(l);
    return demand(peak, i) / strain_limits.strain[i]; // NaN when not checked
  }

  int
  SectionLimitTracker::worst_limit() const
  {
    for (int l = n_section_limits - 1; l >= 0; --l)
      if (!std::isnan(first[l]))
        return l;
    return -1;
  }
} // namespace poundfe
