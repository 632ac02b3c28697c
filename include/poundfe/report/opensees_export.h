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
//    a fixed barrier node), so that closing compresses it;
//  - a 2D frame (report/opensees_export_frames.cc; then every building in
//    model basic -ndm 2 -ndf 3, a shear building's uy and rz fixed): each
//    member an elasticBeamColumn on geomTransf Linear with the member's E,
//    A and I, the lumped masses of M on the nodes, the building's a0 M as
//    dashpots to fixed nodes and a1 K as `rayleigh 0 0 a1 0` (betaKinit:
//    the members' and hinges' initial stiffness, the gaps left out as
//    poundfe's C leaves them; one a1 for every frame, since OpenSees 3.8's per-building form,
//    region, is not among `poundfe opensees`'s commands); Model/Gravity
//    analysis as OpenSees's gravity analysis: the same nodal loads in a
//    Plain pattern, LoadControl in as many steps, then loadConst -time 0;
//  - a fibre member (report/opensees_export_fibres.cc): section Fiber of
//    its fibres and materials, forceBeamColumn (Lobatto) or dispBeamColumn
//    (Legendre), geomTransf PDelta for a PDelta column;
//  - a Bouc-Wen hinge: the member's end node tied to the joint (equalDOF
//    1 2), a zeroLength -dir 6 on BoucWen; a Bouc-Wen storey a zeroLength on
//    BoucWen beside one on Elastic 0 eta. OpenSees's BoucWen integrates by
//    backward Euler, poundfe's by the trapezoidal rule: the runs agree as
//    the step shrinks, to first order, not at one step.
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
    /// The model's space: 1 and 1 for shear buildings alone, 3 and 6 in 3D,
    /// else 2 and 3.
    unsigned int ndm = 1, ndf = 1;
    /// Some node shares DOFs of another (equalDOF: constraints
    /// Transformation, else Plain).
    bool tied = false;
    /// The constraint handler those ties need.
    std::string constraints() const { return tied ? "Transformation" : "Plain"; }
    /// The gravity analysis before the record (empty without one): the
    /// pattern and the static analysis, ending with loadConst -time 0.
    std::vector<std::string> gravity;
    /// The members' stiffness-proportional damping a1 (rayleigh's
    /// betaKinit) when every frame has the same; 0: no rayleigh command.
    double member_stiffness_damping = 0;
    /// Frames of different a1: each building's (1-based, its name) a1 on its
    /// Rayleigh-damped elements (members, hinges), as `region building
    /// -eleOnly elements -rayleigh 0 0 a1 0`.
    struct DampingRegion
    {
      unsigned int     building = 0;
      std::string      name;
      double           a1 = 0;
      std::vector<int> elements;
    };
    std::vector<DampingRegion> damping_regions;
    /// The floor nodes to record, building by building, bottom to top, with
    /// poundfe's names of their columns (shear3_floor1_disp_m, ...): a
    /// frame's floor has a column per node, of one name, and poundfe's
    /// floor displacement is their mean.
    std::vector<int>         floor_nodes;
    std::vector<std::string> floor_names;
    /// The DOFs recorded at each floor node ("1"; a 3D floor's "1 2 6": its
    /// three columns are x, y and θz).
    std::string floor_dofs = "1";
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

  /// A name (a building's, a member's, a material's) as one word of the
  /// script's comments: in double quotes, with a backslash before " and \,
  /// when it has a blank, a quote or a backslash, so that `my bldg` stays one
  /// word and no name ends a comment's line with a backslash, which Tcl
  /// would join to the next line.
  std::string comment_word(const std::string &name);

  /// The OpenSees description of `analysis` under `parameters`' excitation
  /// (`excitation`, made from them). Throws InputError naming the first
  /// entry OpenSees cannot express the same way.
  OpenSeesExport describe_opensees(const Analysis &analysis, const TimeHistoryParameters &parameters,
                                   const Excitation &excitation);
} // namespace poundfe

#endif
