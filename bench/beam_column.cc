// The state determination of the beam-columns: a column of 10 elements
// (5 integration points each, aggregator sections with Steel01 on Mz,
// b = 0.02), its nodes moved through cycles of the cantilever's deflected
// shape u(x) = a(t) (x/L)^2 (rotations its slope) to a tip drift of 4
// times first yield, every element set_trial and commit at each of 2000
// steps; the elastic column (elastic sections) for comparison. Prints the
// microseconds per element state determination and, for the force-based
// element, the element iterations per call.
// Usage: build/poundfe-bench-beam-column [repeats]  (best of repeats, 3)
#include <poundfe/elements/beam_column.h>
#include <poundfe/laws/material_registry.h>
#include <poundfe/sections/aggregator_section.h>
#include <poundfe/sections/elastic_section.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

using namespace poundfe;

namespace
{
  constexpr int    n_elements = 10, n_steps = 2000;
  constexpr double height = 3, ea = 2e9, ei = 2e7, my = 1e5;

  template <class Element>
  std::vector<std::unique_ptr<BeamColumn<2>>>
  column(const SectionLaw &section)
  {
    std::vector<std::unique_ptr<BeamColumn<2>>> elements;
    for (int e = 0; e < n_elements; ++e)
      elements.push_back(std::make_unique<Element>(
        CrdTransformation<2>(Transformation::linear, Eigen::Vector2d(0, e * height / n_elements),
                             Eigen::Vector2d(0, (e + 1) * height / n_elements)),
        section, 5));
    return elements;
  }

  /// Seconds per element state determination (best of `repeats`) and the
  /// mean force-based iterations per call.
  std::pair<double, double>
  time_column(std::vector<std::unique_ptr<BeamColumn<2>>> &elements, const int repeats)
  {
    const double yield_drift = my * height * height / (3 * ei);
    double       best = 1e300, iterations = 0;
    for (int r = 0; r < repeats; ++r)
      {
        for (auto &e : elements)
          e->reset();
        unsigned long calls = 0, iters = 0;
        const auto    start = std::chrono::steady_clock::now();
        for (int step = 1; step <= n_steps; ++step)
          {
            const double a = 4 * yield_drift * std::sin(2 * M_PI * 4 * step / n_steps);
            for (int e = 0; e < n_elements; ++e)
              {
                Eigen::Matrix<double, 6, 1> u;
                for (int end = 0; end < 2; ++end)
                  {
                    const double x = double(e + end) / n_elements;
                    u.segment<3>(3 * end) << -a * x * x, 0, 2 * a * x / height;
                  }
                if (!elements[e]->set_trial(u))
                  {
                    std::printf("state determination failed: %s\n", elements[e]->failure().c_str());
                    std::exit(2);
                  }
                elements[e]->commit();
                ++calls;
                if (auto *fb = dynamic_cast<ForceBeamColumn<2> *>(elements[e].get()))
                  iters += fb->last_iterations();
              }
          }
        const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        best       = std::min(best, seconds / calls);
        iterations = double(iters) / calls;
      }
    return {best, iterations};
  }
} // namespace

int
main(int argc, char **argv)
{
  const int      repeats = argc > 1 ? std::atoi(argv[1]) : 3;
  SectionVector  rigidities(2);
  rigidities << ea, ei;
  AggregatorSection yielding(rigidities);
  yielding.set_law(1, [] {
    return make_material({"Steel01", {{"fy", my}, {"E0", ei}, {"b", 0.02}}});
  });
  const ElasticSection elastic(ea, ei);
  std::printf("%-36s %12s %12s\n", "column of 10 elements, 5 points", "us/element", "iterations");
  for (const bool nonlinear : {false, true})
    {
      const SectionLaw &section = nonlinear ? static_cast<const SectionLaw &>(yielding) : elastic;
      auto fb = column<ForceBeamColumn<2>>(section);
      auto db = column<DispBeamColumn<2>>(section);
      const auto [tf, itf] = time_column(fb, repeats);
      const auto [td, itd] = time_column(db, repeats);
      const std::string what = nonlinear ? "Steel01 Mz" : "elastic";
      std::printf("%-36s %12.3f %12.2f\n", ("force-based, " + what).c_str(), 1e6 * tf, itf);
      std::printf("%-36s %12.3f %12s\n", ("displacement-based, " + what).c_str(), 1e6 * td, "-");
      (void)itd;
    }
  return 0;
}
