// The linear, PDelta and corotational transformations between a member's
// global end displacements and its basic system (equations in the header).
#include <poundfe/base/exceptions.h>
#include <poundfe/elements/crd_transformation.h>
#include <poundfe/elements/displaced_chord.h>

#include <Eigen/Geometry>

#include <cmath>

namespace poundfe
{
  namespace
  {
    constexpr int n_node_dofs(const int dim) { return dim == 2 ? 3 : 6; }

    /// The rotation of a member's global DOFs into its local axes,
    /// diag(R, 1, R, 1) in 2D and diag(R, R, R, R) in 3D.
    template <int dim>
    Eigen::Matrix<double, MemberSize<dim>::dofs, MemberSize<dim>::dofs>
    dof_rotation(const Eigen::Matrix<double, dim, dim> &axes)
    {
      using Matrix = Eigen::Matrix<double, MemberSize<dim>::dofs, MemberSize<dim>::dofs>;
      Matrix lambda = Matrix::Zero();
      if constexpr (dim == 2)
        for (const int o : {0, 3})
          {
            lambda.template block<2, 2>(o, o) = axes;
            lambda(o + 2, o + 2)              = 1;
          }
      else
        for (const int o : {0, 3, 6, 9})
          lambda.template block<3, 3>(o, o) = axes;
      return lambda;
    }

    /// dv/du_local of the linear basic system (OpenSees's signs).
    template <int dim>
    Eigen::Matrix<double, MemberSize<dim>::basic, MemberSize<dim>::dofs>
    local_compatibility(const double L)
    {
      Eigen::Matrix<double, MemberSize<dim>::basic, MemberSize<dim>::dofs> b;
      b.setZero();
      constexpr int j = n_node_dofs(dim); // first DOF of end J
      b(0, 0)         = -1;
      b(0, j)         = 1;
      // theta_z: rz - (v_J - v_I)/L at each end
      const int rz = dim == 2 ? 2 : 5;
      for (const int row : {1, 2})
        {
          b(row, row == 1 ? rz : j + rz) = 1;
          b(row, 1)                      = 1 / L;
          b(row, j + 1)                  = -1 / L;
        }
      if constexpr (dim == 3)
        {
          // theta_y: ry + (w_J - w_I)/L; twist rx_J - rx_I
          for (const int row : {3, 4})
            {
              b(row, row == 3 ? 4 : j + 4) = 1;
              b(row, 2)                    = -1 / L;
              b(row, j + 2)                = 1 / L;
            }
          b(5, 3)     = -1;
          b(5, j + 3) = 1;
        }
      return b;
    }

    /// u_end = u_node + r x o for each end: the rows of a node's
    /// translations gain -[o]x on its rotations (2D: (-o_y, o_x) rz).
    template <int dim>
    Eigen::Matrix<double, MemberSize<dim>::dofs, MemberSize<dim>::dofs>
    rigid_offset_matrix(const Eigen::Matrix<double, dim, 1> &o_i, const Eigen::Matrix<double, dim, 1> &o_j)
    {
      using Matrix = Eigen::Matrix<double, MemberSize<dim>::dofs, MemberSize<dim>::dofs>;
      Matrix        t = Matrix::Identity();
      constexpr int n = n_node_dofs(dim);
      for (const int end : {0, 1})
        {
          const Eigen::Matrix<double, dim, 1> &o = end == 0 ? o_i : o_j;
          const int                            k = end * n;
          if constexpr (dim == 2)
            {
              t(k, k + 2)     = -o[1];
              t(k + 1, k + 2) = o[0];
            }
          else
            {
              Eigen::Matrix3d skew;
              skew << 0, -o[2], o[1], o[2], 0, -o[0], -o[1], o[0], 0;
              t.template block<3, 3>(k, k + 3) = -skew;
            }
        }
      return t;
    }
  } // namespace

  template <int dim>
  CrdTransformation<dim>::CrdTransformation(const Transformation kind, const Point &node_i,
                                            const Point &node_j, const Point &offset_i,
                                            const Point &offset_j,
                                            const Eigen::Vector3d &orientation,
                                            const GlobalVector    &made)
    : type(kind)
    , u_made(made)
    , chord0(displaced_chord<dim>(node_i + offset_i, node_j + offset_j, made))
    , length0(chord0.norm())
    , offsets(rigid_offset_matrix<dim>(offset_i, offset_j))
    , has_offsets(offset_i.norm() > 0 || offset_j.norm() > 0)
  {
    if (!(length0 > 0))
      throw InputError("", 0, "Coordinates", "a member of zero length between its offset ends");
    if (dim == 3 && kind == Transformation::corotational && has_offsets)
      throw InputError("", 0, "Offsets",
                       "rigid end offsets on a corotational member in space");
    set_axes(orientation);
    if constexpr (dim == 3)
      if (kind == Transformation::corotational)
        triads = Corotational3d(axes, chord0);
    b_linear = local_compatibility<dim>(length0) * dof_rotation<dim>(axes);
    update(GlobalVector::Zero());
  }

  template <int dim>
  void
  CrdTransformation<dim>::set_axes(const Eigen::Vector3d &orientation)
  {
    const Point x = chord0 / length0;
    if constexpr (dim == 2)
      axes << x[0], x[1], -x[1], x[0];
    else
      {
        const Eigen::Vector3d y = orientation.cross(x);
        if (!(y.norm() > 1e-6 * orientation.norm()))
          throw InputError("", 0, "Orientation",
                           "the orientation vector is parallel to the member's axis");
        axes.row(0) = x.transpose();
        axes.row(1) = y.normalized().transpose();
        axes.row(2) = x.cross(axes.row(1).transpose()).transpose();
      }
  }

  template <int dim>
  typename CrdTransformation<dim>::GlobalVector
  CrdTransformation<dim>::offset_displacements(const GlobalVector &u) const
  {
    return has_offsets ? GlobalVector(offsets * u) : u;
  }

  template <int dim>
  void
  CrdTransformation<dim>::update(const GlobalVector &u)
  {
    u_end = offset_displacements(u);
    if (type == Transformation::corotational)
      {
        if constexpr (dim == 2)
          update_corotational(u_end);
        else
          {
            triads.update(u_end);
            v = triads.basic_deformation();
            b = triads.compatibility();
          }
        return;
      }
    v = b_linear * u_end;
    b = has_offsets ? Compatibility(b_linear * offsets) : b_linear;
  }

  template <int dim>
  void
  CrdTransformation<dim>::commit()
  {
    if (dim == 3 && type == Transformation::corotational)
      triads.commit();
  }

  template <int dim>
  void
  CrdTransformation<dim>::revert()
  {
    if (dim == 3 && type == Transformation::corotational)
      triads.revert();
  }

  template <int dim>
  void
  CrdTransformation<dim>::reset()
  {
    if (dim == 3 && type == Transformation::corotational)
      triads.reset();
  }

  template <int dim>
  void
  CrdTransformation<dim>::update_corotational(const GlobalVector &u)
  {
    if constexpr (dim == 2)
      {
      const Eigen::Vector2d du(u[3] - u[0], u[4] - u[1]);
      const Eigen::Vector2d chord = chord0 + du;
      length                      = chord.norm();
      direction                   = chord / length;
      const double c = direction[0], s = direction[1], c0 = axes(0, 0), s0 = axes(0, 1);
      // the chord's rotation, within pi of the ends' mean rotation
      double       alpha = std::atan2(c0 * s - s0 * c, c0 * c + s0 * s);
      const double mean  = 0.5 * (u[2] + u[5]);
      alpha += 2 * M_PI * std::round((mean - alpha) / (2 * M_PI));
      // Ln - L0 without the cancellation of two close lengths
      v[0] = (2 * chord0.dot(du) + du.squaredNorm()) / (length + length0);
      v[1] = u[2] - alpha;
      v[2] = u[5] - alpha;
      Compatibility bb;
      bb << -c, -s, 0, c, s, 0, //
        -s / length, c / length, 1, s / length, -c / length, 0, //
        -s / length, c / length, 0, s / length, -c / length, 1;
      b = has_offsets ? Compatibility(bb * offsets) : bb;
      }
  }

  template <int dim>
  void
  CrdTransformation<dim>::transverse(const GlobalVector &u, Eigen::Matrix<double, n_dofs, dim - 1> &g,
                                     Eigen::Matrix<double, dim - 1, 1> &delta) const
  {
    // local v (and w) of end J minus end I
    const auto    lambda = dof_rotation<dim>(axes);
    constexpr int j      = n_node_dofs(dim);
    for (int k = 0; k < dim - 1; ++k)
      {
        g.col(k) = (lambda.row(j + 1 + k) - lambda.row(1 + k)).transpose();
        delta[k] = g.col(k).dot(u);
      }
  }

  template <int dim>
  typename CrdTransformation<dim>::GlobalVector
  CrdTransformation<dim>::global_force(const BasicVector &q) const
  {
    GlobalVector p = b.transpose() * q;
    if (type == Transformation::linear)
      return p;
    GlobalVector extra; // p_g at the flexible ends
    if (type == Transformation::pdelta)
      {
        Eigen::Matrix<double, n_dofs, dim - 1> g;
        Eigen::Matrix<double, dim - 1, 1>      delta;
        transverse(u_end, g, delta);
        extra = q[0] / length0 * (g * delta);
      }
    else
      return p; // corotational: B^T q is the whole force
    return p + (has_offsets ? GlobalVector(offsets.transpose() * extra) : extra);
  }

  template <int dim>
  typename CrdTransformation<dim>::GlobalMatrix
  CrdTransformation<dim>::global_tangent(const BasicVector &q, const BasicMatrix &k_b) const
  {
    GlobalMatrix k = b.transpose() * k_b * b;
    if (type == Transformation::linear)
      return k;
    GlobalMatrix k_g;
    if (type == Transformation::pdelta)
      {
        Eigen::Matrix<double, n_dofs, dim - 1> g;
        Eigen::Matrix<double, dim - 1, 1>      delta;
        transverse(u_end, g, delta);
        // N/L g g^T on the flexible ends; (delta/L) g (dN/du)^T, dN/du
        // already in global DOFs (B includes T_o)
        k_g                          = q[0] / length0 * g * g.transpose();
        const GlobalVector dn_du     = (k_b.row(0) * b).transpose();
        const GlobalVector shear_dir = g * delta / length0;
        if (has_offsets)
          k_g = offsets.transpose() * k_g * offsets;
        if (opensees_tangent)
          return k + k_g;
        return k + k_g +
               (has_offsets ? GlobalVector(offsets.transpose() * shear_dir) : shear_dir) *
                 dn_du.transpose();
      }
    if constexpr (dim == 2)
      {
        const double c = direction[0], s = direction[1];
        GlobalVector r, w;
        r << -c, -s, 0, c, s, 0;
        w << s, -c, 0, -s, c, 0;
        k_g = q[0] / length * w * w.transpose() +
              (q[1] + q[2]) / (length * length) * (r * w.transpose() + w * r.transpose());
        if (has_offsets)
          k_g = offsets.transpose() * k_g * offsets;
        return k + k_g;
      }
    else
      return k + triads.geometric_tangent(q);
  }

  template class CrdTransformation<2>;
  template class CrdTransformation<3>;
} // namespace poundfe
