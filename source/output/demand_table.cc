// pelicun demand tables of a building (output/demand_table.h).
#include <poundfe/excitation/excitation.h>
#include <poundfe/excitation/ground_motion.h>
#include <poundfe/output/peak_response.h>
#include <poundfe/output/append_file.h>
#include <poundfe/output/demand_table.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace poundfe
{
  void
  gap_demands(const Model &model, const std::vector<Impact> &impacts, const unsigned int first_gap,
              std::vector<double> &count, std::vector<double> &force, std::vector<double> &velocity)
  {
    const std::size_t n = model.gaps.size();
    count.assign(n, 0.0);
    force.assign(n, 0.0);
    velocity.assign(n, 0.0);
    for (const Impact &impact : impacts)
      if (impact.element >= first_gap && impact.element - first_gap < n)
        {
          const unsigned int g = impact.element - first_gap;
          count[g] += 1;
          force[g]    = std::max(force[g], impact.peak_force);
          velocity[g] = std::max(velocity[g], std::abs(impact.approach_velocity));
        }
  }

  void
  add_plan_demands(const PeakResponse &peaks, const Excitation &excitation, ResponseDemands &d)
  {
    if (!peaks.floors_y())
      {
        d.pga = excitation.ground_motion().peak();
        return;
      }
    const std::array<double, 2> pga = excitation.applied_horizontal_peaks();
    d.pga                 = pga[0];
    d.pga_y               = pga[1];
    d.peak_drift_y        = peaks.floors_y()->peak_drift_ratio();
    d.peak_acceleration_y = peaks.floors_y()->peak_acceleration();
    d.peak_rotation       = peaks.floors_rz()->peak_displacement(); // |theta_z|, rad
    d.residual_drift_y    = peaks.floors_y()->drift_ratio();        // at the end of the run
  }

  unsigned int
  gap_floor(const Model &model, const unsigned int building, const unsigned int g)
  {
    const Gap                &gap    = model.gaps.at(g);
    const std::vector<Floor> &floors = model.buildings.at(building).floors;
    for (unsigned int side = 0; side < 2; ++side)
      if (gap.nodes[side] >= 0 && gap.buildings[side] == building)
        {
          const unsigned int node = static_cast<unsigned int>(gap.nodes[side]);
          for (unsigned int f = 0; f < floors.size(); ++f)
            if (std::find(floors[f].nodes.begin(), floors[f].nodes.end(), node) !=
                floors[f].nodes.end())
              return f + 1;
          // a node of the building between floors (a column's contact
          // point): the floor at the gap's level or the nearest below it
          unsigned int below = 1;
          for (unsigned int f = 0; f < floors.size(); ++f)
            if (floors[f].level <= gap.level + 1e-9)
              below = f + 1;
          return below;
        }
    return 0;
  }

  std::string
  DemandColumn::name() const
  {
    return "1-" + type + "-" + location + "-" + direction;
  }

  DemandTable::DemandTable(const Model &model_, const unsigned int building_,
                           const bool displacements_, const std::string &spectral_type)
    : model(model_)
    , building(building_)
    , displacements(displacements_)
    , spectral(!spectral_type.empty())
    , plan(model_.dimension == 3)
  {
    const unsigned int n = model.buildings.at(building).floors.size();
    header.push_back({"PFA", "0", "1", "g"});
    if (spectral)
      header.push_back({spectral_type, "0", "1", "g"});
    for (unsigned int f = 1; f <= n; ++f)
      header.push_back({"PFA", std::to_string(f), "1", "g"});
    if (plan)
      for (unsigned int f = 0; f <= n; ++f)
        header.push_back({"PFA", std::to_string(f), "2", "g"});
    struct StoreyType
    {
      const char *type, *direction, *unit;
    };
    std::vector<StoreyType> storey_types = {{"PID", "1", "rad"}};
    if (plan)
      storey_types.push_back({"PID", "2", "rad"});
    storey_types.push_back({"RID", "1", "rad"});
    if (plan)
      storey_types.push_back({"RID", "2", "rad"});
    if (displacements)
      storey_types.insert(storey_types.end(), {{"PFD", "1", "m"}, {"RFD", "1", "m"}});
    for (const auto &[type, direction, unit] : storey_types)
      for (unsigned int s = 1; s <= n; ++s)
        header.push_back({type, std::to_string(s), direction, unit});
    if (displacements)
      header.push_back({"PRD", std::to_string(n), "1", "rad"});
    if (plan)
      for (unsigned int f = 1; f <= n; ++f)
        header.push_back({"PFR", std::to_string(f), "0", "rad"});
    for (unsigned int g = 0; g < model.gaps.size(); ++g)
      if (const unsigned int f = gap_floor(model, building, g); f > 0)
        for (const auto &[type, unit] :
             std::vector<std::pair<const char *, const char *>>{{"NIMP", "ea"},
                                                                 {"PIMF", "N"},
                                                                 {"PIMV", "mps"}})
          header.push_back({type, std::to_string(f), std::to_string(g + 1), unit});
  }

  void
  DemandTable::add(const ResponseDemands &d)
  {
    unsigned int first = 0; // the building's first floor in the model's floor arrays
    for (unsigned int b = 0; b < building; ++b)
      first += model.buildings[b].floors.size();
    const unsigned int n = model.buildings[building].floors.size();
    Assert(d.peak_drift.size() >= first + n && d.peak_acceleration.size() >= first + n &&
             d.residual_drift.size() >= first + n, dealii::ExcInternalError());
    Assert(!displacements || (d.peak_displacement.size() >= first + n &&
                              d.residual_displacement.size() >= first + n),
           dealii::ExcInternalError());
    Assert(!plan || (d.peak_drift_y.size() >= first + n && d.peak_acceleration_y.size() >= first + n &&
                     d.peak_rotation.size() >= first + n && d.residual_drift_y.size() >= first + n),
           dealii::ExcInternalError());
    std::vector<double> row = {d.pga / standard_gravity};
    if (spectral)
      row.push_back(d.sa);
    for (unsigned int f = 0; f < n; ++f)
      row.push_back(d.peak_acceleration[first + f] / standard_gravity);
    if (plan)
      {
        row.push_back(d.pga_y / standard_gravity);
        for (unsigned int f = 0; f < n; ++f)
          row.push_back(d.peak_acceleration_y[first + f] / standard_gravity);
      }
    std::vector<const std::vector<double> *> storey = {&d.peak_drift};
    if (plan)
      storey.push_back(&d.peak_drift_y);
    storey.push_back(&d.residual_drift);
    if (plan)
      storey.push_back(&d.residual_drift_y);
    if (displacements)
      storey.insert(storey.end(), {&d.peak_displacement, &d.residual_displacement});
    for (const std::vector<double> *values : storey)
      {
        // a residual's magnitude: its sign is only the side it leans to
        const bool residual = values == &d.residual_drift || values == &d.residual_drift_y ||
                              values == &d.residual_displacement;
        for (unsigned int f = 0; f < n; ++f)
          row.push_back(residual ? std::abs((*values)[first + f]) : (*values)[first + f]);
      }
    if (displacements) // the roof's peak displacement over the building's height
      {
        const Building &b = model.buildings[building];
        row.push_back(d.peak_displacement[first + n - 1] /
                      (b.floors.back().level - b.base_level));
      }
    if (plan)
      for (unsigned int f = 0; f < n; ++f)
        row.push_back(d.peak_rotation[first + f]);
    for (unsigned int g = 0; g < model.gaps.size(); ++g)
      if (gap_floor(model, building, g) > 0)
        row.insert(row.end(), {d.impacts.at(g), d.impact_force.at(g), d.impact_velocity.at(g)});
    Assert(row.size() == header.size(), dealii::ExcInternalError());
    values.push_back(std::move(row));
  }

  std::string
  DemandTable::csv() const
  {
    std::string text, units = "Units";
    for (const DemandColumn &column : header)
      {
        text += "," + column.name();
        units += "," + column.unit;
      }
    text += "\n" + units + "\n";
    for (std::size_t r = 0; r < values.size(); ++r)
      {
        text += std::to_string(r);
        for (const double x : values[r])
          {
            text += ',';
            append_number(text, x);
          }
        text += '\n';
      }
    return text;
  }

  std::string
  demand_table_file(const Model &model, const unsigned int building, const std::string &suffix)
  {
    return "demands_" + model.buildings.at(building).name + suffix + ".csv";
  }
} // namespace poundfe
