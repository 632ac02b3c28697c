// Confined concrete after Mander, Priestley & Park (1988).
//   Effective lateral confining stress: fl' = ke rho fyh, with the
//   confinement effectiveness (arching between bars and hoops)
//     circular hoops:  ke = (1 - s' / (2 ds))^2 / (1 - rho_cc),
//     spirals:         ke = (1 - s' / (2 ds)) / (1 - rho_cc),
//     rectangular:     ke = (1 - sum w'^2 / (6 bc dc)) (1 - s' / (2 bc))
//                           (1 - s' / (2 dc)) / (1 - rho_cc),
//   rho_s = 4 Asp / (ds s) and fl' = ke rho_s fyh / 2 for circular
//   sections; rho_x = Asx / (s dc), rho_y = Asy / (s bc) for rectangular.
//   Confined strength: equal confinement (the paper's eq. 29)
//     f'cc = f'c0 (-1.254 + 2.254 sqrt(1 + 7.94 fl' / f'c0) - 2 fl' / f'c0);
//   unequal confinement (rectangular sections) from the five-parameter
//   ultimate strength surface (Willam & Warnke 1975) of the paper's
//   appendix: with s_oct = (s1 + s2 + s3) / 3 and t_oct the octahedral
//   stresses over f'c0 (compression negative, s1 >= s2 >= s3 = -f'cc/f'c0),
//   cos(theta) = (s1 - s_oct) / (sqrt(2) t_oct), the meridians
//     T = 0.069232 - 0.661091 s_oct - 0.049350 s_oct^2   (theta = 0),
//     C = 0.122965 - 1.150502 s_oct - 0.315545 s_oct^2   (theta = 60 deg),
//   and the surface t_oct = r(theta) by Willam–Warnke's elliptic
//     r = [2C (C^2 - T^2) c + C (2T - C) sqrt(4 (C^2 - T^2) c^2 + 5T^2 - 4TC)]
//         / [4 (C^2 - T^2) c^2 + (C - 2T)^2],   c = cos(theta).
//   The axial stress s3 on the surface is found by bisection (the paper's
//   chart, its Fig. 4, is this solution drawn). Here the chart is not
//   approximated: the surface itself is solved; eq. 29 is its closed form on
//   the compression meridian (equal confinement).
//   Strain at f'cc: eps_cc = eps_c0 (1 + 5 (f'cc / f'c0 - 1)) (Richart et al.).
//   Ultimate strain: eps_cu = 0.004 + 1.4 rho_s fyh eps_su / f'cc, the
//   energy-balance estimate of Priestley, Seible & Calvi (1996) (rho_s =
//   rho_x + rho_y for rectangular sections): the paper's own energy balance
//   needs the integral of the whole curve and of the steel's.
//   Stress-strain curve (Popovics 1973): f = f'cc x r / (r - 1 + x^r).
// Sources: J.B. Mander, M.J.N. Priestley & R. Park (1988), Theoretical
// stress-strain model for confined concrete, J. Struct. Eng. ASCE 114(8)
// 1804–1826; K.J. Willam & E.P. Warnke (1975), IABSE Proc. 19; M.J.N.
// Priestley, F. Seible & G.M. Calvi (1996), Seismic design and retrofit of
// bridges, Wiley, eq. 5.14. Theory: doc/theory.md §12.7.
#include <poundfe/laws/mander_confinement.h>

#include <cmath>

namespace poundfe
{
  namespace
  {
    /// t_oct on the surface at (s_oct, cos theta), all over f'c0.
    double
    mander_surface_radius(const double s_oct, const double cos_theta)
    {
      const double T  = 0.069232 - 0.661091 * s_oct - 0.049350 * s_oct * s_oct;
      const double C  = 0.122965 - 1.150502 * s_oct - 0.315545 * s_oct * s_oct;
      const double c2 = cos_theta * cos_theta, D = C * C - T * T;
      const double root = std::sqrt(4 * D * c2 + 5 * T * T - 4 * T * C);
      return (2 * C * D * cos_theta + C * (2 * T - C) * root) /
             (4 * D * c2 + (C - 2 * T) * (C - 2 * T));
    }

    /// t_oct minus the surface's radius at the stresses (s1, s2, s3):
    /// negative inside the surface.
    double
    mander_outside(const double s1, const double s2, const double s3)
    {
      const double s_oct = (s1 + s2 + s3) / 3;
      const double t_oct =
        std::sqrt((s1 - s2) * (s1 - s2) + (s2 - s3) * (s2 - s3) + (s3 - s1) * (s3 - s1)) / 3;
      if (t_oct == 0)
        return -1;
      const double cos_theta = (s1 - s_oct) / (std::sqrt(2.0) * t_oct);
      return t_oct - mander_surface_radius(s_oct, cos_theta);
    }

    void
    check_mander_materials(const ManderMaterials &m)
    {
      require_positive("Mander", "fc0", m.fc0);
      require_positive("Mander", "eps_c0", m.eps_c0);
      require_positive("Mander", "fyh", m.fyh);
      require_positive("Mander", "eps_su", m.eps_su);
    }

    /// eps_cc, eps_cu of a confined strength, and the record.
    ManderConfinement
    mander_result(const ManderMaterials &m, const double ratio, const double rho_s,
                  const double ke, const double fl_x, const double fl_y)
    {
      ManderConfinement c;
      c.fcc    = ratio * m.fc0;
      c.eps_cc = m.eps_c0 * (1 + 5 * (ratio - 1));
      c.eps_cu = 0.004 + 1.4 * rho_s * m.fyh * m.eps_su / c.fcc;
      c.ke     = ke;
      c.rho_s  = rho_s;
      c.fl_x   = fl_x;
      c.fl_y   = fl_y;
      return c;
    }
  } // namespace

  double
  mander_equal_confinement_ratio(const double x)
  {
    return -1.254 + 2.254 * std::sqrt(1 + 7.94 * x) - 2 * x;
  }

  double
  mander_surface_ratio(const double fl1, const double fl2)
  {
    const double s1 = -std::min(fl1, fl2), s2 = -std::max(fl1, fl2);
    // bracket the axial stress: inside at s3 = s2, outside far enough down
    double inside = s2, outside = s2 - 1;
    while (mander_outside(s1, s2, outside) < 0)
      outside -= 1;
    for (int it = 0; it < 200 && inside - outside > 1e-14 * std::abs(outside); ++it)
      {
        const double middle = 0.5 * (inside + outside);
        (mander_outside(s1, s2, middle) < 0 ? inside : outside) = middle;
      }
    return -0.5 * (inside + outside);
  }

  ManderConfinement
  mander_from_volumetric_ratio(const ManderMaterials &m, const double rho_s, const double ke)
  {
    check_mander_materials(m);
    require_positive("Mander", "rho_s", rho_s);
    if (!(ke > 0 && ke <= 1))
      refuse_parameter("Mander", "ke", "the confinement effectiveness must lie in (0, 1]");
    const double fl = 0.5 * ke * rho_s * m.fyh;
    return mander_result(m, mander_equal_confinement_ratio(fl / m.fc0), rho_s, ke, fl, fl);
  }

  ManderConfinement
  mander_circular(const ManderCircularSection &c)
  {
    require_positive("Mander", "ds", c.ds);
    require_positive("Mander", "s", c.s);
    require_positive("Mander", "Asp", c.Asp);
    require_in("Mander", "s_clear", c.s_clear, 0, c.s);
    require_in("Mander", "rho_cc", c.rho_cc, 0, 1);
    const double arching = 1 - c.s_clear / (2 * c.ds);
    const double ke      = (c.spiral ? arching : arching * arching) / (1 - c.rho_cc);
    return mander_from_volumetric_ratio(c.materials, 4 * c.Asp / (c.ds * c.s), ke);
  }

  ManderConfinement
  mander_rectangular(const ManderRectangularSection &r)
  {
    check_mander_materials(r.materials);
    require_positive("Mander", "bc", r.bc);
    require_positive("Mander", "dc", r.dc);
    require_positive("Mander", "s", r.s);
    require_positive("Mander", "Asx", r.Asx);
    require_positive("Mander", "Asy", r.Asy);
    require_in("Mander", "s_clear", r.s_clear, 0, r.s);
    require_in("Mander", "rho_cc", r.rho_cc, 0, 1);
    double arches = 0;
    for (const double w : r.w_clear)
      arches += w * w;
    const double ke = (1 - arches / (6 * r.bc * r.dc)) * (1 - r.s_clear / (2 * r.bc)) *
                      (1 - r.s_clear / (2 * r.dc)) / (1 - r.rho_cc);
    if (!(ke > 0))
      refuse_parameter("Mander", "w_clear", "the unconfined arches leave no confined core");
    const double rho_x = r.Asx / (r.s * r.dc), rho_y = r.Asy / (r.s * r.bc);
    const double fl_x = ke * rho_x * r.materials.fyh, fl_y = ke * rho_y * r.materials.fyh;
    const double fc0  = r.materials.fc0;
    return mander_result(r.materials, mander_surface_ratio(fl_x / fc0, fl_y / fc0),
                         rho_x + rho_y, ke, fl_x, fl_y);
  }

  double
  mander_stress(const ManderConfinement &c, const double Ec, const double strain)
  {
    const double r = Ec / (Ec - c.fcc / c.eps_cc);
    const double x = strain / c.eps_cc;
    return c.fcc * x * r / (r - 1 + std::pow(x, r));
  }

  Concrete01Parameters
  mander_concrete01(const ManderConfinement &c, const double fc0, const double Ec)
  {
    // 5000 sqrt(f'c0 [MPa]) MPa, in Pa
    const double E = Ec > 0 ? Ec : 5000e6 * std::sqrt(fc0 / 1e6);
    if (!(E > c.fcc / c.eps_cc))
      refuse_parameter("Mander", "Ec", "must exceed the secant modulus f'cc / eps_cc");
    return {-c.fcc, -c.eps_cc, -mander_stress(c, E, c.eps_cu), -c.eps_cu};
  }
} // namespace poundfe
