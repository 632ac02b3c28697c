// Two-node Euler-Bernoulli beam-column element in the plane, DOFs
// (ux, uy, rz) at each end.
//   Local stiffness: axial EA/L, bending 12EI/L^3, 6EI/L^2, 4EI/L, 2EI/L.
//   Consistent mass: axial mL/6 [2 1; 1 2], bending mL/420 [156 22L 54 -13L; ...].
//   Lumped mass: mL/2 on each end's translations, none on rotations.
//   Global matrices: T^T k T with T the rotation by the member angle.
//   Geometric stiffness under an axial force N (tension +), on the transverse
//   DOFs (v1, rz1, v2, rz2): N/(30L) [36 3L -36 3L; 3L 4L^2 -3L -L^2;
//   -36 -3L 36 -3L; 3L -L^2 -3L 4L^2], from the same cubic shape functions
//   (consistent); no terms on the axial DOFs (their relative size is N/EA).
//   Displacement inside: u(xi) = (1 - xi) u1 + xi u2 (axial), v(xi) = N1 v1 +
//   N2 L r1 + N3 v2 + N4 L r2, N1 = 1 - 3xi^2 + 2xi^3, N2 = xi - 2xi^2 + xi^3,
//   N3 = 3xi^2 - 2xi^3, N4 = xi^3 - xi^2 (xi = x/L).
// Source: Przemieniecki, Theory of Matrix Structural Analysis (1968), ch. 5
// & 11 and its geometric (stability) matrices; McGuire, Gallagher & Ziemian,
// Matrix Structural Analysis, 2nd ed. (2000), eq. 9.19 (its transverse
// part); Chopra, Dynamics of Structures, 4th ed., §16.
#ifndef poundfe_elements_frame_element_h
#define poundfe_elements_frame_element_h

#include <poundfe/model/model.h>

#include <Eigen/Core>

#include <array>

namespace poundfe
{
  using Matrix6 = Eigen::Matrix<double, 6, 6>;
  using Vector6 = Eigen::Matrix<double, 6, 1>;

  class FrameElement
  {
  public:
    FrameElement(const Point2 &start, const Point2 &end, const Section &section);

    double length() const { return element_length; }

    /// Stiffness in local axes (x along the member).
    Matrix6 local_stiffness() const;
    /// Global stiffness T^T k T.
    Matrix6 stiffness() const;
    /// Global mass matrix (translational mass is invariant under rotation
    /// for the lumped form; the consistent form is rotated).
    Matrix6 mass(MassMatrixType type) const;
    /// Member end forces in local axes (N1, V1, M1, N2, V2, M2) from global
    /// end displacements.
    Vector6 local_end_forces(const Vector6 &global_displacements) const;
    /// Global geometric stiffness T^T k_G T under the axial force N
    /// (tension positive: compression softens the member).
    Matrix6 geometric_stiffness(double axial_force) const;
    /// Axial force (tension positive) from global end displacements.
    double axial_force(const Vector6 &global_displacements) const;
    /// Global-to-local rotation T.
    Matrix6 rotation() const;
    /// Global displacement (ux, uy, rz) at x = xi L along the member from
    /// the global end displacements: the axial displacement linear, the
    /// transverse one by the cubic Hermite shape functions of the stiffness
    /// (exact for a member loaded at its ends), rz its slope.
    std::array<double, 3> displacement_at(const Vector6 &global_displacements, double xi) const;

  private:
    double  element_length;
    double  cosine;
    double  sine;
    Section section;
  };
} // namespace poundfe

#endif
