// The description of a poundfe model as an OpenSees 3.8 script (`poundfe
// export-opensees`): the model's nodes, materials and elements as OpenSees
// commands, the ground motion sampled at the time step, the floors and
// gaps to record and the Newmark step. What it holds, in OpenSees's terms:
//  - a 2D shear building: a 1-DOF node per floor (model basic -ndm 1
//    -ndf 1) with the floor's mass, the base fixed, each storey a
//    zeroLength on uniaxialMaterial Elastic k eta, eta = a1 k + c_storey;
//    the building's Rayleigh term a0 M a zeroLength dashpot (Elastic 0
//    a0 m) from each floor to a fixed node of its own: C = a0 M + a1 K +
//    the storey dashpots exactly as poundfe assembles it (assembly/
//    linear_system.cc, assemble_damping), each building with its own a0, a1;
//  - a gap with the linear contact law (F = k d, d the penetration): a
//    zeroLength on ElasticPPGap k Fy -g with a yield force no impact
//    reaches (the same law), from the left node to the right one (or to
//    a fixed barrier node), so that closing compresses it.
// Anything else the model has is refused by InputError naming its entry.
#ifndef poundfe_report_opensees_export_h
#define poundfe_report_opensees_export_h

#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/time_history.h>

#include <string>
#include <vector>

namespace poundfe
{
  struct OpenSeesExport
  {
    /// The model's commands, one a line, with comment lines (# ...) that
    /// say what each part is in poundfe's terms.
    std::vector<std::string> model;
    /// The floor nodes to record, building by building, bottom to top, with
    /// poundfe's names of their columns (shear3_floor1_disp_m, ...).
    std::vector<int>         floor_nodes;
    std::vector<std::string> floor_names;
    /// The gap elements and their names (gap1, ...).
    std::vector<int>         gap_elements;
    std::vector<std::string> gap_names;
    /// a_g (m/s^2) at 0, dt, ..., (n_steps + 1) dt.
    std::vector<double> ground_acceleration;
    double              time_step = 0, gamma = 0.5, beta = 0.25;
    unsigned long       n_steps   = 0;
    /// Gaps present: Newton with a displacement test; else algorithm Linear.
    bool nonlinear = false;
    /// The test's iteration limit: OpenSees 3.8's Hertzdamp and
    /// JankowskiImpact give Newton a tangent of the wrong sign, with which it
    /// converges linearly, in more iterations than 50.
    unsigned int test_iterations = 50;
  };

  /// The OpenSees description of `analysis` under `parameters`' excitation
  /// (`excitation`, made from them). Throws InputError naming the first
  /// entry OpenSees cannot express the same way.
  OpenSeesExport describe_opensees(const Analysis &analysis, const TimeHistoryParameters &parameters,
                                   const Excitation &excitation);
} // namespace poundfe

#endif
