// Helpers of the foundation tests that compare two runs floor by floor.
#ifndef poundfe_tests_dynamics_floor_histories_h
#define poundfe_tests_dynamics_floor_histories_h

#include <algorithm>
#include <cmath>
#include <vector>

#include "time_history_helpers.h"

namespace poundfe_test
{
  /// Every floor node's (ux, uy, rz) time histories: [node*3 + c][step].
  inline std::vector<std::vector<double>>
  floor_histories(const poundfe::Analysis &analysis, const StepRecorder &run)
  {
    using namespace poundfe;
    std::vector<std::vector<double>> h;
    for (const Floor &floor : analysis.model.buildings[0].floors)
      for (const unsigned int node : floor.nodes)
        for (const Component c : {Component::ux, Component::uy, Component::rz})
          {
            const int e = analysis.model.equation(Model::dof(node, c));
            BOOST_REQUIRE(e >= 0);
            h.emplace_back();
            for (const Vector &u : run.u)
              h.back().push_back(u[e]);
          }
    return h;
  }

  /// The largest |x|.
  inline double
  peak(const std::vector<double> &x)
  {
    double p = 0;
    for (const double v : x)
      p = std::max(p, std::abs(v));
    return p;
  }
} // namespace poundfe_test

#endif
