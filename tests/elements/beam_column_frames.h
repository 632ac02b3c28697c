// A plane frame of beam-columns solved statically by Newton's method, for
// the beam-column tests: nodes with (ux, uy, rz), members on two nodes,
// loads or prescribed displacements on any DOF.
#ifndef poundfe_tests_beam_column_frames_h
#define poundfe_tests_beam_column_frames_h

#include <poundfe/elements/beam_column.h>
#include <poundfe/sections/aggregator_section.h>
#include <poundfe/sections/elastic_section.h>

#include <boost/test/unit_test.hpp>

#include <Eigen/Dense>

#include <array>
#include <memory>
#include <vector>

namespace beam_column_frames
{
  using namespace poundfe;

  struct Frame2d
  {
    std::vector<Eigen::Vector2d> nodes;
    struct Member
    {
      std::unique_ptr<BeamColumn<2>> element;
      std::array<int, 2>             node;
    };
    std::vector<Member> members;
    /// DOFs whose displacement is prescribed (supports, displacement control).
    std::vector<bool> prescribed;

    int n_dofs() const { return 3 * nodes.size(); }

    int add_node(const double x, const double y)
    {
      nodes.emplace_back(x, y);
      prescribed.resize(n_dofs(), false);
      return nodes.size() - 1;
    }

    Eigen::Matrix<double, 6, 1> member_dofs(const Member &m, const Eigen::VectorXd &u) const
    {
      Eigen::Matrix<double, 6, 1> local;
      for (int e = 0; e < 2; ++e)
        for (int k = 0; k < 3; ++k)
          local[3 * e + k] = u[3 * m.node[e] + k];
      return local;
    }

    /// The internal forces and tangent at the trial displacements u.
    bool assemble(const Eigen::VectorXd &u, Eigen::VectorXd &f, Eigen::MatrixXd &k)
    {
      f = Eigen::VectorXd::Zero(n_dofs());
      k = Eigen::MatrixXd::Zero(n_dofs(), n_dofs());
      for (Member &m : members)
        {
          if (!m.element->set_trial(member_dofs(m, u)))
            return false;
          for (int a = 0; a < 6; ++a)
            {
              const int i = 3 * m.node[a / 3] + a % 3;
              f[i] += m.element->resisting_force()[a];
              for (int b = 0; b < 6; ++b)
                k(i, 3 * m.node[b / 3] + b % 3) += m.element->tangent()(a, b);
            }
        }
      return true;
    }

    void commit()
    {
      for (Member &m : members)
        m.element->commit();
    }

    /// Newton from u (prescribed entries already at their values) to
    /// f_int = load on the free DOFs; commits on convergence. Returns the
    /// internal forces (reactions on the prescribed DOFs).
    Eigen::VectorXd solve(Eigen::VectorXd &u, const Eigen::VectorXd &load,
                          const double force_scale, const double tolerance = 1e-9)
    {
      std::vector<int> free;
      for (int i = 0; i < n_dofs(); ++i)
        if (!prescribed[i])
          free.push_back(i);
      Eigen::VectorXd f;
      Eigen::MatrixXd k;
      for (int iteration = 0; iteration < 100; ++iteration)
        {
          BOOST_REQUIRE(assemble(u, f, k));
          Eigen::VectorXd r(free.size());
          Eigen::MatrixXd kff(free.size(), free.size());
          for (unsigned int a = 0; a < free.size(); ++a)
            {
              r[a] = load[free[a]] - f[free[a]];
              for (unsigned int b = 0; b < free.size(); ++b)
                kff(a, b) = k(free[a], free[b]);
            }
          if (r.norm() <= tolerance * force_scale)
            {
              commit();
              return f;
            }
          const Eigen::VectorXd du = kff.partialPivLu().solve(r);
          for (unsigned int a = 0; a < free.size(); ++a)
            u[free[a]] += du[a];
        }
      BOOST_FAIL("Newton did not converge");
      return f;
    }

    /// The tangent's rows and columns of the free DOFs.
    Eigen::MatrixXd free_tangent(const Eigen::VectorXd &u)
    {
      Eigen::VectorXd f;
      Eigen::MatrixXd k;
      BOOST_REQUIRE(assemble(u, f, k));
      std::vector<int> free;
      for (int i = 0; i < n_dofs(); ++i)
        if (!prescribed[i])
          free.push_back(i);
      Eigen::MatrixXd kff(free.size(), free.size());
      for (unsigned int a = 0; a < free.size(); ++a)
        for (unsigned int b = 0; b < free.size(); ++b)
          kff(a, b) = k(free[a], free[b]);
      return kff;
    }
  };

  enum class Formulation
  {
    force,
    displacement
  };

  inline std::unique_ptr<BeamColumn<2>>
  make_member(const Formulation formulation, const Transformation kind, const Eigen::Vector2d &a,
              const Eigen::Vector2d &b, const SectionLaw &section, const unsigned int n_points)
  {
    const CrdTransformation<2> t(kind, a, b);
    if (formulation == Formulation::force)
      return std::make_unique<ForceBeamColumn<2>>(t, section, n_points);
    return std::make_unique<DispBeamColumn<2>>(t, section, n_points);
  }

  /// A line of n members from node `first` to a new last node at (x, y)
  /// each; returns the last node.
  inline int
  add_line(Frame2d &frame, const int first, const Eigen::Vector2d &to, const unsigned int n,
           const Formulation formulation, const Transformation kind, const SectionLaw &section,
           const unsigned int n_points)
  {
    const Eigen::Vector2d from = frame.nodes[first];
    int                   node = first;
    for (unsigned int e = 1; e <= n; ++e)
      {
        const Eigen::Vector2d x    = from + (to - from) * double(e) / n;
        const int             next = frame.add_node(x[0], x[1]);
        frame.members.push_back(
          {make_member(formulation, kind, frame.nodes[node], x, section, n_points), {{node, next}}});
        node = next;
      }
    return node;
  }

  inline void
  fix(Frame2d &frame, const int node)
  {
    for (int k = 0; k < 3; ++k)
      frame.prescribed[3 * node + k] = true;
  }
} // namespace beam_column_frames

#endif
