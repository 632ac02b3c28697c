// Confined concrete after Mander, Priestley & Park (1988): the confined
// strength f'cc, its strain eps_cc and the ultimate strain eps_cu from the
// unconfined strength and the transverse reinforcement, to feed
// Concrete01/Concrete02's parameters (equations in
// source/laws/mander_confinement.cc). Stresses are positive magnitudes here.
#ifndef poundfe_laws_mander_confinement_h
#define poundfe_laws_mander_confinement_h

#include <poundfe/laws/concrete01.h>

#include <vector>

namespace poundfe
{
  struct ManderConfinement
  {
    double fcc     = 0; // confined compressive strength (Pa)
    double eps_cc  = 0; // strain at fcc
    double eps_cu  = 0; // ultimate strain (first hoop fracture)
    double ke      = 0; // confinement effectiveness
    double rho_s   = 0; // volumetric ratio of transverse steel
    double fl_x    = 0; // effective lateral confining stresses (Pa)
    double fl_y    = 0;
  };

  /// Unconfined concrete and transverse steel, common to every section.
  struct ManderMaterials
  {
    double fc0    = 0;     // unconfined strength (Pa)
    double eps_c0 = 0.002; // strain at fc0
    double fyh    = 0;     // yield stress of the transverse steel (Pa)
    double eps_su = 0;     // strain of the transverse steel at its maximum stress
  };

  /// Circular sections with hoops or a spiral.
  struct ManderCircularSection
  {
    ManderMaterials materials;
    double          ds      = 0;     // core diameter to the hoops' centreline (m)
    double          s       = 0;     // centre spacing of the hoops (m)
    double          s_clear = 0;     // clear spacing s' (m)
    double          Asp     = 0;     // area of the hoop bar (m^2)
    double          rho_cc  = 0;     // longitudinal steel over the core area
    bool            spiral  = false; // a spiral rather than circular hoops
  };

  /// Rectangular sections with rectilinear hoops (and cross ties).
  struct ManderRectangularSection
  {
    ManderMaterials     materials;
    double              bc = 0, dc = 0; // core sides to the hoops' centreline, along x and y (m)
    double              s       = 0;    // centre spacing of the hoop sets (m)
    double              s_clear = 0;    // clear spacing s' (m)
    double              Asx = 0, Asy = 0; // total area of the legs along x and along y (m^2)
    double              rho_cc = 0;       // longitudinal steel over the core area
    std::vector<double> w_clear;          // clear spacings w' between restrained bars (m)
  };

  /// f'cc / f'c0 under equal effective lateral stress fl (the paper's
  /// closed form, its eq. 29): -1.254 + 2.254 sqrt(1 + 7.94 x) - 2 x, x = fl / f'c0.
  double mander_equal_confinement_ratio(double fl_over_fc0);

  /// f'cc / f'c0 under effective lateral stresses fl1, fl2 (any order, as
  /// fractions of f'c0) from the five-parameter ultimate strength surface
  /// (Willam & Warnke 1975, with the meridians Mander et al. fitted to
  /// Schickert & Winkler's tests), solved for the axial stress.
  double mander_surface_ratio(double fl1_over_fc0, double fl2_over_fc0);

  /// From the volumetric ratio and the effectiveness: fl = ke rho_s fyh / 2 on
  /// both axes (circular sections, or square ones with equal steel).
  ManderConfinement mander_from_volumetric_ratio(const ManderMaterials &materials, double rho_s,
                                                 double ke);
  ManderConfinement mander_circular(const ManderCircularSection &section);
  /// fl_x = ke rho_x fyh, fl_y = ke rho_y fyh, rho_x = Asx / (s dc),
  /// rho_y = Asy / (s bc), f'cc from the surface.
  ManderConfinement mander_rectangular(const ManderRectangularSection &section);

  /// Concrete01's parameters (negative) for the confined core: (eps_cc,
  /// fcc), and at eps_cu the stress of Mander's curve (Popovics' form with
  /// Ec = 5000 sqrt(f'c0 in MPa) MPa unless `Ec` > 0 is given).
  Concrete01Parameters mander_concrete01(const ManderConfinement &confined, double fc0,
                                         double Ec = 0);
  /// Mander's stress-strain curve: f'cc x r / (r - 1 + x^r), x = eps / eps_cc,
  /// r = Ec / (Ec - f'cc / eps_cc) (magnitudes).
  double mander_stress(const ManderConfinement &confined, double Ec, double strain);
} // namespace poundfe

#endif
