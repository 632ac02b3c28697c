#include <poundfe/output/peak_response.h>
#include <poundfe/output/response_range.h>

#include <cmath>
#include <sstream>

namespace poundfe
{
  ResponseRange::ResponseRange(const Model &model, const PeakResponse &peaks,
                               const double drift_limit, const double rotation_limit)
    : model(model)
    , peaks(peaks)
    , drift_limit(drift_limit)
    , rotation_limit(rotation_limit)
  {
    for (unsigned int node = 0; node < model.n_nodes(); ++node)
      if (const int q = model.equation(Model::dof(node, Component::rz)); q >= 0)
        {
          rotation_equations.push_back(q);
          rotation_nodes.push_back(node);
          rotation_buildings.push_back(model.nodes[node].building);
        }
  }

  void
  ResponseRange::initialize(const ResponseView &state)
  {
    peak_rotation.assign(model.buildings.size(), 0.0);
    peak_rotation_time.assign(model.buildings.size(), 0.0);
    peak_rotation_node.assign(model.buildings.size(), 0);
    observe_step(state);
  }

  void
  ResponseRange::observe_step(const ResponseView &state)
  {
    if (!(rotation_limit > 0) || rotation_equations.empty())
      return;
    // each building's nodes in node order, as its peak's ties are kept
    const Vector &u = state.displacement();
    for (unsigned int i = 0; i < rotation_equations.size(); ++i)
      {
        const unsigned int b = rotation_buildings[i];
        if (!state.observes_building(b))
          continue;
        if (const double theta = std::abs(u[rotation_equations[i]]); theta > peak_rotation[b])
          {
            peak_rotation[b]      = theta;
            peak_rotation_time[b] = state.time();
            peak_rotation_node[b] = rotation_nodes[i];
          }
      }
  }

  std::vector<std::string>
  ResponseRange::warnings() const
  {
    std::vector<std::string> found;
    const FloorResponse     &floors = peaks.floors();
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      {
        const Building &building = model.buildings[b];
        double          height   = 0;
        for (unsigned int f = 0; f < building.floors.size(); ++f)
          {
            height += building.floors[f].storey_height;
            const unsigned int i     = floors.index(b, f);
            const double       drift = floors.peak_drift_ratio()[i];
            if (drift_limit > 0 && !(drift <= drift_limit)) // NaN warns too
              {
                std::ostringstream w;
                w.precision(3);
                w << building.name << " storey " << f + 1 << ": peak drift ratio " << drift
                  << " at t = " << floors.peak_drift_time()[i]
                  << " s exceeds Output/Warnings/Drift ratio = " << drift_limit
                  << " (beyond collapse: the model's members and hinges do not represent it)";
                found.push_back(w.str());
              }
          }
        if (building.floors.empty() || !(height > 0))
          continue;
        const double roof = floors.peak_displacement()[floors.index(b, building.floors.size() - 1)];
        if (drift_limit > 0 && !(roof <= drift_limit * height))
          {
            std::ostringstream w;
            w.precision(3);
            w << building.name << ": peak roof displacement " << roof << " m is " << roof / height
              << " of the height " << height << " m, beyond Output/Warnings/Drift ratio = "
              << drift_limit;
            found.push_back(w.str());
          }
        if (rotation_limit > 0 && b < peak_rotation.size() && !(peak_rotation[b] <= rotation_limit))
          {
            const Point2      &at = model.nodes[peak_rotation_node[b]].position;
            std::ostringstream w;
            w.precision(3);
            w << building.name << ": node " << peak_rotation_node[b] << " at (" << at.x << ", "
              << at.y << ") rotates " << peak_rotation[b] << " rad at t = "
              << peak_rotation_time[b] << " s, beyond Output/Warnings/Rotation = "
              << rotation_limit
              << " rad: the frame elements assume small displacements";
            found.push_back(w.str());
          }
      }
    return found;
  }

  void
  ResponseRange::merge(const RankMerge &ranks)
  {
    ranks.owned(Owner::building, peak_rotation);
    ranks.owned(Owner::building, peak_rotation_time);
    ranks.owned(Owner::building, peak_rotation_node);
  }
} // namespace poundfe
