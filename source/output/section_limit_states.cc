// The limit states of a run's fibre members (output/section_limit_states.h).
#include <poundfe/output/section_limit_states.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/section_states.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace poundfe
{
  namespace
  {
    /// The storey (1-based) a member of building b stands in: the first
    /// floor at or above its upper end (the columns below a floor, the
    /// beams of that floor); a 3D member's ends by their z.
    unsigned int
    storey_of_member(const Model &model, const std::string &label, const unsigned int b)
    {
      double top = -std::numeric_limits<double>::infinity();
      for (const Member &member : model.members)
        if (member.label == label)
          for (const unsigned int n : member.nodes)
            top = std::max(top, model.nodes[n].position.y);
      for (const Member3D &member : model.members_3d)
        if (member.label == label)
          for (const auto &end : member.ends)
            top = std::max(top, end[2]);
      const std::vector<Floor> &floors    = model.buildings[b].floors;
      const double              tolerance = 1e-6 * std::max(1.0, std::abs(top));
      unsigned int              f         = 0;
      while (f + 1 < floors.size() && floors[f].level < top - tolerance)
        ++f;
      return f + 1;
    }

    /// The smallest first time over the member's sections (NaN: never).
    double
    first_time(const SectionLimitStates::MemberLimits &m, const SectionLimit l)
    {
      double t = std::numeric_limits<double>::quiet_NaN();
      for (const SectionLimitTracker &s : m.sections)
        if (!std::isnan(s.first_time(l)) && !(t <= s.first_time(l)))
          t = s.first_time(l);
      return t;
    }

    /// The largest ratio over the member's sections (NaN: not checked).
    double
    worst_ratio(const SectionLimitStates::MemberLimits &m, const SectionLimit l)
    {
      double r = std::numeric_limits<double>::quiet_NaN();
      for (const SectionLimitTracker &s : m.sections)
        if (!std::isnan(s.ratio(l)) && !(r >= s.ratio(l)))
          r = s.ratio(l);
      return r;
    }

    template <typename Get>
    std::vector<double>
    per_point(const SectionLimitStates::MemberLimits &m, const Get &get)
    {
      std::vector<double> values;
      for (const SectionLimitTracker &s : m.sections)
        values.push_back(get(s));
      return values;
    }
  } // namespace

  int
  SectionLimitStates::MemberLimits::worst_limit() const
  {
    int worst = -1;
    for (const SectionLimitTracker &s : sections)
      worst = std::max(worst, s.worst_limit());
    return worst;
  }

  SectionLimitStates::SectionLimitStates(const Model &model, const NonlinearElements &elements,
                                         const SectionLimitParameters &parameters)
  {
    for (const NonlinearElement &e : elements)
      {
        if (fibre_section_of(e, 0) == nullptr) // not a member on fibre sections
          continue;
        MemberLimits m{&e, e.label, e.building, storey_of_member(model, e.label, e.building),
                       {}, {}, {}};
        for (unsigned int i = 0; fibre_section_of(e, i) != nullptr; ++i)
          {
            const FibreSection &section = *fibre_section_of(e, i);
            m.sections.emplace_back(section, section_strain_limits(section, parameters));
            const double yield = m.sections.back().limits().strain[unsigned(SectionLimit::bar_yield)];
            m.yield_axial_force.push_back(std::numeric_limits<double>::quiet_NaN());
            const double ea = section_axial_stiffness(section);
            m.axial_force_tolerance.push_back(
              std::isnan(yield) ? 0.0 : yield_force_tolerance * ea * yield);
          }
        limits.push_back(std::move(m));
      }
  }

  void
  SectionLimitStates::find_yield_curvatures()
  {
    for (MemberLimits &m : limits)
      for (unsigned int i = 0; i < m.sections.size(); ++i)
        {
          const FibreSection &section = *fibre_section_of(*m.element, i);
          const double yield =
            m.sections[i].limits().strain[unsigned(SectionLimit::bar_yield)];
          if (std::isnan(yield)) // no bars: no yield curvature
            continue;
          const double n = section.resultant()[0];
          if (std::abs(n - m.yield_axial_force[i]) <= m.axial_force_tolerance[i])
            continue; // kappa_y± of a close enough N (NaN: never found)
          m.yield_axial_force[i] = n;
          m.sections[i].set_yield_curvatures(section_yield_curvature(section, n, yield, +1),
                                             section_yield_curvature(section, n, yield, -1));
          if (section.n_resultants() == 4) // in space: about y too
            m.sections[i].set_yield_curvatures_y(
              section_yield_curvature(section, n, yield, +1, BendingAxis::y),
              section_yield_curvature(section, n, yield, -1, BendingAxis::y));
        }
  }

  void
  SectionLimitStates::initialize_at(const double when)
  {
    if (!axial_force_followed) // else observe_at finds them
      find_yield_curvatures(); // at the gravity state's axial forces
    observe_at(when);
  }

  void
  SectionLimitStates::observe_at(const double when)
  {
    if (axial_force_followed)
      find_yield_curvatures();
    for (MemberLimits &m : limits)
      for (unsigned int i = 0; i < m.sections.size(); ++i)
        m.sections[i].observe(*fibre_section_of(*m.element, i), when);
  }

  std::vector<int>
  SectionLimitStates::storey_worst_limits(const Model &model, const unsigned int b) const
  {
    std::vector<int> worst(model.buildings[b].floors.size(), -1);
    for (const MemberLimits &m : limits)
      if (m.building == b && m.storey <= worst.size())
        worst[m.storey - 1] = std::max(worst[m.storey - 1], m.worst_limit());
    return worst;
  }

  void
  SectionLimitStates::write_json(JsonWriter &json, const Model &model,
                                 const std::string &first_key) const
  {
    json.begin_array("section_limit_states");
    for (const MemberLimits &m : limits)
      {
        json.begin_object()
          .value("member", m.label)
          .value("building", model.buildings[m.building].name)
          .value("storey", m.storey)
          .value("damage_state", damage_state_name(m.worst_limit()))
          .value("yield_curvature_positive_1_m",
                 per_point(m, [](auto &s) { return s.limits().yield_curvature_positive; }))
          .value("yield_curvature_negative_1_m",
                 per_point(m, [](auto &s) { return s.limits().yield_curvature_negative; }))
          .value("peak_curvature_positive_1_m",
                 per_point(m, [](auto &s) { return s.peak_curvature_positive(); }))
          .value("peak_curvature_negative_1_m",
                 per_point(m, [](auto &s) { return s.peak_curvature_negative(); }))
          .value("curvature_ductility",
                 per_point(m, [](auto &s) { return s.curvature_ductility(); }))
          .value("peak_concrete_strain", per_point(m, [](auto &s) { return s.peaks().concrete; }))
          .value("peak_core_strain", per_point(m, [](auto &s) { return s.peaks().core; }))
          .value("peak_steel_strain_max", per_point(m, [](auto &s) { return s.peaks().steel_max; }))
          .value("peak_steel_strain_min",
                 per_point(m, [](auto &s) { return s.peaks().steel_min; }));
        if (m.sections.front().in_space()) // the first fields about z, these about y
          json
            .value("curvature_ductility_z",
                   per_point(m, [](auto &s) { return s.curvature_ductility_z(); }))
            .value("curvature_ductility_y",
                   per_point(m, [](auto &s) { return s.curvature_ductility_y(); }))
            .value("yield_curvature_y_positive_1_m",
                   per_point(m, [](auto &s) { return s.limits().yield_curvature_y_positive; }))
            .value("yield_curvature_y_negative_1_m",
                   per_point(m, [](auto &s) { return s.limits().yield_curvature_y_negative; }))
            .value("peak_curvature_y_positive_1_m",
                   per_point(m, [](auto &s) { return s.peak_curvature_y_positive(); }))
            .value("peak_curvature_y_negative_1_m",
                   per_point(m, [](auto &s) { return s.peak_curvature_y_negative(); }));
        json.begin_object("limits");
        for (unsigned int l = 0; l < n_section_limits; ++l)
          {
            const SectionLimit limit = static_cast<SectionLimit>(l);
            json.begin_object(section_limit_name(limit))
              .value("strain", m.sections.front().limits().strain[l])
              .value("ratio", worst_ratio(m, limit))
              .value(first_key, first_time(m, limit))
              .end_object();
          }
        json.end_object().end_object();
      }
    json.end_array();
  }
} // namespace poundfe
