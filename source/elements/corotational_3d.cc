// The corotational basic system in space: Crisfield's formulation with the
// nodal triads turned by the rotation increments, as OpenSees 3.8's
// CorotCrdTransf3d (equations and sources in the header).
#include <poundfe/elements/corotational_3d.h>

#include <cmath>

namespace poundfe
{
  namespace
  {
    /// S(a) with S(a) b = a x b.
    Eigen::Matrix3d
    skew(const Eigen::Vector3d &a)
    {
      Eigen::Matrix3d s;
      s << 0, -a[2], a[1], a[2], 0, -a[0], -a[1], a[0], 0;
      return s;
    }

    /// exp(S(theta)) as a unit quaternion (the identity for theta = 0).
    Eigen::Quaterniond
    spin(const Eigen::Vector3d &theta)
    {
      const double angle = theta.norm();
      if (angle == 0)
        return Eigen::Quaterniond::Identity();
      return Eigen::Quaterniond(Eigen::AngleAxisd(angle, theta / angle));
    }

    /// R(w) = I + (S(w) + S(w)^2/2)/(1 + |w|^2/4) of the tangent-scaled
    /// pseudo-vector w = 2 tan(phi/2) n.
    Eigen::Matrix3d
    tangent_scaled_rotation(const Eigen::Vector3d &w)
    {
      const Eigen::Matrix3d s = skew(w);
      return Eigen::Matrix3d::Identity() + (s + 0.5 * s * s) / (1 + w.squaredNorm() / 4);
    }

    /// Add m at the blocks (I, I), (J, J) and -m at (I, J), (J, I) of the
    /// translations.
    void
    add_translation_pair(Corotational3d::GlobalMatrix &k, const Eigen::Matrix3d &m)
    {
      k.block<3, 3>(0, 0) += m, k.block<3, 3>(6, 6) += m;
      k.block<3, 3>(0, 6) -= m, k.block<3, 3>(6, 0) -= m;
    }
  } // namespace

  Corotational3d::Corotational3d(const Eigen::Matrix3d &axes, const Eigen::Vector3d &chord)
    : axes0(axes.transpose())
    , chord0(chord)
    , length0(chord.norm())
    , length(length0)
  {
    reset();
    update(GlobalVector::Zero());
  }

  void
  Corotational3d::reset()
  {
    trial.i = trial.j = Eigen::Quaterniond(axes0);
    trial.rotation_i.setZero();
    trial.rotation_j.setZero();
    committed = trial;
  }

  void
  Corotational3d::update(const GlobalVector &u)
  {
    // the triads turned by the rotations' change since the last update
    trial.i = spin(u.segment<3>(3) - trial.rotation_i) * trial.i;
    trial.j = spin(u.segment<3>(9) - trial.rotation_j) * trial.j;
    trial.rotation_i = u.segment<3>(3), trial.rotation_j = u.segment<3>(9);
    r_i = trial.i.toRotationMatrix(), r_j = trial.j.toRotationMatrix();
    // the mean triad: half the relative rotation's tangent-scaled vector
    const Eigen::Quaterniond gamma(Eigen::Matrix3d(r_j * r_i.transpose()));
    r_bar = tangent_scaled_rotation(gamma.vec() / gamma.w()) * r_i;
    // the chord's direction, and the mean triad turned onto it
    const Eigen::Vector3d d  = u.segment<3>(6) - u.segment<3>(0);
    const Eigen::Vector3d dx = chord0 + d;
    length                   = dx.norm();
    const Eigen::Vector3d e1 = dx / length, r1 = r_bar.col(0);
    e.col(0)                 = e1;
    for (const int k : {1, 2})
      e.col(k) = r_bar.col(k) - (e1 + r1) * (0.5 * r_bar.col(k).dot(e1));
    for (const int end : {0, 1})
      {
        const Eigen::Matrix3d &r = end == 0 ? r_i : r_j;
        local[3 * end]     = std::asin(0.5 * (r.col(1).dot(e.col(2)) - r.col(2).dot(e.col(1))));
        local[3 * end + 1] = std::asin(0.5 * (r.col(0).dot(e.col(1)) - r.col(1).dot(e.col(0))));
        local[3 * end + 2] = std::asin(0.5 * (r.col(0).dot(e.col(2)) - r.col(2).dot(e.col(0))));
      }
    // the elongation by the mid-point rule, free of L_n - L's cancellation
    local[6] = 2 * (chord0 + 0.5 * d).dot(d) / (length + length0);
    v << local[6], local[1], local[4], -local[2], -local[5], local[3] - local[0];
    set_gradients();
  }

  Corotational3d::MidPoint
  Corotational3d::mid_point_matrix(const Eigen::Vector3d &r) const
  {
    const Eigen::Vector3d e1 = e.col(0), sum = e1 + r_bar.col(0);
    const double          re1 = r.dot(e1);
    const Eigen::Matrix3d l1  = 0.5 * re1 * a + 0.5 * a * r * sum.transpose();
    const Eigen::Matrix3d l2 =
      0.5 * skew(r) - 0.25 * re1 * skew(r_bar.col(0)) - 0.25 * skew(r) * e1 * sum.transpose();
    MidPoint l;
    l << l1, l2, -l1, l2;
    return l;
  }

  Corotational3d::GlobalVector
  Corotational3d::dot_gradient(const Eigen::Vector3d &vector, const int end, const int k) const
  {
    GlobalVector g            = GlobalVector::Zero();
    g.segment<3>(6 * end + 3) = vector.cross(e.col(k));
    if (k == 0)
      {
        g.segment<3>(0) = -a * vector;
        g.segment<3>(6) = a * vector;
      }
    else
      g += (k == 1 ? l_2 : l_3) * vector;
    return g;
  }

  void
  Corotational3d::set_gradients()
  {
    const Eigen::Vector3d e1 = e.col(0);
    a   = (Eigen::Matrix3d::Identity() - e1 * e1.transpose()) / length;
    l_2 = mid_point_matrix(r_bar.col(1));
    l_3 = mid_point_matrix(r_bar.col(2));
    for (const int end : {0, 1})
      {
        const Eigen::Matrix3d &r = end == 0 ? r_i : r_j;
        const int              o = 3 * end;
        t.row(o)     = (dot_gradient(r.col(1), end, 2) - dot_gradient(r.col(2), end, 1)).transpose();
        t.row(o + 1) = (dot_gradient(r.col(0), end, 1) - dot_gradient(r.col(1), end, 0)).transpose();
        t.row(o + 2) = (dot_gradient(r.col(0), end, 2) - dot_gradient(r.col(2), end, 0)).transpose();
        for (int row = o; row < o + 3; ++row)
          t.row(row) /= 2 * std::cos(local[row]);
      }
    t.row(6).setZero();
    t.block<1, 3>(6, 0) = -e1.transpose();
    t.block<1, 3>(6, 6) = e1.transpose();
    // B = T_p T (OpenSees's renumbering of the local deformations)
    b.row(0) = t.row(6), b.row(1) = t.row(1), b.row(2) = t.row(4);
    b.row(3) = -t.row(2), b.row(4) = -t.row(5), b.row(5) = t.row(3) - t.row(0);
  }

  Corotational3d::GlobalMatrix
  Corotational3d::k_sigma2(const Eigen::Vector3d &r, const Eigen::Vector3d &z) const
  {
    const Eigen::Vector3d e1 = e.col(0), r1 = r_bar.col(0);
    const double          re1 = r.dot(e1), ze1 = z.dot(e1), zr1 = z.dot(r1);
    const Eigen::Matrix3d u = -0.5 * a * z * r.transpose() * a +
                              re1 / (2 * length) * a * z * e1.transpose() +
                              (ze1 + zr1) / (2 * length) * a * r * e1.transpose();
    const Eigen::Matrix3d k11 =
      u + u.transpose() + re1 * (2 * ze1 + zr1) / (2 * length) * a;
    const Eigen::Matrix3d sr = skew(r), sr1 = skew(r1), sz = skew(z);
    const Eigen::Matrix3d k12 = -0.25 * a * z * e1.transpose() * sr -
                                0.25 * a * r * z.transpose() * sr1 - 0.25 * (ze1 + zr1) * a * sr;
    const Eigen::Matrix3d k22 =
      -0.125 * re1 * sz * sr1 + 0.125 * sr1 * z * e1.transpose() * sr +
      0.125 * sr * e1 * z.transpose() * sr1 - 0.125 * (ze1 + zr1) * skew(e1) * sr + 0.25 * sz * sr;
    GlobalMatrix k = GlobalMatrix::Zero();
    add_translation_pair(k, k11);
    for (const int rotation : {3, 9})
      {
        k.block<3, 3>(0, rotation) += k12, k.block<3, 3>(6, rotation) -= k12;
        k.block<3, 3>(rotation, 0) += k12.transpose();
        k.block<3, 3>(rotation, 6) -= k12.transpose();
        for (const int other : {3, 9})
          k.block<3, 3>(rotation, other) += k22;
      }
    return k;
  }

  Corotational3d::GlobalMatrix
  Corotational3d::k_sigma_1345(const double axial, const Eigen::Matrix<double, 6, 1> &m) const
  {
    GlobalMatrix k = GlobalMatrix::Zero();
    add_translation_pair(k, axial * a); // K_sigma1
    const Eigen::Matrix3d se1 = skew(e.col(0)), se2 = skew(e.col(1)), se3 = skew(e.col(2));
    for (const int end : {0, 1})
      {
        const Eigen::Matrix3d &r = end == 0 ? r_i : r_j;
        const Eigen::Matrix3d  s1 = skew(r.col(0)), s2 = skew(r.col(1)), s3 = skew(r.col(2));
        const int              o = 3 * end, rotation = 6 * end + 3;
        // K_sigma3 (the torsion at J's moment m_3 at both ends, as OpenSees)
        const double twist = end == 0 ? m[3] : -m[3];
        const Eigen::Matrix<double, 12, 3> bar =
          end == 0 ? Eigen::Matrix<double, 12, 3>(-l_2 * (m[3] * s3 + m[1] * s1) +
                                                  l_3 * (m[3] * s2 - m[2] * s1)) :
                     Eigen::Matrix<double, 12, 3>(l_2 * (m[3] * s3 - m[4] * s1) -
                                                  l_3 * (m[3] * s2 + m[5] * s1));
        k.block<12, 3>(0, rotation) += bar;
        k.block<3, 12>(rotation, 0) += bar.transpose();
        // K_sigma4
        k.block<3, 3>(rotation, rotation) += twist * (se2 * s3 - se3 * s2) +
                                             m[o + 1] * (se2 * s1 - se1 * s2) +
                                             m[o + 2] * (se3 * s1 - se1 * s3);
        // K_sigma5's blocks of translations and rotations
        const Eigen::Matrix3d k1r = -(m[o + 1] * a * s2 + m[o + 2] * a * s3);
        k.block<3, 3>(0, rotation) += k1r, k.block<3, 3>(6, rotation) -= k1r;
        k.block<3, 3>(rotation, 0) += k1r.transpose();
        k.block<3, 3>(rotation, 6) -= k1r.transpose();
      }
    const Eigen::Vector3d e1 = e.col(0);
    const Eigen::Vector3d w =
      (m[1] * r_i.col(1) + m[2] * r_i.col(2) + m[4] * r_j.col(1) + m[5] * r_j.col(2)) / length;
    add_translation_pair(k, e1.dot(w) * a + a * w * e1.transpose() + e1 * w.transpose() * a);
    return k;
  }

  Corotational3d::GlobalMatrix
  Corotational3d::geometric_tangent(const BasicVector &q) const
  {
    // the local forces T_p^T q and the moments over 2 cos t
    LocalVector pl;
    pl << -q[5], q[1], -q[3], q[5], q[2], -q[4], q[0];
    Eigen::Matrix<double, 6, 1> m;
    for (int i = 0; i < 6; ++i)
      m[i] = pl[i] / (2 * std::cos(local[i]));
    GlobalMatrix          k  = k_sigma_1345(pl[6], m);
    const Eigen::Vector3d r2 = r_bar.col(1), r3 = r_bar.col(2);
    k += m[3] * (k_sigma2(r2, r_i.col(2) - r_j.col(2)) + k_sigma2(r3, r_j.col(1) - r_i.col(1)));
    k += m[1] * k_sigma2(r2, r_i.col(0)) + m[2] * k_sigma2(r3, r_i.col(0));
    k += m[4] * k_sigma2(r2, r_j.col(0)) + m[5] * k_sigma2(r3, r_j.col(0));
    // the asin's second derivative: T^T diag(p_l tan t) T
    for (int i = 0; i < 6; ++i)
      k += t.row(i).transpose() * (pl[i] * std::tan(local[i])) * t.row(i);
    return k;
  }
} // namespace poundfe
