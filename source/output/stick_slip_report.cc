#include <poundfe/output/atomic_file.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/observer.h>
#include <poundfe/output/peak_response.h>
#include <poundfe/output/stick_slip_report.h>
#include <poundfe/output/memory_results.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace poundfe
{
  void
  write_distribution(JsonWriter &json, const std::string &key, std::vector<double> values)
  {
    json.begin_object(key).value("count", static_cast<unsigned int>(values.size()));
    if (!values.empty())
      {
        std::sort(values.begin(), values.end());
        const double n    = values.size();
        const double mean = std::accumulate(values.begin(), values.end(), 0.0) / n;
        double       sum2 = 0;
        for (const double v : values)
          sum2 += (v - mean) * (v - mean);
        auto quantile = [&](const double q) {
          const double      position = q * (n - 1);
          const std::size_t below    = static_cast<std::size_t>(std::floor(position));
          const std::size_t above    = std::min(below + 1, values.size() - 1);
          return values[below] + (position - below) * (values[above] - values[below]);
        };
        json.value("mean_s", mean)
          .value("std_s", n > 1 ? std::sqrt(sum2 / (n - 1)) : 0.0)
          .value("min_s", values.front())
          .value("p10_s", quantile(0.1))
          .value("median_s", quantile(0.5))
          .value("p90_s", quantile(0.9))
          .value("max_s", values.back());
      }
    json.end_object();
  }

  double
  reversal_duration(const ResponseView &state, const unsigned int h)
  {
    const NonlinearElement &e = state.elements[h];
    const int               q = e.equations()[0];
    const double            m = state.system.mass.coeff(q, q);
    const double            k = e.initial_stiffness();
    return k > 0 ? 2 * M_PI * std::sqrt(m / k) : 0.0;
  }

  void
  write_springs_and_friction(JsonWriter &json, const ResponseView &state,
                             const PeakResponse &peaks, const double end_time)
  {
    const NonlinearElements &elements = state.elements;
    for (const ElementKind kind : {ElementKind::spring, ElementKind::friction})
      {
        bool any = false;
        for (unsigned int h = 0; h < elements.size(); ++h)
          {
            const NonlinearElement &e = elements[h];
            if (e.kind != kind)
              continue;
            if (!any)
              json.begin_array(kind == ElementKind::spring ? "springs" : "friction");
            any = true;
            json.begin_object()
              .value("label", e.label)
              .value("building", state.model.buildings[e.building].name)
              .value("peak_displacement_m", peaks.peak_deformation()[h])
              .value("peak_force_N", peaks.peak_force()[h]);
            if (kind == ElementKind::friction)
              {
                const StickSlipStatistics s = stick_slip_statistics(
                  state.stick_slip_log(), h, end_time, reversal_duration(state, h));
                json.value("dissipated_energy_J", state.dissipated_energy(h))
                  .value("sticks", s.n_sticks)
                  .value("slips", s.n_slips)
                  .value("reversals_through_stick_spring", s.n_reversals)
                  .value("shortest_stick_counted_s", reversal_duration(state, h))
                  .value("fraction_of_time_stuck", s.fraction_stuck());
                write_distribution(json, "stick_durations", s.stick_durations);
                write_distribution(json, "slip_durations", s.slip_durations);
              }
            json.end_object();
          }
        if (any)
          json.end_array();
      }
  }

  void
  write_friction_episodes(const std::string &directory, const ResponseView &state,
                          const double end_time, MemoryResults *memory)
  {
    std::ostringstream csv;
    csv.precision(10);
    csv << "element,state,start_time_s,end_time_s,duration_s,completed\n";
    for (const FrictionEpisode &e : state.stick_slip_log().episodes())
      {
        const double end = e.end < 0 ? end_time : e.end;
        csv << state.elements[e.element].label << "," << (e.slipping ? "slip" : "stick") << ","
            << e.start << "," << end << "," << end - e.start << "," << (e.end >= 0 ? 1 : 0)
            << "\n";
      }
    write_result_text(memory, directory, "friction_episodes.csv", csv.str());
  }
} // namespace poundfe
