// Frequency-independent impedances of a rigid foundation on (or embedded in)
// an elastic half-space, for the plane motion of a 2D model: a horizontal
// spring and dashpot (sway u_0) and a rocking spring and dashpot (rotation
// θ about the horizontal axis normal to the plane).
//
// Gazetas (rectangular base 2L x 2B, L >= B, χ = B/L; the plane's length
// along x or y of Gazetas' axes):
//   K_y  = 2 G L / (2 - ν) (2 + 2.5 χ^0.85)          (sway along the short side)
//   K_x  = K_y - 0.2 G L (1 - B/L) / (0.75 - ν)      (sway along the long side)
//   K_rx = G / (1 - ν) I_bx^0.75 (L/B)^0.25 (2.4 + 0.5 B/L)   (about the long axis)
//   K_ry = 3 G / (1 - ν) I_by^0.75 (L/B)^0.15               (about the short axis)
// embedded to depth D with full sidewall contact (d = D, h = D/2, sidewall
// area A_w = 4 d (B + L)):
//   sway  × [1 + 0.15 sqrt(D/B)] [1 + 0.52 (h A_w / (B L²))^0.4]   (along y;
//         L B² for x, Gazetas' Table 2)
//   K_rx  × [1 + 1.26 (d/B) (1 + (d/B) (d/D)^-0.2 sqrt(B/L))]
//   K_ry  × [1 + 0.92 (d/L)^0.6 (1.5 + (d/L)^1.9 (d/D)^-0.6)]
// dashpots: the high-frequency limits (c̃ = 1) of Gazetas' radiation
// coefficients for the base, C_h = ρ V_s A_b, C_r = ρ V_La I_b with
// Lysmer's analog velocity V_La = 3.4 V_s / (π (1 - ν)); the sidewalls'
// radiation is left out (less damping: on the safe side for pounding).
// Source: G. Gazetas, Formulas and charts for impedances of surface and
// embedded foundations, J. Geotech. Eng. 117(9), 1363-1381, 1991, Tables 1
// and 2; also G. Mylonakis, S. Nikolaou & G. Gazetas, Footings under seismic
// loading, Soil Dyn. Earthq. Eng. 26, 824-853, 2006, Table 1.
//
// Wolf's cones (a disk of the base's area for sway, of its moment of area
// for rocking: r_h = sqrt(A/π), r_r = (4 I/π)^(1/4)), surface only:
//   K_h = 8 G r_h / (2 - ν),         C_h = ρ V_s π r_h²
//   K_r = 8 G r_r³ / (3 (1 - ν)),    C_r = ρ c π r_r⁴ / 4,
//   c = V_p for ν <= 1/3, 2 V_s for 1/3 < ν < 1/2, and a trapped mass moment
//   ΔM_θ = 0.3 π (ν - 1/3) ρ r_r⁵ for ν > 1/3 (added to the rotary inertia).
// Source: J.P. Wolf, Foundation Vibration Analysis Using Simple Physical
// Models, Prentice Hall 1994, §2.1-2.3 and Table 2-1 (the static stiffnesses
// are the exact disk values of Veletsos & Wei 1971; also ASCE 7-16 §19.2.1.1).
//
// In 3D (rectangle `length` along the foundation's local x, `width` along
// local y): the sway along x and rocking about y are the 2D values of the
// plane x-z; the sway along y and rocking about x those of the plane y-z
// (length and width swapped); and the torsion about the vertical, with
// J_t = I_bx + I_by the polar moment of the base area:
//   Gazetas: K_t = G J_t^0.75 [4 + 11 (1 - χ)^10],
//            embedded × [1 + 1.4 (1 + B/L) (d/B)^0.9],  C_t = ρ V_s J_t
//   (Mylonakis, Nikolaou & Gazetas 2006, Table 1; Gazetas 1991, Table 2);
//   cone:    K_t = 16 G r_t³ / 3, r_t = (2 J_t/π)^(1/4),  C_t = ρ V_s J_t
//   (Wolf 1994, Table 2-1: the exact disk value; the dashpot the cone's
//   high-frequency limit, like the others here).
// Vertical (frames, which carry vertical motion), rectangle 2L x 2B, A_b = 4BL:
//   Gazetas: K_z = 2 G L / (1 - ν) (0.73 + 1.54 χ^0.75), embedded to D
//            × [1 + D/(21 B) (1 + 1.3 χ)] [1 + 0.2 (A_w/A_b)^(2/3)],
//            C_z = ρ V_La A_b (Gazetas 1991, Tables 1 and 2; Mylonakis,
//            Nikolaou & Gazetas 2006, Table 1);
//   cone:    K_z = 4 G r_h / (1 - ν), C_z = ρ c A_b (c as for rocking), and
//            for ν > 1/3 a trapped mass ΔM = 2.4 π (ν - 1/3) ρ r_h³ (Wolf
//            1994, Table 2-1; the disk's exact static value).
// doc/theory.md §1.16.
#ifndef poundfe_laws_foundation_impedance_h
#define poundfe_laws_foundation_impedance_h

namespace poundfe
{
  /// The soil: an elastic half-space.
  struct SoilProperties
  {
    double shear_wave_velocity = 0; // V_s, m/s
    double density             = 0; // ρ, kg/m³
    double poisson_ratio       = 0; // ν in (0, 0.5)

    double shear_modulus() const { return density * shear_wave_velocity * shear_wave_velocity; }
  };

  /// A rectangular rigid foundation: its side in the plane of motion, the
  /// side normal to it, and its embedment (0: on the surface).
  struct FoundationGeometry
  {
    double length    = 0; // in the plane, m
    double width     = 0; // normal to the plane, m
    double embedment = 0; // D, m
  };

  /// Springs, dashpots and the soil's added rotary inertia of one foundation
  /// in the plane.
  struct FoundationImpedance
  {
    double horizontal_stiffness = 0; // N/m
    double rocking_stiffness    = 0; // N m/rad
    double horizontal_damping   = 0; // N s/m
    double rocking_damping      = 0; // N m s/rad
    double added_rotary_inertia = 0; // kg m² (Wolf's trapped soil, ν > 1/3)
    double vertical_stiffness   = 0; // N/m
    double vertical_damping     = 0; // N s/m
    double added_mass           = 0; // kg, on the vertical (Wolf's trapped soil)
  };

  /// Springs, dashpots and added inertias of one foundation in 3D, in its
  /// local axes: [0] along (sway) or about (rocking) x, [1] y.
  struct FoundationImpedance3D
  {
    double sway_stiffness[2]       = {0, 0}; // N/m
    double sway_damping[2]         = {0, 0}; // N s/m
    double rocking_stiffness[2]    = {0, 0}; // N m/rad
    double rocking_damping[2]      = {0, 0}; // N m s/rad
    double added_rotary_inertia[2] = {0, 0}; // kg m²
    double torsional_stiffness     = 0;      // N m/rad
    double torsional_damping       = 0;      // N m s/rad
    double vertical_stiffness      = 0;      // N/m
    double vertical_damping        = 0;      // N s/m
    double added_mass              = 0;      // kg, on the vertical
  };

  /// Gazetas in 3D, surface or embedded (as gazetas_impedance).
  FoundationImpedance3D gazetas_impedance_3d(const SoilProperties     &soil,
                                             const FoundationGeometry &foundation);

  /// Wolf's cones in 3D, on the surface.
  FoundationImpedance3D cone_impedance_3d(const SoilProperties     &soil,
                                          const FoundationGeometry &foundation);

  /// Gazetas (1991), surface or embedded (embedment <= the smaller side).
  FoundationImpedance gazetas_impedance(const SoilProperties &soil,
                                        const FoundationGeometry &foundation);

  /// Wolf's cones (1994) on the surface (embedment ignored: the caller
  /// refuses it).
  FoundationImpedance cone_impedance(const SoilProperties &soil,
                                     const FoundationGeometry &foundation);
} // namespace poundfe

#endif
