// Gazetas (1991) and Wolf (1994) impedances: the equations and sources are
// in include/poundfe/laws/foundation_impedance.h and doc/theory.md §1.16.
#include <poundfe/laws/foundation_impedance.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;
  }

  FoundationImpedance
  gazetas_impedance(const SoilProperties &soil, const FoundationGeometry &foundation)
  {
    const double G  = soil.shear_modulus();
    const double nu = soil.poisson_ratio;
    const double L  = 0.5 * std::max(foundation.length, foundation.width);
    const double B  = 0.5 * std::min(foundation.length, foundation.width);
    const double chi = B / L;
    // the plane of motion along the long side: sway along x, rocking about y
    const bool   along_long = foundation.length >= foundation.width;
    const double area       = 4 * B * L;
    const double k_y        = 2 * G * L / (2 - nu) * (2 + 2.5 * std::pow(chi, 0.85));
    const double k_x        = k_y - 0.2 * G * L * (1 - chi) / (0.75 - nu);
    const double i_bx       = 2 * L * std::pow(2 * B, 3) / 12; // about the long axis
    const double i_by       = 2 * B * std::pow(2 * L, 3) / 12; // about the short axis
    const double k_rx = G / (1 - nu) * std::pow(i_bx, 0.75) * std::pow(L / B, 0.25) *
                        (2.4 + 0.5 * chi);
    const double k_ry = 3 * G / (1 - nu) * std::pow(i_by, 0.75) * std::pow(L / B, 0.15);

    double sway_factor = 1, rocking_factor = 1;
    const double D = foundation.embedment;
    if (D > 0)
      {
        const double d = D, h = D - d / 2, wall_area = 4 * d * (B + L);
        const double across = along_long ? L * B * B : B * L * L;
        sway_factor = (1 + 0.15 * std::sqrt(D / B)) *
                      (1 + 0.52 * std::pow(h * wall_area / across, 0.4));
        rocking_factor =
          along_long ?
            1 + 0.92 * std::pow(d / L, 0.6) *
                  (1.5 + std::pow(d / L, 1.9) * std::pow(d / D, -0.6)) :
            1 + 1.26 * (d / B) * (1 + (d / B) * std::pow(d / D, -0.2) * std::sqrt(B / L));
      }
    double vertical_factor = 1;
    if (D > 0)
      vertical_factor = (1 + D / (21 * B) * (1 + 1.3 * chi)) *
                        (1 + 0.2 * std::pow(4 * D * (B + L) / area, 2.0 / 3));
    const double analog_velocity = 3.4 * soil.shear_wave_velocity / (pi * (1 - nu));
    FoundationImpedance z;
    z.vertical_stiffness =
      2 * G * L / (1 - nu) * (0.73 + 1.54 * std::pow(chi, 0.75)) * vertical_factor;
    z.vertical_damping = soil.density * analog_velocity * area;
    z.horizontal_stiffness = (along_long ? k_x : k_y) * sway_factor;
    z.rocking_stiffness    = (along_long ? k_ry : k_rx) * rocking_factor;
    z.horizontal_damping   = soil.density * soil.shear_wave_velocity * area;
    z.rocking_damping      = soil.density * analog_velocity * (along_long ? i_by : i_bx);
    return z;
  }

  namespace
  {
    /// The sway and rocking of the planes x-z and y-z (two 2D impedances).
    template <typename Impedance2D>
    FoundationImpedance3D
    in_two_planes(const SoilProperties &soil, const FoundationGeometry &foundation,
                  const Impedance2D &impedance_2d)
    {
      const FoundationImpedance in_x = impedance_2d(soil, foundation);
      const FoundationImpedance in_y =
        impedance_2d(soil, {foundation.width, foundation.length, foundation.embedment});
      FoundationImpedance3D z;
      z.sway_stiffness[0]       = in_x.horizontal_stiffness;
      z.sway_stiffness[1]       = in_y.horizontal_stiffness;
      z.sway_damping[0]         = in_x.horizontal_damping;
      z.sway_damping[1]         = in_y.horizontal_damping;
      // rocking about y is the plane x-z's, about x the plane y-z's
      z.rocking_stiffness[0]    = in_y.rocking_stiffness;
      z.rocking_stiffness[1]    = in_x.rocking_stiffness;
      z.rocking_damping[0]      = in_y.rocking_damping;
      z.rocking_damping[1]      = in_x.rocking_damping;
      z.added_rotary_inertia[0] = in_y.added_rotary_inertia;
      z.added_rotary_inertia[1] = in_x.added_rotary_inertia;
      z.vertical_stiffness      = in_x.vertical_stiffness;
      z.vertical_damping        = in_x.vertical_damping;
      z.added_mass              = in_x.added_mass;
      return z;
    }

    /// J_t = I_bx + I_by of the rectangular base.
    double
    polar_moment_of_area(const FoundationGeometry &foundation)
    {
      const double a = foundation.length, b = foundation.width;
      return a * b * (a * a + b * b) / 12;
    }
  } // namespace

  FoundationImpedance3D
  gazetas_impedance_3d(const SoilProperties &soil, const FoundationGeometry &foundation)
  {
    FoundationImpedance3D z  = in_two_planes(soil, foundation, gazetas_impedance);
    const double          L  = 0.5 * std::max(foundation.length, foundation.width);
    const double          B  = 0.5 * std::min(foundation.length, foundation.width);
    const double          jt = polar_moment_of_area(foundation);
    const double          d  = foundation.embedment;
    z.torsional_stiffness    = soil.shear_modulus() * std::pow(jt, 0.75) *
                            (4 + 11 * std::pow(1 - B / L, 10)) *
                            (1 + 1.4 * (1 + B / L) * std::pow(d / B, 0.9));
    z.torsional_damping = soil.density * soil.shear_wave_velocity * jt;
    return z;
  }

  FoundationImpedance3D
  cone_impedance_3d(const SoilProperties &soil, const FoundationGeometry &foundation)
  {
    FoundationImpedance3D z  = in_two_planes(soil, foundation, cone_impedance);
    const double          jt = polar_moment_of_area(foundation);
    const double          r  = std::pow(2 * jt / pi, 0.25);
    z.torsional_stiffness    = 16 * soil.shear_modulus() * r * r * r / 3;
    z.torsional_damping      = soil.density * soil.shear_wave_velocity * jt;
    return z;
  }

  FoundationImpedance
  cone_impedance(const SoilProperties &soil, const FoundationGeometry &foundation)
  {
    const double G      = soil.shear_modulus();
    const double nu     = soil.poisson_ratio;
    const double vs     = soil.shear_wave_velocity;
    const double area   = foundation.length * foundation.width;
    const double moment = foundation.width * std::pow(foundation.length, 3) / 12;
    const double r_h    = std::sqrt(area / pi);
    const double r_r    = std::pow(4 * moment / pi, 0.25);
    const double vp     = vs * std::sqrt(2 * (1 - nu) / (1 - 2 * nu));
    const bool   nearly_incompressible = nu > 1.0 / 3;
    FoundationImpedance z;
    z.horizontal_stiffness = 8 * G * r_h / (2 - nu);
    z.rocking_stiffness    = 8 * G * std::pow(r_r, 3) / (3 * (1 - nu));
    z.horizontal_damping   = soil.density * vs * pi * r_h * r_h;
    z.rocking_damping =
      soil.density * (nearly_incompressible ? 2 * vs : vp) * pi * std::pow(r_r, 4) / 4;
    z.vertical_stiffness = 4 * G * r_h / (1 - nu);
    z.vertical_damping   = soil.density * (nearly_incompressible ? 2 * vs : vp) * area;
    if (nearly_incompressible)
      {
        z.added_rotary_inertia = 0.3 * pi * (nu - 1.0 / 3) * soil.density * std::pow(r_r, 5);
        z.added_mass           = 2.4 * pi * (nu - 1.0 / 3) * soil.density * std::pow(r_h, 3);
      }
    return z;
  }
} // namespace poundfe
