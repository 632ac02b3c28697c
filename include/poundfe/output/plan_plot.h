// The plan view of where two 3D buildings hit each other (impacts_plan.png):
// the slab outline of every floor of each building (site plan at rest, the
// distinct outlines of its floors, closed polygons) and the plan point of
// each impact of impacts.csv (where its peak force acted, doc/theory.md
// §1.13), a filled circle whose size grows with the peak force,
//   point size = 1 + 3 F_peak / max F_peak,
// on equal x and y scales, so that corner-to-edge hits show where they are.
#ifndef poundfe_output_plan_plot_h
#define poundfe_output_plan_plot_h

#include <poundfe/integration/impact_log.h>
#include <poundfe/model/model.h>
#include <poundfe/output/plots.h>

namespace poundfe
{
  /// The plot of a 3D model with gaps (Model/Dimension = 3).
  Plot impact_plan_plot(const Model &model, const std::vector<Impact> &impacts);
} // namespace poundfe

#endif
