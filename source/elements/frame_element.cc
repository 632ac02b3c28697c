#include <poundfe/elements/frame_element.h>

#include <cmath>

namespace poundfe
{
  FrameElement::FrameElement(const Point2 &start, const Point2 &end, const Section &section)
    : element_length(std::hypot(end.x - start.x, end.y - start.y))
    , cosine((end.x - start.x) / element_length)
    , sine((end.y - start.y) / element_length)
    , section(section)
  {}

  Matrix6
  FrameElement::rotation() const
  {
    Matrix6 t = Matrix6::Zero();
    for (unsigned int end = 0; end < 2; ++end)
      {
        const unsigned int o = 3 * end;
        t(o, o)         = cosine;
        t(o, o + 1)     = sine;
        t(o + 1, o)     = -sine;
        t(o + 1, o + 1) = cosine;
        t(o + 2, o + 2) = 1;
      }
    return t;
  }

  Matrix6
  FrameElement::local_stiffness() const
  {
    const double L  = element_length;
    const double ea = section.youngs_modulus * section.area / L;
    const double ei = section.youngs_modulus * section.second_moment;
    const double k1 = 12 * ei / (L * L * L), k2 = 6 * ei / (L * L), k3 = 4 * ei / L,
                 k4 = 2 * ei / L;
    Matrix6 k;
    // clang-format off
    k <<  ea,   0,   0, -ea,   0,   0,
           0,  k1,  k2,   0, -k1,  k2,
           0,  k2,  k3,   0, -k2,  k4,
         -ea,   0,   0,  ea,   0,   0,
           0, -k1, -k2,   0,  k1, -k2,
           0,  k2,  k4,   0, -k2,  k3;
    // clang-format on
    return k;
  }

  Matrix6
  FrameElement::stiffness() const
  {
    const Matrix6 t = rotation();
    return t.transpose() * local_stiffness() * t;
  }

  Matrix6
  FrameElement::mass(const MassMatrixType type) const
  {
    const double L    = element_length;
    const double m    = section.mass_per_length * L;
    Matrix6      mass = Matrix6::Zero();
    if (m == 0)
      return mass;
    if (type == MassMatrixType::lumped)
      {
        for (const unsigned int i : {0, 1, 3, 4})
          mass(i, i) = 0.5 * m;
        return mass;
      }
    const double a = m / 6, b = m / 420;
    // clang-format off
    mass <<  2*a,        0,          0,   a,          0,          0,
               0,    156*b,    22*L*b,    0,      54*b,    -13*L*b,
               0,   22*L*b,  4*L*L*b,    0,    13*L*b,   -3*L*L*b,
               a,        0,          0, 2*a,          0,          0,
               0,     54*b,    13*L*b,    0,     156*b,    -22*L*b,
               0,  -13*L*b, -3*L*L*b,    0,   -22*L*b,    4*L*L*b;
    // clang-format on
    const Matrix6 t = rotation();
    return t.transpose() * mass * t;
  }

  Matrix6
  FrameElement::geometric_stiffness(const double axial_force) const
  {
    const double L = element_length;
    const double a = axial_force / (30 * L);
    Matrix6      k = Matrix6::Zero();
    // clang-format off
    const double transverse[4][4] = {{ 36,     3*L,  -36,    3*L},
                                     { 3*L,  4*L*L, -3*L,   -L*L},
                                     {-36,    -3*L,   36,   -3*L},
                                     { 3*L,   -L*L, -3*L,  4*L*L}};
    // clang-format on
    const unsigned int dof[4] = {1, 2, 4, 5}; // v1, rz1, v2, rz2 in local axes
    for (unsigned int i = 0; i < 4; ++i)
      for (unsigned int j = 0; j < 4; ++j)
        k(dof[i], dof[j]) = a * transverse[i][j];
    const Matrix6 t = rotation();
    return t.transpose() * k * t;
  }

  double
  FrameElement::axial_force(const Vector6 &global_displacements) const
  {
    return local_end_forces(global_displacements)[3]; // N2 = EA (u2 - u1) / L
  }

  Vector6
  FrameElement::local_end_forces(const Vector6 &global_displacements) const
  {
    return local_stiffness() * (rotation() * global_displacements);
  }

  std::array<double, 3>
  FrameElement::displacement_at(const Vector6 &global_displacements, const double xi) const
  {
    const Vector6 local = rotation() * global_displacements; // u1 v1 r1 u2 v2 r2
    const double  L     = element_length;
    const double  axial = (1 - xi) * local[0] + xi * local[3];
    const double  xi2 = xi * xi, xi3 = xi2 * xi;
    const double  transverse = (1 - 3 * xi2 + 2 * xi3) * local[1] +
                              (xi - 2 * xi2 + xi3) * L * local[2] +
                              (3 * xi2 - 2 * xi3) * local[4] + (xi3 - xi2) * L * local[5];
    const double slope = (-6 * xi + 6 * xi2) / L * local[1] + (1 - 4 * xi + 3 * xi2) * local[2] +
                         (6 * xi - 6 * xi2) / L * local[4] + (3 * xi2 - 2 * xi) * local[5];
    return {{cosine * axial - sine * transverse, sine * axial + cosine * transverse, slope}};
  }
} // namespace poundfe
