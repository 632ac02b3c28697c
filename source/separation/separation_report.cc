// The tables and figures of the separation engine's results
// (separation/separation_report.h).
#include <poundfe/separation/separation_report.h>
#include <poundfe/base/numbers.h>
#include <poundfe/output/finite_output.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace poundfe
{
  std::string
  separation_table(const Model &model, const std::vector<AdjacentPair> &pairs,
                   const std::vector<PairResult> &results, const SpectrumPeaks *spectrum)
  {
    std::string csv = "pair,left,right,level_m,floors_coincide,u_left_m,u_right_m,abs_m,srss_m,"
                      "ddc_m,ec8_m,asce7_m,";
    csv += spectrum ? "u_left_srss_m,u_right_srss_m,u_left_cqc_m,u_right_cqc_m\n" :
                      "time_history_m\n";
    for (std::size_t p = 0; p < pairs.size(); ++p)
      {
        const AdjacentPair &pair = pairs[p];
        for (std::size_t l = 0; l < pair.levels.size(); ++l)
          {
            const LevelResult &r = results[p].levels[l];
            csv += std::to_string(p + 1) + "," + model.buildings[pair.left].name + "," +
                   model.buildings[pair.right].name + ",";
            append_number(csv, pair.levels[l].level);
            csv += pair.levels[l].floors_coincide ? ",1" : ",0";
            for (const double x : {r.u_left, r.u_right})
              csv += ',', append_number(csv, x);
            for (const double x : rule_values(r.rules))
              csv += ',', append_number(csv, x);
            if (spectrum)
              {
                const auto &[left, right] = spectrum->levels[p][l];
                for (const double x : {left.srss, right.srss, left.cqc, right.cqc})
                  csv += ',', append_number(csv, x);
              }
            else
              csv += ',', append_number(csv, r.time_history);
            csv += '\n';
          }
      }
    return csv;
  }

  Plot
  separation_plot(const std::vector<AdjacentPair> &pairs, const SpectrumPeaks *spectrum,
                  const bool monte_carlo)
  {
    // where u_1, u_2 of the rules came from: the title and the peaks' curve say it
    const std::string source =
      spectrum ? "response spectrum" : (monte_carlo ? "Monte Carlo mean" : "time history");
    Plot plot;
    for (std::size_t p = 0; p < pairs.size(); ++p)
      {
        const AdjacentPair &pair = pairs[p];
        Plot panel{"separation.png",
                   "Required separation of " + pair.name + " against level" +
                     " (" + source + ")",
                   "separation (mm)", "level (m)", {}};
        // separation.csv in m, drawn in mm; from 0, so that no point sits on the frame
        panel.settings = "set xrange [0:*]\n";
        const std::string only = "(($1==" + std::to_string(p + 1) + ")?1000*$";
        // a dark colour per rule (gnuplot's fifth default colour is a yellow
        // unreadable on white); ASCE 7 dashed: it may equal SRSS
        const std::array<const char *, 5> colour{
          {"#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#a6761d"}};
        for (unsigned int c = 0; c < rule_names.size(); ++c)
          panel.series.push_back({"separation.csv", only + std::to_string(8 + c) + ":1/0):4",
                                  rule_names[c],
                                  std::string(c == 4 ? "linespoints dt 2" : "linespoints") +
                                    " lc rgb '" + colour[c] + "'"});
        if (!spectrum)
          panel.series.push_back({"separation.csv", only + "13:1/0):4",
                                  source + " (no contact)", "linespoints lw 3 lc rgb 'black'"});
        // the existing gap from the ground to the top common level: a line
        // even when the pair has one common level
        double top = 0;
        for (const CommonLevel &level : pair.levels)
          top = std::max(top, level.level);
        const std::string gap   = number_text(1000 * pair.existing_gap);
        const std::string block = "$gap" + std::to_string(p + 1);
        panel.data_blocks = block + " << EOD\ngap_mm,level_m\n" + gap + ",0\n" + gap + "," +
                            number_text(top) + "\nEOD\n";
        panel.series.push_back({block, "1:2", "existing gap", "lines dt 2 lw 2 lc rgb 'gray40'"});
        if (p == 0)
          plot = panel;
        else
          plot.below.push_back(panel);
      }
    return plot;
  }

  std::string
  pounding_probability_table(const SeparationParameters &separation,
                             const std::vector<AdjacentPair> &pairs,
                             const std::vector<PairResult> &results)
  {
    const std::vector<double> gaps = gap_grid(separation, pairs, results);
    std::vector<std::vector<ExceedancePoint>> curves;
    std::string csv = "gap_m";
    for (std::size_t p = 0; p < pairs.size(); ++p)
      {
        curves.push_back(exceedance_curve(results[p].largest_approach, gaps,
                                          separation.confidence_level));
        for (const char *what : {"_exceedances", "_probability", "_lower", "_upper"})
          csv += "," + pairs[p].name + what;
      }
    csv += '\n';
    for (std::size_t i = 0; i < gaps.size(); ++i)
      {
        append_number(csv, gaps[i]);
        for (const auto &curve : curves)
          {
            csv += "," + std::to_string(curve[i].n_exceeding);
            for (const double x : {curve[i].probability, curve[i].lower, curve[i].upper})
              csv += ',', append_number(csv, x);
          }
        csv += '\n';
      }
    return csv;
  }

  Plot
  pounding_probability_plot(const SeparationParameters &separation,
                            const std::vector<AdjacentPair> &pairs,
                            const std::vector<PairResult> &results)
  {
    const std::size_t n_gaps = gap_grid(separation, pairs, results).size();
    Plot              plot;
    const std::string band =
      rounded(100 * separation.confidence_level) + " % band (Wilson, pointwise)";
    for (std::size_t p = 0; p < pairs.size(); ++p)
      {
        const std::string c = std::to_string(3 + 4 * p);
        Plot panel{"pounding_probability.png",
                   "Probability of pounding of " + pairs[p].name + ", " +
                     std::to_string(results[p].largest_approach.size()) +
                     (results[p].largest_approach.size() == 1 ? " realization" : " realizations"),
                   "gap width g (mm)", "P(largest relative approach > g)", {}};
        panel.settings = "set yrange [-0.02:1.05]\n"; // P reaches 0 and 1: the curve off the frame
        panel.series = {
          {"pounding_probability.csv", "(1000*$1):" + std::to_string(4 + 4 * p) + ":" +
                                         std::to_string(5 + 4 * p),
           band, "filledcurves fs transparent solid 0.3 noborder lc rgb 'skyblue'"},
          {"pounding_probability.csv", "(1000*$1):" + c, "Monte Carlo", "lines lw 2 lc rgb 'navy'"},
          {"pounding_probability.csv",
           "(" + number_text(1000 * pairs[p].existing_gap) + "):($0/" +
             std::to_string(std::max<std::size_t>(1, n_gaps - 1)) + ".0)",
           "existing gap " + rounded(1000 * pairs[p].existing_gap) + " mm", "lines dt 2 lc rgb 'red'"}};
        if (p == 0)
          plot = panel;
        else
          plot.below.push_back(panel);
      }
    return plot;
  }

  std::string
  spectrum_modes_table(const Model &model, const SpectrumPeaks &peaks)
  {
    std::string csv = "building,mode,period_s,damping_ratio,participation_factor,"
                      "effective_mass_ratio,cumulative_mass_ratio,Se_m_s2,Sd_m\n";
    for (unsigned int b = 0; b < peaks.buildings.size(); ++b)
      {
        const SpectrumModalResponse &r   = peaks.buildings[b];
        double                       sum = 0;
        for (unsigned int i = 0; i < r.n_modes(); ++i)
          {
            sum += r.effective_mass_ratio[i];
            csv += model.buildings[b].name + "," + std::to_string(i + 1);
            for (const double x : {2 * M_PI / r.omega[i], r.damping_ratio[i], r.participation[i],
                                   r.effective_mass_ratio[i], sum, r.spectral_acceleration[i],
                                   r.spectral_displacement[i]})
              csv += ',', append_number(csv, x);
            csv += '\n';
          }
      }
    return csv;
  }

  namespace
  {
    /// The "levels" array of a pair: each level's displacements and the
    /// separations the rules require there.
    void
    write_level_objects(JsonWriter &json, const AdjacentPair &pair, const PairResult &r,
                        const bool time_history)
    {
      json.begin_array("levels");
      for (std::size_t l = 0; l < r.levels.size(); ++l)
        {
          const LevelResult &level = r.levels[l];
          json.begin_object()
            .value("level_m", pair.levels[l].level)
            .value("floors_coincide", pair.levels[l].floors_coincide)
            .value("u_left_m", level.u_left)
            .value("u_right_m", level.u_right);
          if (time_history)
            json.value("time_history_m", level.time_history);
          const auto values = rule_values(level.rules);
          for (unsigned int c = 0; c < 5; ++c)
            json.value(rule_names[c], values[c]);
          json.end_object();
        }
      json.end_array();
    }

    /// The probabilities of pounding of a pair, when its runs were random:
    /// at the existing gap (with the gap for the target probability), and
    /// at the random separations.
    void
    write_pounding_probabilities(JsonWriter &json, const SeparationParameters &s,
                                 const AdjacentPair &pair, const PairResult &r)
    {
      if (!r.largest_approach.empty())
        {
          const auto at_gap =
            exceedance_curve(r.largest_approach, {pair.existing_gap}, s.confidence_level)[0];
          json.begin_object("pounding")
            .value("probability_at_existing_gap", at_gap.probability)
            .value("lower", at_gap.lower)
            .value("upper", at_gap.upper)
            .value("gap_for_target_probability_m",
                   gap_for_probability(r.largest_approach, s.target_probability))
            .value("gap_for_target_probability_upper_band_m",
                   gap_for_probability_upper(r.largest_approach, s.target_probability,
                                             s.confidence_level))
            .end_object();
        }
      if (!r.random_separation.empty())
        {
          const ProbabilityEstimate e = pounding_at_random_separation(r);
          json.begin_object("pounding_at_random_separation")
            .value("probability", e.probability)
            .value("coefficient_of_variation", undefined_if_infinite(e.coefficient_of_variation))
            .value("pounding_realizations", e.n_failures)
            .value("realizations", e.n)
            .end_object();
        }
    }
  } // namespace

  void
  write_pair_json(JsonWriter &json, const SeparationParameters &s, const Model &model,
                const AdjacentPair &pair, const PairResult &r, const bool time_history)
  {
    json.begin_object()
      .value("pair", pair.name)
      .value("left", model.buildings[pair.left].name)
      .value("right", model.buildings[pair.right].name)
      .value("existing_gap_m", pair.existing_gap)
      .value("left_period_s", 2 * M_PI / r.left_mode.omega)
      .value("left_damping_ratio", r.left_mode.damping_ratio)
      .value("right_period_s", 2 * M_PI / r.right_mode.omega)
      .value("right_damping_ratio", r.right_mode.damping_ratio)
      .value("correlation_rho", r.rho);
    const Joint joint = joint_of(r);
    if (time_history)
      json.value("time_history_m", joint.time_history);
    json.begin_object("required_m");
    for (unsigned int c = 0; c < 5; ++c)
      json.value(rule_names[c], joint.required[c]);
    json.end_object();
    if (time_history)
      {
        json.begin_object("relative_to_time_history");
        for (unsigned int c = 0; c < 5; ++c)
          json.value(rule_names[c], joint.time_history > 0 ?
                                      joint.required[c] / joint.time_history - 1 :
                                      std::numeric_limits<double>::quiet_NaN());
        json.end_object();
      }
    json.value("governing_code_rule", rule_names[joint.governing_code_rule()]);
    write_level_objects(json, pair, r, time_history);
    write_pounding_probabilities(json, s, pair, r);
    json.end_object();
  }
} // namespace poundfe
