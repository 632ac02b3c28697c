// Floor masses and a gap's effective mass (model/floor_mass.h).
#include <poundfe/model/floor_mass.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  double
  floor_mass(const Model &model, const Floor &floor)
  {
    double mass = 0;
    for (const NodalMass &m : model.masses)
      if (std::find(floor.nodes.begin(), floor.nodes.end(), m.node) != floor.nodes.end())
        mass += m.mass;
    return mass;
  }

  double
  floor_effective_mass(const Model &model, const Gap &gap)
  {
    // the floor of building b nearest the gap's level (a gap from a floor
    // to a column: the nearest floor's mass collides)
    const auto mass_near = [&](const Building &b) {
      const Floor *best = &b.floors.front();
      for (const Floor &f : b.floors)
        if (std::abs(f.level - gap.level) < std::abs(best->level - gap.level))
          best = &f;
      return floor_mass(model, *best);
    };
    const double m1 = mass_near(model.buildings[gap.buildings[0]]);
    if (gap.nodes[0] < 0 || gap.nodes[1] < 0) // a barrier: the floor alone
      return m1;
    const double m2 = mass_near(model.buildings[gap.buildings[1]]);
    return m1 * m2 / (m1 + m2);
  }
} // namespace poundfe
