// The figure of `poundfe switching` (phase_portrait.png): equation 1's
// trajectory (trajectory.csv: time, u, v, sliding flag, ...) with the
// switching surfaces that are lines of its (u, v) plane dashed, the sliding
// samples (Filippov's convex method) in red and each hit (switching.csv) as
// a marker of its class. The key names only the classes of hit that
// occurred (a marker that never shows is a false statement about the run),
// and the axes carry the unit of equation 1's DOF.
#ifndef poundfe_report_switching_plot_h
#define poundfe_report_switching_plot_h

#include <poundfe/integration/filippov.h>
#include <poundfe/output/plots.h>

#include <set>
#include <string>
#include <vector>

namespace poundfe
{
  /// The portrait of a model of `n_equations` equations (state (u, v)) with
  /// these `surfaces`, the hits' `classes` (switching_class_name) that
  /// occurred; `slides`: the run has a sliding interval (else no sliding
  /// samples in the key); `rotation`: equation 1 is a rotation (rad,
  /// rad/s; else m, m/s).
  Plot switching_phase_portrait(const std::vector<SwitchingSurface> &surfaces,
                                unsigned int                          n_equations,
                                const std::set<std::string>          &classes,
                                bool                                  slides,
                                bool                                  rotation);
} // namespace poundfe

#endif
