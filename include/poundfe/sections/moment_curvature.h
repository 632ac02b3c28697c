// Moment–curvature analysis of a fibre section under a constant axial
// force N: the curvature grows in steps along the direction at `angle` from
// z (kappa_z = kappa cos a, kappa_y = kappa sin a; a plane section has only
// a = 0), and at each step Newton's method on the axial strain,
//   eps0 <- eps0 - (N(eps0, kappa) - N) / k_s(0, 0),
// restores the axial force with the section tangent. The moment is M =
// Mz cos a + My sin a, and its tangent at constant N the condensed
//   dM/dkappa = d^T K_kk d - (d^T K_k0)(K_0k d) / K_00,  d = (cos a, sin a)
// (d^T K_kk d when K_00 = 0: every fibre on a plateau).
// It stops at the target curvature, when the moment falls below a
// fraction of the peak, after the first point whose extreme steel strain
// reaches a given magnitude (when asked: the first yield alone is wanted), when a fibre passes its material's strain limit
// (crushing, rupture: located within the step by the secant method on the
// curvature), or when N can no longer be carried. Events: the first yield
// of each steel material (its law's yield strain), each concrete
// material's strain reaching its law's epscu (spalling of the cover,
// crushing of the core), located the same way; the peak moment.
// The engine returns the table; the command writes it.
#ifndef poundfe_sections_moment_curvature_h
#define poundfe_sections_moment_curvature_h

#include <poundfe/sections/fibre_section.h>

#include <string>
#include <vector>

namespace poundfe
{
  struct MomentCurvatureSettings
  {
    double       axial_force       = 0;  // N, tension positive
    double       angle             = 0;  // degrees from the z axis (space only)
    double       target_curvature  = 0;  // 1/m, > 0
    unsigned int steps             = 200; // equal curvature increments to the target
    double       drop_fraction     = 0.8; // stop when M < fraction x peak (0: never)
    /// Stop after the first point at which an extreme steel fibre's strain
    /// magnitude reaches this (0: never): the points up to it are those of
    /// the whole curve, so a first yield read from them is the same.
    double       stop_steel_strain = 0;
    double       tolerance         = 1e-10; // |N - N_target| over the section's squash force
    unsigned int max_iterations    = 50;
  };

  /// One point of the curve.
  struct MomentCurvaturePoint
  {
    double curvature = 0, moment = 0, axial_strain = 0;
    double concrete_strain = 0; // the most compressed concrete fibre (0: no concrete)
    double steel_strain_max = 0, steel_strain_min = 0; // the extreme steel fibres
    double tangent = 0;          // dM/dkappa at constant N
    double moment_z = 0, moment_y = 0;
  };

  /// A point of the curve where something happened.
  struct MomentCurvatureEvent
  {
    std::string          what; // "first yield of steel", "core reached epscu", ...
    MomentCurvaturePoint at;
  };

  struct MomentCurvatureResult
  {
    std::vector<MomentCurvaturePoint> points;
    std::vector<MomentCurvatureEvent> events; // in order of curvature
    bool                 yielded = false;
    MomentCurvaturePoint first_yield, peak, ultimate;
    std::string          stop_reason; // why the curve ends there
    /// kappa_u / kappa_y (0 without yield).
    double ductility() const;
  };

  /// Runs on `section` (reset first; left at the last converged point).
  /// InputError (parameter "Axial force") if N cannot be carried at zero
  /// curvature; Assert on settings out of range.
  MomentCurvatureResult moment_curvature(FibreSection &section,
                                         const MomentCurvatureSettings &settings);
} // namespace poundfe

#endif
