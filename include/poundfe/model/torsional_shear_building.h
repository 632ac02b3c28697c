// Torsionally coupled shear building: rigid floor diaphragms with three DOFs
// q_i = (ux, uy, θz) at the mass centre C_i of floor i, joined by storeys of
// lateral-resisting planes (frames or walls, each stiff only along its own
// direction in plan).
//   A plane of direction d (unit, in plan) through the point p deforms, for
//   a rigid floor moving q about the point C, by δ = a(C)·q with
//   a(C) = (d_x, d_y, d_y (p_x - C_x) - d_x (p_y - C_y)). In storey i (between
//   floor i-1, or the ground, and floor i) it adds k a aᵀ to the 6x6 of
//   (q_{i-1}, q_i) with a = (-a(C_{i-1}), a(C_i)).
//   Mass: diag(m_i, m_i, I_i), I_i the polar moment about C_i.
//   Stiffness centre of a storey (the point about which a lateral force
//   causes no twist): with K_xx, K_xy, K_yy, K_xθ, K_yθ of the storey's
//   planes about the origin, K_xy y_R - K_yy x_R = -K_yθ and K_xx y_R - K_xy
//   x_R = -K_xθ (for planes along x and y alone: x_R = Σ k_y p_x / Σ k_y,
//   y_R = Σ k_x p_y / Σ k_x).
//   Torsional stiffness about it K_θR = Σ k a_θ(R)²; torsional radii
//   r_x = sqrt(K_θR / K_yy), r_y = sqrt(K_θR / K_xx); radius of gyration of
//   the floor mass l_s = sqrt(I / m); structural eccentricity e_0 = R - C.
//   EC8 (EN 1998-1) §4.2.3.2(6), for analysis along y (and likewise along x):
//   e_0x ≤ 0.30 r_x and r_x ≥ l_s.
//   Accidental eccentricity (EN 1998-1 §4.3.2(1), ASCE 7-16 §12.8.4.2): the
//   mass centre moved by ±0.05 L, L the plan dimension normal to the action.
// Source: Chopra, Dynamics of Structures, 4th ed. (2012), ch. 9 (one- and
// multi-storey systems with unsymmetric plan: the stiffness of resisting
// planes referred to the mass centre); EN 1998-1:2004 §4.2.3.2 and §4.3.2;
// ASCE/SEI 7-16 §12.8.4.2.
// Plain data and Eigen dense matrices (a building has few floors).
#ifndef poundfe_model_torsional_shear_building_h
#define poundfe_model_torsional_shear_building_h

#include <poundfe/base/point.h>

#include <Eigen/Core>

#include <vector>

namespace poundfe
{
  /// A frame or wall of one storey: stiff along `direction` only.
  struct ResistingPlane
  {
    Point2 direction{1, 0}; // in plan; normalised where used
    Point2 position;        // any point of the plane in plan, m
    double stiffness = 0;   // storey stiffness along `direction`, N/m
  };

  /// A rigid floor and the planes of the storey below it.
  struct TorsionalFloor
  {
    double                      mass         = 0; // kg
    double                      polar_moment = 0; // about the mass centre, kg m²
    Point2                      mass_centre;      // in plan, m
    std::vector<ResistingPlane> planes;           // of the storey below
  };

  /// Floors bottom to top; floor i has DOFs 3i + (0: ux, 1: uy, 2: θz).
  struct TorsionalShearBuilding
  {
    std::vector<TorsionalFloor> floors;

    unsigned int n_floors() const { return floors.size(); }
    unsigned int n_dofs() const { return 3 * floors.size(); }
  };

  /// Throws InputError (no file: the caller adds it) for a floor without
  /// positive mass and polar moment, a plane without a direction or with a
  /// negative stiffness, or a storey whose planes cannot hold a floor (all
  /// parallel, or all through one point: no torsional stiffness).
  void check_building(const TorsionalShearBuilding &building);

  /// a(point): the plane's deformation δ = a·(ux, uy, θz) of a rigid floor
  /// moving about `point`.
  Eigen::Vector3d plane_row(const ResistingPlane &plane, const Point2 &point);

  /// The 3x3 stiffness of the rigid-floor motion (ux, uy, θz) about `point`
  /// from `planes`.
  Eigen::Matrix3d storey_stiffness(const std::vector<ResistingPlane> &planes, const Point2 &point);

  /// Global stiffness (3 n_floors square), DOFs at the mass centres.
  Eigen::MatrixXd stiffness_matrix(const TorsionalShearBuilding &building);
  /// Global mass, diag(m, m, I) per floor.
  Eigen::MatrixXd mass_matrix(const TorsionalShearBuilding &building);

  /// Throws InputError when the planes are all parallel (no centre).
  Point2 stiffness_centre(const std::vector<ResistingPlane> &planes);

  /// The torsional properties of storey i (below floor i) for EC8's check.
  struct StoreyTorsion
  {
    Point2 stiffness_centre;
    Point2 eccentricity;          // e_0 = stiffness centre - mass centre of floor i
    double torsional_stiffness = 0; // K_θR, about the stiffness centre, N m/rad
    double torsional_radius_x  = 0; // sqrt(K_θR / K_yy), m
    double torsional_radius_y  = 0; // sqrt(K_θR / K_xx), m
    double radius_of_gyration  = 0; // l_s = sqrt(I / m) of floor i, m

    /// EN 1998-1 §4.2.3.2(6) (4.1a, b) along x and y:
    /// |e_0y| ≤ 0.30 r_y, r_y ≥ l_s and |e_0x| ≤ 0.30 r_x, r_x ≥ l_s.
    bool regular_in_plan() const;
  };
  StoreyTorsion storey_torsion(const TorsionalShearBuilding &building, unsigned int floor);

  enum class PlanDirection
  {
    x,
    y
  };

  /// The accidental eccentricity of a floor of plan dimensions (L_x, L_y)
  /// for the seismic action along `action`: ±ratio times the dimension normal
  /// to it, as a shift of the mass centre (sign +1 or -1).
  Point2 accidental_eccentricity(const Point2 &plan_dimensions, PlanDirection action, int sign,
                                 double ratio = 0.05);

  /// The building with each floor's mass centre moved by its accidental
  /// eccentricity (plan dimensions per floor, or one for all); the polar
  /// moment about the moved centre is unchanged (the mass moves as a whole).
  TorsionalShearBuilding with_accidental_eccentricity(const TorsionalShearBuilding &building,
                                                      const std::vector<Point2> &plan_dimensions,
                                                      PlanDirection action, int sign,
                                                      double ratio = 0.05);
} // namespace poundfe

#endif
