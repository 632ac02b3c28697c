// Floor masses and a gap's effective mass (model/floor_mass.h).
#include <poundfe/model/floor_mass.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <deal.II/base/exceptions.h>

namespace poundfe
{
  MassesByNode
  masses_by_node(const Model &model)
  {
    MassesByNode index;
    index.start.assign(model.nodes.size() + 1, 0);
    for (const NodalMass &m : model.masses)
      ++index.start[m.node + 1];
    for (unsigned int n = 0; n < model.nodes.size(); ++n)
      index.start[n + 1] += index.start[n];
    index.entries.resize(model.masses.size());
    std::vector<unsigned int> next(index.start.begin(), index.start.end() - 1);
    for (unsigned int i = 0; i < model.masses.size(); ++i)
      index.entries[next[model.masses[i].node]++] = i;
    return index;
  }

  double
  floor_mass(const Model &model, const Floor &floor, const MassesByNode *index)
  {
    double mass = 0;
    if (!index)
      {
        for (const NodalMass &m : model.masses)
          if (std::find(floor.nodes.begin(), floor.nodes.end(), m.node) != floor.nodes.end())
            mass += m.mass;
        return mass;
      }
    AssertDimension(index->entries.size(), model.masses.size());
    // the same sum in the same order as the scan above: its entries sorted
    std::vector<unsigned int> entries;
    for (const unsigned int node : floor.nodes)
      entries.insert(entries.end(), index->entries.begin() + index->start[node],
                     index->entries.begin() + index->start[node + 1]);
    std::sort(entries.begin(), entries.end());
    entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
    for (const unsigned int i : entries)
      mass += model.masses[i].mass;
    return mass;
  }

  double
  floor_effective_mass(const Model &model, const Gap &gap, const MassesByNode *index)
  {
    // the floor of building b nearest the gap's level (a gap from a floor
    // to a column: the nearest floor's mass collides)
    const auto mass_near = [&](const Building &b) {
      const Floor *best = &b.floors.front();
      for (const Floor &f : b.floors)
        if (std::abs(f.level - gap.level) < std::abs(best->level - gap.level))
          best = &f;
      return floor_mass(model, *best, index);
    };
    const double m1 = mass_near(model.buildings[gap.buildings[0]]);
    if (gap.nodes[0] < 0 || gap.nodes[1] < 0) // a barrier: the floor alone
      return m1;
    const double m2 = mass_near(model.buildings[gap.buildings[1]]);
    return m1 * m2 / (m1 + m2);
  }
} // namespace poundfe
