// Two-node elastic beam-column element in space, DOFs (ux, uy, uz, rx, ry,
// rz) at each end; local DOFs (u, v, w, θx, θy, θz) per end, in that order.
//   Local axes (OpenSees geomTransf convention): x = (X2 - X1)/L, y = v_xz × x
//   normalised, z = x × y, with v_xz the orientation vector, which lies in
//   the local x-z plane (refused when parallel to the axis).
//   Axial EA/L [1 -1; -1 1] on (u1, u2); torsion GJ/L [1 -1; -1 1] on
//   (θx1, θx2) (Saint-Venant, no warping).
//   Bending in the local x-y plane on (v1, θz1, v2, θz2) with EIz, in x-z on
//   (w1, -θy1, w2, -θy2) with EIy (θy = -dw/dx), each the Timoshenko
//   (Euler-Bernoulli when Φ = 0) matrix
//     EI/((1+Φ)L^3) [12 6L -12 6L; 6L (4+Φ)L² -6L (2-Φ)L²; -12 -6L 12 -6L;
//                    6L (2-Φ)L² -6L (4+Φ)L²],
//   Φ_y = 12 E Iz/(G Avy L²), Φ_z = 12 E Iy/(G Avz L²) (0 when the shear
//   area is 0: no shear deformation).
//   Consistent mass, m = m̄L, per bending plane (1+Φ)^-2 times
//     translation m [13/35 + 7Φ/10 + Φ²/3, (11/210 + 11Φ/120 + Φ²/24)L,
//                    9/70 + 3Φ/10 + Φ²/6, -(13/420 + 3Φ/40 + Φ²/24)L;
//                    (1/105 + Φ/60 + Φ²/120)L², (13/420 + 3Φ/40 + Φ²/24)L,
//                    -(1/140 + Φ/60 + Φ²/120)L²; ...] and, optionally,
//     rotary inertia ρI/L [6/5, (1/10 - Φ/2)L, -6/5, (1/10 - Φ/2)L;
//                    (2/15 + Φ/6 + Φ²/3)L², -(1/10 - Φ/2)L,
//                    -(1/30 + Φ/6 - Φ²/6)L²; ...];
//   axial m/6 [2 1; 1 2]; torsional ρIp L/6 [2 1; 1 2], ρ = m̄/A, Ip = Iy + Iz.
//   Lumped mass: m/2 on each end's three translations, ρIp L/2 on each
//   twist, ρI L/2 on each bending rotation with rotary inertia, else none.
//   Geometric stiffness under the axial force N (tension +), consistent with
//   the same shape functions: per bending plane N/((1+Φ)²L) [6/5 + 2Φ + Φ²,
//   L/10, -(6/5 + 2Φ + Φ²), L/10; (2/15 + Φ/6 + Φ²/12)L², -L/10,
//   -(1/30 + Φ/6 + Φ²/12)L²; ...], the Wagner term N Ip/(A L) [1 -1; -1 1] on
//   the twists, nothing on the axial DOFs (as the 2D element, doc/theory.md
//   §1.10: their size relative to EA/L is N/EA).
//   Global matrices: T^T k T with T = diag(R, R, R, R), R's rows the local axes.
// Source: Przemieniecki, Theory of Matrix Structural Analysis (1968), ch. 5
// (beam stiffness with shear deformation), ch. 11 (consistent mass with
// shear deformation and rotary inertia) and its geometric (stability)
// matrices; McGuire, Gallagher & Ziemian, Matrix Structural Analysis, 2nd
// ed. (2000), ch. 4 (3D frame stiffness), ch. 5 (local axes from a
// reference vector), eq. 9.19 (3D geometric stiffness, its part in the axial
// force). Each bending matrix is the integral of the exact Timoshenko
// end-load shape functions, which tests/elements checks by quadrature.
#ifndef poundfe_elements_frame_element_3d_h
#define poundfe_elements_frame_element_3d_h

#include <poundfe/model/model.h>

#include <Eigen/Core>

namespace poundfe
{
  using Matrix12 = Eigen::Matrix<double, 12, 12>;
  using Vector12 = Eigen::Matrix<double, 12, 1>;

  // Section3D: model/model.h (the model keeps the sections of its members).

  /// Whether the mass matrices carry the rotary inertia ρI of the bending
  /// rotations (the twist always carries its ρIp).
  enum class RotaryInertia
  {
    excluded,
    included
  };

  class FrameElement3D
  {
  public:
    /// `orientation`: the vector v_xz in the local x-z plane. Throws
    /// InputError (no file: the caller adds it) for a member of zero length,
    /// an orientation parallel to the member axis (sine of the angle below
    /// 1e-6) or a section without positive E, G, A, Iy, Iz, J.
    FrameElement3D(const Eigen::Vector3d &start, const Eigen::Vector3d &end,
                   const Eigen::Vector3d &orientation, const Section3D &section);

    double length() const { return element_length; }

    /// Rows: the local x, y, z axes in global components.
    const Eigen::Matrix3d &local_axes() const { return axes; }
    /// Global-to-local rotation T = diag(R, R, R, R).
    Matrix12 rotation() const;

    /// Timoshenko parameter Φ of bending in the local x-y plane (Iz, Avy).
    double shear_parameter_y() const;
    /// Timoshenko parameter Φ of bending in the local x-z plane (Iy, Avz).
    double shear_parameter_z() const;

    Matrix12 local_stiffness() const;
    /// Global stiffness T^T k T.
    Matrix12 stiffness() const;
    Matrix12 local_mass(MassMatrixType type, RotaryInertia rotary = RotaryInertia::excluded) const;
    /// Global mass T^T m T.
    Matrix12 mass(MassMatrixType type, RotaryInertia rotary = RotaryInertia::excluded) const;
    /// Local geometric stiffness under the axial force N (tension positive:
    /// compression softens the member).
    Matrix12 local_geometric_stiffness(double axial_force) const;
    /// Global geometric stiffness T^T k_G T.
    Matrix12 geometric_stiffness(double axial_force) const;

    /// Member end forces in local axes (N1, Vy1, Vz1, T1, My1, Mz1, N2, ...)
    /// from global end displacements.
    Vector12 local_end_forces(const Vector12 &global_displacements) const;
    /// Axial force (tension positive) from global end displacements.
    double axial_force(const Vector12 &global_displacements) const;

  private:
    double          element_length;
    Eigen::Matrix3d axes;
    Section3D       section;
  };
} // namespace poundfe

#endif
