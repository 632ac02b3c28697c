// Helpers shared by the unit tests: MPI set-up and hand-built models.
#ifndef poundfe_tests_test_utilities_h
#define poundfe_tests_test_utilities_h

#include <poundfe/input/input_parameters.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/integration/newmark.h>
#include <poundfe/model/model.h>

#include <deal.II/base/mpi.h>

#include <boost/test/unit_test.hpp>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace poundfe_test
{
  /// PETSc and Trilinos need MPI initialised once per process.
  struct MpiFixture
  {
    MpiFixture()
      : mpi(boost::unit_test::framework::master_test_suite().argc,
            boost::unit_test::framework::master_test_suite().argv, 1)
    {}
    dealii::Utilities::MPI::MPI_InitFinalize mpi;
  };

  /// A straight member from `start` to `end` in n elements, one building.
  inline poundfe::Model
  straight_member(const poundfe::Point2 &start, const poundfe::Point2 &end,
                  const poundfe::Section &section, const unsigned int n_elements)
  {
    poundfe::Model model;
    for (unsigned int i = 0; i <= n_elements; ++i)
      {
        poundfe::Node node;
        const double  s = double(i) / n_elements;
        node.position   = {start.x + s * (end.x - start.x), start.y + s * (end.y - start.y)};
        model.nodes.push_back(node);
      }
    for (unsigned int i = 0; i < n_elements; ++i)
      {
        poundfe::Member m;
        m.nodes   = {{i, i + 1}};
        m.section = section;
        model.members.push_back(m);
      }
    poundfe::Building b;
    b.first_node = 0;
    b.n_nodes    = model.nodes.size();
    model.buildings.push_back(b);
    return model;
  }

  /// Input for an n-storey shear building with equal storeys.
  inline poundfe::InputParameters
  shear_building_input(const unsigned int n, const double mass, const double stiffness,
                       const double damping_ratio)
  {
    poundfe::InputParameters p;
    p.file = "test";
    p.model.buildings.resize(1);
    auto &b              = p.model.buildings[0];
    b.name               = "S";
    b.type               = poundfe::BuildingType::shear;
    b.n_storeys          = n;
    b.floor_masses       = {mass};
    b.storey_stiffnesses = {stiffness};
    b.storey_heights     = {3.0};
    b.damping_type       = damping_ratio > 0 ? poundfe::RayleighDamping::Kind::modes :
                                             poundfe::RayleighDamping::Kind::none;
    b.damping_ratio      = damping_ratio;
    b.damping_modes      = {1, 2};
    p.ground_motion.type = poundfe::GroundMotionType::none;
    p.output.n_modes            = n;
    return p;
  }
  /// The largest relative column error of the integrator's Newton tangent
  /// against central differences of its residual, at the current
  /// displacements perturbed by up to 2e-4 of each (random, from `seed`),
  /// under the load `load` at the end of the next step.
  inline double
  tangent_error_by_central_differences(poundfe::NewmarkIntegrator &integrator,
                                       const poundfe::Vector &load, const unsigned int seed)
  {
    std::mt19937                     random(seed);
    std::uniform_real_distribution<> uniform(-1, 1);
    poundfe::Vector                  u = integrator.displacement();
    for (Eigen::Index i = 0; i < u.size(); ++i)
      u[i] += 2e-4 * uniform(random) * std::max(std::abs(u[i]), 1e-3);
    poundfe::Vector r, r_plus, r_minus;
    Eigen::MatrixXd tangent, unused;
    integrator.residual_and_tangent(load, u, r, tangent);
    double worst = 0;
    for (Eigen::Index j = 0; j < u.size(); ++j)
      {
        const double    h = 1e-7 * std::max(std::abs(u[j]), 1e-4);
        poundfe::Vector x = u;
        x[j] += h;
        integrator.residual_and_tangent(load, x, r_plus, unused);
        x[j] -= 2 * h;
        integrator.residual_and_tangent(load, x, r_minus, unused);
        const poundfe::Vector fd = -(r_plus - r_minus) / (2 * h);
        worst = std::max(worst, (fd - tangent.col(j)).norm() / tangent.col(j).norm());
      }
    return worst;
  }

  /// Writes `contents` to poundfe_<name> in the system's temporary directory; returns its path.
  inline std::string
  temporary_file(const std::string &name, const std::string &contents)
  {
    const std::string path =
      (std::filesystem::temp_directory_path() / ("poundfe_" + name)).string();
    std::ofstream(path) << contents;
    return path;
  }

  /// The message of the poundfe::InputError `f` throws ("" when it throws none).
  template <typename F>
  std::string
  input_error_of(F &&f)
  {
    try
      {
        f();
      }
    catch (const poundfe::InputError &e)
      {
        return e.what();
      }
    return "";
  }

  /// The eigenvalues of A x = λ B x, B positive definite, ascending.
  inline Eigen::VectorXd
  generalized_eigenvalues(const Eigen::MatrixXd &a, const Eigen::MatrixXd &b)
  {
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(a, b);
    BOOST_REQUIRE(solver.info() == Eigen::Success);
    return solver.eigenvalues();
  }
} // namespace poundfe_test

#endif
