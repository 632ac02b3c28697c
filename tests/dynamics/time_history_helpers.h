// Helpers of the dynamics tests that run whole time histories from a
// parameter text: read it, run it through TimeHistory, record every step.
#ifndef poundfe_tests_dynamics_time_history_helpers_h
#define poundfe_tests_dynamics_time_history_helpers_h

#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <string>
#include <vector>

#include "test_utilities.h"

namespace poundfe_test
{
  /// The modes of a shear building of n equal storeys (m, k), fixed base,
  /// computed here (M = m I, K tridiagonal; Eigen), mass-normalised.
  struct ShearBuildingModes
  {
    Eigen::VectorXd omega;
    Eigen::MatrixXd phi;
    ShearBuildingModes(const unsigned int n, const double m, const double k)
    {
      Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
      for (unsigned int i = 0; i < n; ++i)
        {
          K(i, i) = (i + 1 < n ? 2 : 1) * k;
          if (i + 1 < n)
            K(i, i + 1) = K(i + 1, i) = -k;
        }
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(K / m);
      omega = eigen.eigenvalues().cwiseSqrt();
      phi   = eigen.eigenvectors() / std::sqrt(m); // phi^T M phi = I
    }
  };

  /// The parameters of `text`, written to a temporary file `name`.prm.
  inline poundfe::InputParameters
  input_of(const std::string &name, const std::string &text)
  {
    return poundfe::read_parameters(temporary_file(name + ".prm", text));
  }

  /// Every step's time, u, v and a, and the energy balance at the last.
  struct StepRecorder : poundfe::StepObserver
  {
    std::vector<double>          t;
    std::vector<poundfe::Vector> u, v, a;
    double                       max_energy_error = 0;
    poundfe::EnergyBalance       energy;
    void
    observe_step(const poundfe::ResponseView &s) override
    {
      t.push_back(s.time());
      u.push_back(s.displacement());
      v.push_back(s.velocity());
      a.push_back(s.acceleration());
      max_energy_error = s.max_energy_error();
      energy           = s.energy();
    }
  };

  /// The time history of `p` on `analysis`, recorded; it must complete.
  inline StepRecorder
  recorded_run(const poundfe::Analysis &analysis, const poundfe::InputParameters &p)
  {
    const poundfe::TimeHistoryParameters parameters = poundfe::time_history_parameters(p);
    const poundfe::Excitation excitation = poundfe::make_excitation(analysis, parameters);
    poundfe::TimeHistory      history(analysis, parameters);
    StepRecorder              recorder;
    BOOST_REQUIRE(history.run(excitation, {&recorder}).completed());
    return recorder;
  }
} // namespace poundfe_test

#endif
