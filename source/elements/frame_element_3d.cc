// The 3D beam-column of include/poundfe/elements/frame_element_3d.h (its
// equations and sources are there; doc/theory.md §1.11).
#include <poundfe/base/exceptions.h>
#include <poundfe/elements/frame_element_3d.h>

#include <Eigen/Geometry>

#include <array>
#include <cmath>

namespace poundfe
{
  namespace
  {
    using Matrix4 = Eigen::Matrix4d;

    /// The DOFs of one bending plane in the local 12 (v or w, θ at each
    /// end) and the sign that turns its rotation into the slope convention
    /// of the planar matrices: θz = dv/dx, but θy = -dw/dx.
    struct BendingPlane
    {
      std::array<unsigned int, 4> dofs;
      std::array<double, 4>       signs;
    };
    constexpr BendingPlane plane_xy{{{1, 5, 7, 11}}, {{1, 1, 1, 1}}};
    constexpr BendingPlane plane_xz{{{2, 4, 8, 10}}, {{1, -1, 1, -1}}};

    constexpr unsigned int axial_dof   = 0;
    constexpr unsigned int torsion_dof = 3;

    void
    add_bending(Matrix12 &k, const BendingPlane &plane, const Matrix4 &block)
    {
      for (unsigned int i = 0; i < 4; ++i)
        for (unsigned int j = 0; j < 4; ++j)
          k(plane.dofs[i], plane.dofs[j]) += plane.signs[i] * plane.signs[j] * block(i, j);
    }

    /// [diagonal off; off diagonal] on the DOF `dof` of both ends.
    void
    add_two_node(Matrix12 &k, const unsigned int dof, const double diagonal, const double off)
    {
      k(dof, dof) += diagonal;
      k(dof + 6, dof + 6) += diagonal;
      k(dof, dof + 6) += off;
      k(dof + 6, dof) += off;
    }

    /// A symmetric 4x4 of a bending plane from its upper triangle.
    Matrix4
    symmetric(const double a11, const double a12, const double a13, const double a14,
              const double a22, const double a23, const double a24, const double a33,
              const double a34, const double a44)
    {
      Matrix4 m;
      // clang-format off
      m << a11, a12, a13, a14,
           a12, a22, a23, a24,
           a13, a23, a33, a34,
           a14, a24, a34, a44;
      // clang-format on
      return m;
    }

    Matrix4
    bending_stiffness(const double ei, const double L, const double phi)
    {
      const double c = ei / ((1 + phi) * L * L * L);
      return c * symmetric(12, 6 * L, -12, 6 * L, (4 + phi) * L * L, -6 * L, (2 - phi) * L * L,
                           12, -6 * L, (4 + phi) * L * L);
    }

    /// ∫ m̄ v² over the element for the Timoshenko shape functions.
    Matrix4
    translational_mass(const double m, const double L, const double p)
    {
      const double c   = m / ((1 + p) * (1 + p));
      const double a11 = 13. / 35 + 7 * p / 10 + p * p / 3;
      const double a12 = (11. / 210 + 11 * p / 120 + p * p / 24) * L;
      const double a13 = 9. / 70 + 3 * p / 10 + p * p / 6;
      const double a14 = -(13. / 420 + 3 * p / 40 + p * p / 24) * L;
      const double a22 = (1. / 105 + p / 60 + p * p / 120) * L * L;
      const double a24 = -(1. / 140 + p / 60 + p * p / 120) * L * L;
      return c * symmetric(a11, a12, a13, a14, a22, -a14, a24, a11, -a12, a22);
    }

    /// ∫ ρI ψ² over the element (ψ the rotation of the section).
    Matrix4
    rotary_mass(const double rho_i, const double L, const double p)
    {
      const double c   = rho_i / ((1 + p) * (1 + p) * L);
      const double a12 = (1. / 10 - p / 2) * L;
      const double a22 = (2. / 15 + p / 6 + p * p / 3) * L * L;
      const double a24 = -(1. / 30 + p / 6 - p * p / 6) * L * L;
      return c * symmetric(6. / 5, a12, -6. / 5, a12, a22, -a12, a24, 6. / 5, -a12, a22);
    }

    /// ∫ N v'² over the element.
    Matrix4
    bending_geometric(const double n, const double L, const double p)
    {
      const double c   = n / ((1 + p) * (1 + p) * L);
      const double a11 = 6. / 5 + 2 * p + p * p;
      const double a22 = (2. / 15 + p / 6 + p * p / 12) * L * L;
      const double a24 = -(1. / 30 + p / 6 + p * p / 12) * L * L;
      return c * symmetric(a11, L / 10, -a11, L / 10, a22, -L / 10, a24, a11, -L / 10, a22);
    }

    /// Φ = 12 EI/(G Av L²), 0 without a shear area (Euler-Bernoulli).
    double
    timoshenko_parameter(const Section3D &s, const double second_moment, const double shear_area,
                         const double L)
    {
      return shear_area > 0 ?
               12 * s.youngs_modulus * second_moment / (s.shear_modulus * shear_area * L * L) :
               0.;
    }

    void
    check_section(const Section3D &s)
    {
      const std::array<std::pair<double, const char *>, 6> required{
        {{s.youngs_modulus, "E"},
         {s.shear_modulus, "G"},
         {s.area, "A"},
         {s.second_moment_y, "Iy"},
         {s.second_moment_z, "Iz"},
         {s.torsion_constant, "J"}}};
      for (const auto &[value, name] : required)
        if (!(value > 0) || !std::isfinite(value))
          throw InputError("", 0, "Section", std::string(name) + " must be a positive number");
      for (const double value : {s.shear_area_y, s.shear_area_z, s.mass_per_length})
        if (!(value >= 0) || !std::isfinite(value))
          throw InputError("", 0, "Section",
                           "shear areas and mass per length must be 0 or positive numbers");
    }

    /// Rows x, y, z of the local axes (OpenSees's geomTransf: y = v_xz × x).
    Eigen::Matrix3d
    local_axes_of(const Eigen::Vector3d &axis, const Eigen::Vector3d &orientation)
    {
      const Eigen::Vector3d x = axis.normalized();
      const Eigen::Vector3d y = orientation.cross(x);
      // |v × x| = |v| sin(angle): a vector (nearly) along the member leaves
      // the local y, z undefined.
      if (!(y.norm() > 1e-6 * orientation.norm()))
        throw InputError("", 0, "Orientation",
                         "the orientation vector (in the local x-z plane) is parallel to the "
                         "member axis or zero; give one at an angle to the member");
      Eigen::Matrix3d r;
      r.row(0) = x;
      r.row(1) = y.normalized();
      r.row(2) = x.cross(r.row(1).transpose());
      return r;
    }
  } // namespace

  FrameElement3D::FrameElement3D(const Eigen::Vector3d &start, const Eigen::Vector3d &end,
                                 const Eigen::Vector3d &orientation, const Section3D &section)
    : element_length((end - start).norm())
    , section(section)
  {
    if (!(element_length > 0) || !std::isfinite(element_length))
      throw InputError("", 0, "Nodes", "a member's two nodes are at the same point");
    check_section(section);
    axes = local_axes_of(end - start, orientation);
  }

  Matrix12
  FrameElement3D::rotation() const
  {
    Matrix12 t = Matrix12::Zero();
    for (unsigned int block = 0; block < 4; ++block)
      t.block<3, 3>(3 * block, 3 * block) = axes;
    return t;
  }

  double
  FrameElement3D::shear_parameter_y() const
  {
    return timoshenko_parameter(section, section.second_moment_z, section.shear_area_y,
                                element_length);
  }

  double
  FrameElement3D::shear_parameter_z() const
  {
    return timoshenko_parameter(section, section.second_moment_y, section.shear_area_z,
                                element_length);
  }

  Matrix12
  FrameElement3D::local_stiffness() const
  {
    const double L  = element_length;
    const double E  = section.youngs_modulus;
    const double ea = E * section.area / L;
    const double gj = section.shear_modulus * section.torsion_constant / L;
    Matrix12     k  = Matrix12::Zero();
    add_two_node(k, axial_dof, ea, -ea);
    add_two_node(k, torsion_dof, gj, -gj);
    const double ei_z = E * section.second_moment_z, ei_y = E * section.second_moment_y;
    add_bending(k, plane_xy, bending_stiffness(ei_z, L, shear_parameter_y()));
    add_bending(k, plane_xz, bending_stiffness(ei_y, L, shear_parameter_z()));
    return k;
  }

  Matrix12
  FrameElement3D::stiffness() const
  {
    const Matrix12 t = rotation();
    return t.transpose() * local_stiffness() * t;
  }

  Matrix12
  FrameElement3D::local_mass(const MassMatrixType type, const RotaryInertia rotary) const
  {
    const double L     = element_length;
    const double m     = section.mass_per_length * L;
    const double rho   = section.mass_per_length / section.area; // mass per volume
    const double rho_p = rho * (section.second_moment_y + section.second_moment_z);
    const bool   with_rotary = rotary == RotaryInertia::included;
    Matrix12     mass        = Matrix12::Zero();
    if (type == MassMatrixType::lumped)
      {
        for (unsigned int end = 0; end < 2; ++end)
          {
            const unsigned int o = 6 * end;
            for (unsigned int i = 0; i < 3; ++i)
              mass(o + i, o + i) = 0.5 * m;
            mass(o + torsion_dof, o + torsion_dof) = 0.5 * rho_p * L;
            if (with_rotary)
              {
                mass(o + 4, o + 4) = 0.5 * rho * section.second_moment_y * L;
                mass(o + 5, o + 5) = 0.5 * rho * section.second_moment_z * L;
              }
          }
        return mass;
      }
    add_two_node(mass, axial_dof, m / 3, m / 6);
    add_two_node(mass, torsion_dof, rho_p * L / 3, rho_p * L / 6);
    const double phi_y = shear_parameter_y(), phi_z = shear_parameter_z();
    add_bending(mass, plane_xy, translational_mass(m, L, phi_y));
    add_bending(mass, plane_xz, translational_mass(m, L, phi_z));
    if (with_rotary)
      {
        add_bending(mass, plane_xy, rotary_mass(rho * section.second_moment_z, L, phi_y));
        add_bending(mass, plane_xz, rotary_mass(rho * section.second_moment_y, L, phi_z));
      }
    return mass;
  }

  Matrix12
  FrameElement3D::mass(const MassMatrixType type, const RotaryInertia rotary) const
  {
    const Matrix12 t = rotation();
    return t.transpose() * local_mass(type, rotary) * t;
  }

  Matrix12
  FrameElement3D::local_geometric_stiffness(const double axial_force) const
  {
    const double L = element_length;
    const double wagner =
      axial_force * (section.second_moment_y + section.second_moment_z) / (section.area * L);
    Matrix12 k = Matrix12::Zero();
    add_two_node(k, torsion_dof, wagner, -wagner);
    add_bending(k, plane_xy, bending_geometric(axial_force, L, shear_parameter_y()));
    add_bending(k, plane_xz, bending_geometric(axial_force, L, shear_parameter_z()));
    return k;
  }

  Matrix12
  FrameElement3D::geometric_stiffness(const double axial_force) const
  {
    const Matrix12 t = rotation();
    return t.transpose() * local_geometric_stiffness(axial_force) * t;
  }

  Vector12
  FrameElement3D::local_end_forces(const Vector12 &global_displacements) const
  {
    return local_stiffness() * (rotation() * global_displacements);
  }

  double
  FrameElement3D::axial_force(const Vector12 &global_displacements) const
  {
    return local_end_forces(global_displacements)[6]; // N2 = EA (u2 - u1) / L
  }
} // namespace poundfe
