// Separation of adjacent buildings: the rules, the time-history minimum and
// the probability of pounding against the gap width. Equations and sources
// in include/poundfe/separation/separation.h and doc/theory.md §7.1.
#include <poundfe/reliability/montecarlo.h>
#include <poundfe/hazard/pounding_hazard.h>
#include <poundfe/dynamics/realization.h>
#include <poundfe/dynamics/run.h>
#include <poundfe/separation/separation.h>
#include <poundfe/separation/separation_spectrum.h>
#include <poundfe/reliability/statistics.h>
#include <poundfe/base/numbers.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/base/progress.h>
#include <poundfe/output/append_file.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/plots.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>

namespace poundfe
{
  double
  modal_correlation(const double omega_1, const double zeta_1, const double omega_2,
                    const double zeta_2)
  {
    Assert(omega_1 > 0 && omega_2 > 0, dealii::ExcMessage("frequencies must be positive"));
    const double r = omega_2 / omega_1;
    const double numerator =
      8 * std::sqrt(zeta_1 * zeta_2) * (zeta_1 + r * zeta_2) * std::pow(r, 1.5);
    const double denominator = (1 - r * r) * (1 - r * r) + 4 * zeta_1 * zeta_2 * r * (1 + r * r) +
                               4 * (zeta_1 * zeta_1 + zeta_2 * zeta_2) * r * r;
    return denominator > 0 ? numerator / denominator : 1.0; // undamped twins: fully correlated
  }

  SeparationRules
  separation_rules(const double u_1, const double u_2, const double rho,
                   const BuildingCodeFactors &left, const BuildingCodeFactors &right,
                   const bool floors_coincide, const double coinciding_levels_factor)
  {
    SeparationRules s;
    s.abs  = u_1 + u_2;
    s.srss = std::hypot(u_1, u_2);
    // |rho| <= 1 keeps the radicand >= (u_1 - u_2)^2; max() guards the rounding
    s.ddc = std::sqrt(std::max(0.0, u_1 * u_1 + u_2 * u_2 - 2 * rho * u_1 * u_2));
    const double f = floors_coincide ? coinciding_levels_factor : 1.0;
    s.ec8          = f * std::hypot(left.behaviour_factor * u_1, right.behaviour_factor * u_2);
    s.asce7 = std::hypot(left.deflection_amplification * u_1 / left.importance_factor,
                         right.deflection_amplification * u_2 / right.importance_factor);
    return s;
  }

  namespace
  {
    /// How building b's displacement at `level` follows from its floors.
    LevelInterpolation
    interpolation_at(const Model &model, const FloorResponse &floors, const unsigned int b,
                     const double level, const double tolerance)
    {
      const Building    &building = model.buildings[b];
      LevelInterpolation where;
      double             below_level = building.base_level;
      for (unsigned int f = 0; f < building.floors.size(); ++f)
        {
          const double y = building.floors[f].level;
          if (std::abs(y - level) <= tolerance)
            {
              where.below = where.above = floors.index(b, f);
              where.weight              = 0;
              return where;
            }
          if (y < level)
            {
              where.below = floors.index(b, f);
              below_level = y;
            }
          else if (where.above < 0)
            {
              where.above  = floors.index(b, f);
              where.weight = (level - below_level) / (y - below_level);
            }
        }
      Assert(where.above >= 0, dealii::ExcMessage("a common level lies below the lower roof"));
      return where;
    }

  } // namespace

  std::vector<AdjacentPair>
  adjacent_pairs(const Model &model)
  {
    const FloorResponse       floors(model);
    std::vector<AdjacentPair> pairs;
    for (unsigned int b = 0; b + 1 < model.buildings.size(); ++b)
      {
        const Building &L = model.buildings[b], &R = model.buildings[b + 1];
        AdjacentPair    pair;
        pair.left         = b;
        pair.right        = b + 1;
        pair.existing_gap = R.left - L.right;
        pair.name         = L.name + "-" + R.name;
        if (L.floors.empty() || R.floors.empty())
          {
            pairs.push_back(pair);
            continue;
          }
        // as the model builder places gap elements (model_builder.cc): every
        // floor level of either building up to the lower roof
        const double top = std::min(L.floors.back().level, R.floors.back().level);
        const double bottom    = std::max(L.base_level, R.base_level);
        const double tolerance = 1e-6 * std::max(L.floors.back().level, R.floors.back().level);
        std::vector<double> levels;
        for (const Building *building : {&L, &R})
          for (const Floor &f : building->floors)
            if (f.level <= top + tolerance && f.level > bottom + tolerance &&
                std::none_of(levels.begin(), levels.end(),
                             [&](double y) { return std::abs(y - f.level) <= tolerance; }))
              levels.push_back(f.level);
        std::sort(levels.begin(), levels.end());
        for (const double y : levels)
          {
            CommonLevel level;
            level.level    = y;
            level.sides[0] = interpolation_at(model, floors, b, y, tolerance);
            level.sides[1] = interpolation_at(model, floors, b + 1, y, tolerance);
            level.floors_coincide = level.sides[0].below == level.sides[0].above &&
                                    level.sides[1].below == level.sides[1].above;
            pair.levels.push_back(level);
          }
        pairs.push_back(pair);
      }
    return pairs;
  }

  FundamentalMode
  fundamental_mode(const Analysis &analysis, const unsigned int b)
  {
    const LinearSystem &system = analysis.system;
    const auto          range  = analysis.model.equation_range(b);
    Modes               own;
    const Modes        *modes = &analysis.building_modes[b];
    if (modes->n_modes() == 0) // not computed by prepare_analysis: no modes wanted
      {
        own   = compute_modes(block(system.mass, range), block(system.stiffness, range),
                              system.influence.segment(range[0], range[1] - range[0]), 1,
                              analysis.input.modal.eigensolver);
        modes = &own;
      }
    FundamentalMode mode;
    mode.omega              = modes->omega[0];
    mode.damping_ratio = modal_damping_ratio(block(system.damping, range),
                                             modes->shapes.col(0), mode.omega);
    return mode;
  }

  SeparationObserver::SeparationObserver(const Model &model, const std::vector<AdjacentPair> &p)
    : pairs(p)
    , floors(model)
  {
    for (const AdjacentPair &pair : pairs)
      levels.emplace_back(pair.levels.size());
  }

  double
  value_at(const std::vector<double> &x, const LevelInterpolation &where)
  {
    const double below = where.below < 0 ? 0.0 : x[where.below];
    return where.below == where.above ? below : (1 - where.weight) * below + where.weight * x[where.above];
  }

  void
  SeparationObserver::initialize(const ResponseView &state)
  {
    for (std::vector<LevelResponse> &pair : levels)
      for (LevelResponse &level : pair)
        level = LevelResponse{0, 0, -std::numeric_limits<double>::infinity(), 0};
    observe_step(state);
  }

  void
  SeparationObserver::observe_step(const ResponseView &state)
  {
    floors.evaluate(state.time(), state.displacement(), state.velocity(), state.acceleration(),
                    state.ground_acceleration());
    for (std::size_t p = 0; p < pairs.size(); ++p)
      for (std::size_t l = 0; l < pairs[p].levels.size(); ++l)
        {
          const CommonLevel &where = pairs[p].levels[l];
          LevelResponse     &r     = levels[p][l];
          const double       u_left  = value_at(floors.displacement(), where.sides[0]);
          const double       u_right = value_at(floors.displacement(), where.sides[1]);
          r.peak_left    = std::max(r.peak_left, std::abs(u_left));
          r.peak_right   = std::max(r.peak_right, std::abs(u_right));
          r.approach     = u_left - u_right;
          r.max_approach = std::max(r.max_approach, r.approach);
        }
  }

  std::vector<double>
  gap_grid(const SeparationParameters &p, const double largest)
  {
    if (!p.gap_values.empty())
      return p.gap_values;
    const double        top = largest > 0 ? 1.2 * largest : 1.0;
    std::vector<double> gaps;
    for (unsigned int k = 0; k < p.n_gap_values; ++k)
      gaps.push_back(top * k / (p.n_gap_values - 1));
    return gaps;
  }

  std::vector<ExceedancePoint>
  exceedance_curve(const std::vector<double> &sample, const std::vector<double> &gaps,
                   const double confidence)
  {
    std::vector<ExceedancePoint> curve;
    for (const double g : gaps)
      {
        ExceedancePoint point;
        point.gap         = g;
        point.n_exceeding = std::count_if(sample.begin(), sample.end(), [g](double d) { return d > g; });
        point.probability = sample.empty() ? 0.0 : double(point.n_exceeding) / sample.size();
        const ProbabilityInterval band = wilson_interval(point.n_exceeding, sample.size(), confidence);
        point.lower = band.lower;
        point.upper = band.upper;
        curve.push_back(point);
      }
    return curve;
  }

  namespace
  {
    /// Removes `names` from `directory`; an absent file is no error.
    void
    remove_files(const std::string &directory, const std::vector<const char *> &names)
    {
      for (const char *name : names)
        std::filesystem::remove(directory + "/" + name);
    }

    const std::vector<const char *> pounding_hazard_files{"pounding_hazard.csv",
                                                          "pounding_given_pga.csv",
                                                          "pounding_hazard.png"};

    /// One value for every building or one per building.
    double
    of_building(const std::vector<double> &values, const unsigned int b)
    {
      return values.size() == 1 ? values[0] : values.at(b);
    }

    BuildingCodeFactors
    code_factors(const SeparationParameters &p, const unsigned int b)
    {
      return {of_building(p.deflection_amplification, b), of_building(p.importance_factor, b),
              of_building(p.behaviour_factor, b)};
    }

    /// The values of one common level: peaks, time-history value, rules.
    struct LevelResult
    {
      double          u_left = 0, u_right = 0, time_history = 0;
      SeparationRules rules;
    };

    struct PairResult
    {
      FundamentalMode          left_mode, right_mode;
      double                   rho = 0;
      std::vector<LevelResult> levels;
      /// Monte Carlo: per completed realization, the largest approach over
      /// the pair's levels.
      std::vector<double> largest_approach;
    };

    /// The rule values and their names, in the order of separation.csv.
    const std::array<const char *, 5> rule_names{{"ABS", "SRSS", "DDC", "EC8", "ASCE7"}};

    std::array<double, 5>
    rule_values(const SeparationRules &r)
    {
      return {{r.abs, r.srss, r.ddc, r.ec8, r.asce7}};
    }

    /// Fill the rules of every level from its u_left, u_right.
    void
    apply_rules(const InputParameters &input, const AdjacentPair &pair, PairResult &result)
    {
      const SeparationParameters &p = input.separation;
      for (std::size_t l = 0; l < pair.levels.size(); ++l)
        {
          LevelResult &r = result.levels[l];
          r.rules = separation_rules(r.u_left, r.u_right, result.rho, code_factors(p, pair.left),
                                     code_factors(p, pair.right), pair.levels[l].floors_coincide,
                                     p.coinciding_levels_factor);
        }
    }

    /// realizations.csv's columns: per pair and level, the two peaks and the largest approach.
    std::vector<std::string>
    realization_columns(const std::vector<AdjacentPair> &pairs)
    {
      std::vector<std::string> names;
      for (const AdjacentPair &pair : pairs)
        for (const CommonLevel &level : pair.levels)
          {
            std::ostringstream stem;
            stem << pair.name << "@" << level.level << "_";
            for (const char *what : {"peak_u_left_m", "peak_u_right_m", "max_approach_m"})
              names.push_back(stem.str() + what);
          }
      return names;
    }

    /// The gaps of the exceedance curve: past the largest approach and the existing gaps.
    std::vector<double>
    gap_grid(const SeparationParameters &p, const std::vector<AdjacentPair> &pairs,
             const std::vector<PairResult> &results)
    {
      double top = 0;
      for (std::size_t i = 0; i < pairs.size(); ++i)
        {
          top = std::max(top, pairs[i].existing_gap);
          for (const double d : results[i].largest_approach)
            top = std::max(top, d);
        }
      return poundfe::gap_grid(p, top);
    }

    /// The gap whose P(D > g) is the target, interpolated (type-7 quantile).
    double
    gap_for_probability(std::vector<double> sample, const double probability)
    {
      std::sort(sample.begin(), sample.end());
      return quantile(sample, 1 - probability);
    }

    /// The smallest gap at which the band's upper limit is at most the
    /// target: no more than k exceedances with wilson(k, n).upper <= p;
    /// NaN when even none is not enough (too few realizations).
    double
    gap_for_probability_upper(std::vector<double> sample, const double probability,
                              const double confidence)
    {
      const unsigned long n = sample.size();
      std::sort(sample.rbegin(), sample.rend());
      long k = -1;
      while (k + 1 < long(n) && wilson_interval(k + 1, n, confidence).upper <= probability)
        ++k;
      if (k < 0)
        return std::numeric_limits<double>::quiet_NaN();
      return sample[k]; // k values lie above it (ties aside)
    }

    /// The joint of a pair: each rule's and the time history's largest
    /// requirement over the levels.
    struct Joint
    {
      std::array<double, 5> required{};
      double                time_history = 0;
      /// The larger of the two code rules: EC8 (3) or ASCE 7 (4).
      unsigned int governing_code_rule() const { return required[3] >= required[4] ? 3 : 4; }
    };

    Joint
    joint_of(const PairResult &result)
    {
      Joint joint;
      for (const LevelResult &level : result.levels)
        {
          const auto values = rule_values(level.rules);
          for (unsigned int c = 0; c < 5; ++c)
            joint.required[c] = std::max(joint.required[c], values[c]);
          joint.time_history = std::max(joint.time_history, level.time_history);
        }
      return joint;
    }

    std::string
    percent_of(const double value, const double reference)
    {
      if (!(reference > 0))
        return "n/a";
      const double percent = 100 * (value - reference) / reference;
      return (percent >= 0 ? "+" : "") + rounded(percent, 3) + " %";
    }

    /// separation.csv and its plot (one panel per pair).
    void
    write_separation_table(const std::string &directory, const Model &model,
                           const std::vector<AdjacentPair> &pairs,
                           const std::vector<PairResult> &results, std::vector<Plot> &plots,
                           const SpectrumPeaks *spectrum)
    {
      std::string csv = "pair,left,right,level_m,floors_coincide,u_left_m,u_right_m,abs_m,srss_m,"
                        "ddc_m,ec8_m,asce7_m,";
      csv += spectrum ? "u_left_srss_m,u_right_srss_m,u_left_cqc_m,u_right_cqc_m\n" :
                        "time_history_m\n";
      Plot        plot;
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
          Plot panel{"separation.png",
                     "required separation of " + pair.name + " against level" +
                       (spectrum ? " (response spectrum)" : ""),
                     "separation (m)", "level (m)", {}};
          const std::string only = "(($1==" + std::to_string(p + 1) + ")?$";
          for (unsigned int c = 0; c < rule_names.size(); ++c) // ASCE 7 dashed: it may equal SRSS
            panel.series.push_back(
              {"separation.csv", only + std::to_string(8 + c) + ":1/0):4", rule_names[c],
               c == 4 ? "linespoints dt 2" : "linespoints"});
          if (!spectrum)
            panel.series.push_back({"separation.csv", only + "13:1/0):4",
                                    "time history (no contact)", "linespoints lw 3 lc rgb 'black'"});
          panel.series.push_back({"separation.csv", "(($1==" + std::to_string(p + 1) + ")?" +
                                                      std::to_string(pair.existing_gap) + ":1/0):4",
                                  "existing gap", "lines dt 2 lc rgb 'gray40'"});
          if (p == 0)
            plot = panel;
          else
            plot.below.push_back(panel);
        }
      write_file_atomically(directory + "/separation.csv", csv);
      plots.push_back(plot);
    }

    /// pounding_probability.csv and its plot (one panel per pair).
    void
    write_probability_table(const std::string &directory, const InputParameters &input,
                            const std::vector<AdjacentPair> &pairs,
                            const std::vector<PairResult> &results, std::vector<Plot> &plots)
    {
      const std::vector<double> gaps = gap_grid(input.separation, pairs, results);
      std::vector<std::vector<ExceedancePoint>> curves;
      std::string csv = "gap_m";
      for (std::size_t p = 0; p < pairs.size(); ++p)
        {
          curves.push_back(exceedance_curve(results[p].largest_approach, gaps,
                                            input.separation.confidence_level));
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
      write_file_atomically(directory + "/pounding_probability.csv", csv);

      Plot plot;
      const std::string band =
        rounded(100 * input.separation.confidence_level) + " % band (Wilson, pointwise)";
      for (std::size_t p = 0; p < pairs.size(); ++p)
        {
          const std::string c = std::to_string(3 + 4 * p);
          Plot panel{"pounding_probability.png",
                     "probability of pounding of " + pairs[p].name + ", " +
                       std::to_string(results[p].largest_approach.size()) + " realizations",
                     "gap width g (m)", "P(largest relative approach > g)", {}};
          panel.series = {
            {"pounding_probability.csv", "1:" + std::to_string(4 + 4 * p) + ":" +
                                           std::to_string(5 + 4 * p),
             band, "filledcurves fs transparent solid 0.3 noborder lc rgb 'skyblue'"},
            {"pounding_probability.csv", "1:" + c, "Monte Carlo", "lines lw 2 lc rgb 'navy'"},
            {"pounding_probability.csv",
             "(" + std::to_string(pairs[p].existing_gap) + "):($0/" +
               std::to_string(std::max<std::size_t>(1, gaps.size() - 1)) + ".0)",
             "existing gap " + rounded(pairs[p].existing_gap) + " m", "lines dt 2 lc rgb 'red'"}};
          if (p == 0)
            plot = panel;
          else
            plot.below.push_back(panel);
        }
      plots.push_back(plot);
    }

    /// One pair's object of summary.json.
    void
    write_pair(JsonWriter &json, const SeparationParameters &s, const Model &model,
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
      json.end_object();
    }

    void
    write_summary(const std::string &directory, const InputParameters &input,
                  const Model &model, const std::vector<AdjacentPair> &pairs,
                  const std::vector<PairResult> &results, const std::string &status,
                  const std::string &method, const unsigned long n_realizations,
                  const SpectrumPeaks *spectrum, const std::optional<PoundingHazard> &hazard)
    {
      const SeparationParameters &s = input.separation;
      JsonWriter                  json;
      begin_summary(json, "separation", input, status);
      if (hazard && !hazard->failure.empty())
        json.value("message", "site hazard: " + hazard->failure);
      json.value("method", method)
        .value("peak_displacements", peak_displacements_names().name(s.peak_displacements));
      if (spectrum)
        write_spectrum_summary(json, input, model, *spectrum);
      if (n_realizations > 0)
        json.value("completed_realizations", n_realizations);
      json.value("target_probability", s.target_probability)
        .value("confidence_level", s.confidence_level)
        .value("coinciding_levels_factor", s.coinciding_levels_factor);
      json.begin_array("pairs");
      for (std::size_t p = 0; p < pairs.size(); ++p)
        write_pair(json, s, model, pairs[p], results[p], spectrum == nullptr);
      json.end_array();
      if (hazard)
        write_pounding_hazard_json(json, input, pairs, *hazard);
      json.end_object();
      write_file_atomically(directory + "/summary.json", json.str());
    }

    /// The console report: per pair and level the rules against the time
    /// history, the governing rule and the probability of pounding.
    void
    report(std::ostream &out, const InputParameters &input, const std::vector<AdjacentPair> &pairs,
           const std::vector<PairResult> &results, const bool time_history)
    {
      const SeparationParameters &s = input.separation;
      for (std::size_t p = 0; p < pairs.size(); ++p)
        {
          const AdjacentPair &pair = pairs[p];
          const PairResult   &r    = results[p];
          out << pair.name << ": existing gap " << rounded(pair.existing_gap) << " m, T = "
              << rounded(2 * M_PI / r.left_mode.omega) << " s (zeta "
              << rounded(r.left_mode.damping_ratio) << ") and "
              << rounded(2 * M_PI / r.right_mode.omega) << " s (zeta "
              << rounded(r.right_mode.damping_ratio) << "), rho = " << rounded(r.rho) << "\n";
          for (std::size_t l = 0; l < r.levels.size(); ++l)
            {
              const auto values = rule_values(r.levels[l].rules);
              out << "  level " << rounded(pair.levels[l].level) << " m"
                  << (pair.levels[l].floors_coincide ? "" : " (floors differ)");
              if (time_history)
                out << ": time history " << rounded(r.levels[l].time_history) << " m";
              else
                out << ": u " << rounded(r.levels[l].u_left) << " and "
                    << rounded(r.levels[l].u_right) << " m";
              for (unsigned int c = 0; c < 5; ++c)
                {
                  out << ", " << rule_names[c] << " " << rounded(values[c]);
                  if (time_history)
                    out << " (" << percent_of(values[c], r.levels[l].time_history) << ")";
                }
              out << "\n";
            }
          const Joint        joint     = joint_of(r);
          const unsigned int governing = joint.governing_code_rule();
          out << "  joint (largest over the levels): ";
          if (time_history)
            out << "time history " << rounded(joint.time_history) << " m; ";
          out << "governing code rule " << (governing == 3 ? "EC8 " : "ASCE 7 ")
              << rounded(joint.required[governing]) << " m";
          if (time_history)
            out << "; EC8 " << percent_of(joint.required[3], joint.time_history) << ", ASCE 7 "
                << percent_of(joint.required[4], joint.time_history) << " of the time history";
          out << "\n";
          if (!r.largest_approach.empty())
            {
              const auto at_gap = exceedance_curve(r.largest_approach, {pair.existing_gap},
                                                   s.confidence_level)[0];
              const double upper =
                gap_for_probability_upper(r.largest_approach, s.target_probability,
                                          s.confidence_level);
              out << "  P(pounding at the existing gap) = " << rounded(at_gap.probability) << " ["
                  << rounded(at_gap.lower) << ", " << rounded(at_gap.upper) << "]; gap for P = "
                  << s.target_probability << ": "
                  << rounded(gap_for_probability(r.largest_approach, s.target_probability))
                  << " m (" << rounded(100 * s.confidence_level) << " % upper band: "
                  << (std::isnan(upper) ? "needs more realizations" : rounded(upper) + " m")
                  << ")\n";
            }
        }
    }

    /// The results before any run: each building's fundamental mode, rho, the levels.
    std::vector<PairResult>
    empty_results(const Analysis &analysis, const std::vector<AdjacentPair> &pairs)
    {
      std::vector<FundamentalMode> modes;
      for (unsigned int b = 0; b < analysis.model.buildings.size(); ++b)
        modes.push_back(fundamental_mode(analysis, b));
      std::vector<PairResult> results(pairs.size());
      for (std::size_t p = 0; p < pairs.size(); ++p)
        {
          results[p].left_mode  = modes[pairs[p].left];
          results[p].right_mode = modes[pairs[p].right];
          results[p].rho = modal_correlation(modes[pairs[p].left].omega, modes[pairs[p].left].damping_ratio,
                                             modes[pairs[p].right].omega, modes[pairs[p].right].damping_ratio);
          results[p].levels.resize(pairs[p].levels.size());
        }
      return results;
    }

    /// One time history of the file's (deterministic) excitation.
    RunStatus
    run_once(const Analysis &analysis, const std::vector<AdjacentPair> &pairs,
             std::vector<PairResult> &results)
    {
      TimeHistory        history(analysis);
      SeparationObserver observer(analysis.model, pairs);
      const Excitation   excitation = make_excitation(analysis);
      const RunStatus    status     = history.run(excitation, {&observer}, true);
      for (std::size_t p = 0; p < pairs.size(); ++p)
        for (std::size_t l = 0; l < pairs[p].levels.size(); ++l)
          {
            const SeparationObserver::LevelResponse &response = observer.responses()[p][l];
            results[p].levels[l].u_left       = response.peak_left;
            results[p].levels[l].u_right      = response.peak_right;
            results[p].levels[l].time_history = response.max_approach;
          }
      return status;
    }

    /// The response-spectrum route's peaks, by `combination`, into the
    /// levels (no time-history value).
    void
    fill_from_spectrum(const SpectrumPeaks &spectrum, const ModalCombination combination,
                       std::vector<PairResult> &results)
    {
      for (std::size_t p = 0; p < results.size(); ++p)
        for (std::size_t l = 0; l < results[p].levels.size(); ++l)
          {
            LevelResult &level = results[p].levels[l];
            level.u_left       = spectrum.levels[p][l][0].of(combination);
            level.u_right      = spectrum.levels[p][l][1].of(combination);
            level.time_history = std::numeric_limits<double>::quiet_NaN();
          }
    }

    /// Monte Carlo over the random loading: the means of the peaks and the
    /// largest approach of every realization. Returns the table (rank 0).
    MonteCarloTable
    run_realizations_without_contact(const Analysis &analysis, const std::vector<AdjacentPair> &pairs,
                                     const std::string &directory, const MPI_Comm comm,
                                     std::vector<PairResult> &results)
    {
      RealizationRunner  runner(analysis);
      SeparationObserver observer(analysis.model, pairs);
      RealizationJob     job;
      job.names = realization_columns(pairs);
      job.seed  = runner.stochastic_load().seed();
      job.run   = [&](const std::uint64_t r, std::vector<double> &row) {
        const bool completed = runner.run(r, Observers{&observer});
        row.clear();
        for (const auto &pair : observer.responses())
          for (const SeparationObserver::LevelResponse &level : pair)
            for (const double x : {level.peak_left, level.peak_right, level.max_approach})
              row.push_back(x);
        return completed;
      };
      const unsigned long n = analysis.input.monte_carlo.realizations;
      Progress            progress(std::cerr, "realizations", n);
      MonteCarloTable     table =
        run_realizations(job, n, directory + "/realizations.csv", comm, "", &progress);
      progress.finish();
      unsigned int column = 0;
      for (std::size_t p = 0; p < pairs.size(); ++p)
        {
          for (std::size_t l = 0; l < pairs[p].levels.size(); ++l, column += 3)
            {
              LevelResult &level = results[p].levels[l];
              level.u_left       = describe(table.completed_values(column)).mean;
              level.u_right      = describe(table.completed_values(column + 1)).mean;
              const std::vector<double> approach = table.completed_values(column + 2);
              level.time_history = describe(approach).mean;
              auto &largest      = results[p].largest_approach;
              largest.resize(approach.size(), -std::numeric_limits<double>::infinity());
              for (std::size_t i = 0; i < approach.size(); ++i)
                largest[i] = std::max(largest[i], approach[i]);
            }
        }
      return table;
    }
  } // namespace

  int
  separation_command(const InputParameters &file_input, const std::string &directory,
                     const MPI_Comm comm)
  {
    // The free responses: no gap element between the buildings, no barrier.
    InputParameters input = file_input;
    input.contact.law     = "none";
    if (input.model.buildings.size() < 2)
      input.fail("Model/Number of buildings",
                 "separation needs two or more adjacent buildings, got " +
                   std::to_string(input.model.buildings.size()));
    const Analysis                  analysis = prepare_analysis(input);
    const std::vector<AdjacentPair> pairs    = adjacent_pairs(analysis.model);
    for (const AdjacentPair &pair : pairs)
      if (pair.levels.empty())
        input.fail("Model/Number of buildings",
                   "buildings " + pair.name + " have no level in common (a floor of either "
                   "above both bases and up to the lower roof)");
    const bool by_spectrum =
      input.separation.peak_displacements == PeakDisplacements::response_spectrum;
    if (by_spectrum && input.spectrum.target == DesignSpectrum::none)
      input.fail("Separation/Peak displacements",
                 "response spectrum needs a design spectrum: set Spectrum/Target "
                 "(ec8-type-1 or ec8-type-2)");
    const bool random = !by_spectrum && (input.ground_motion.is_stochastic() ||
                                         !input.nodal_forces.white_noise.empty());
    std::optional<PoundingHazard> hazard; // read and checked before any output
    if (by_spectrum && input.separation.hazard.given())
      input.fail(input.separation.hazard.hazard_file.empty() ?
                   "Separation/Site hazard/Annual rate at 1 g" :
                   "Separation/Site hazard/File",
                 "a site hazard needs the time-history route (Monte Carlo of a random "
                 "ground motion at its PGA levels), not Peak displacements = response spectrum");
    if (input.separation.hazard.given())
      hazard = prepare_pounding_hazard(analysis);
    const unsigned int         rank = dealii::Utilities::MPI::this_mpi_process(comm);
    dealii::ConditionalOStream pcout(std::cout, rank == 0);
    std::optional<SpectrumPeaks> spectrum; // before any output: it may find bad input
    if (by_spectrum && rank == 0)
      spectrum = spectrum_peaks(analysis, pairs);
    if (rank == 0)
      {
        create_directories(directory);
        // an earlier run's files that this run does not write
        if (!by_spectrum)
          remove_files(directory, {"spectrum_modes.csv"});
        if (!random)
          remove_files(directory, {"pounding_probability.csv", "pounding_probability.png"});
        if (!hazard)
          remove_files(directory, pounding_hazard_files);
      }

    std::vector<PairResult> results = empty_results(analysis, pairs);
    std::string             status  = "completed", method;
    unsigned long           n_completed = 0;
    int                     exit_status = 0;
    if (by_spectrum)
      {
        if (rank != 0)
          return 0;
        method = spectrum->method;
        fill_from_spectrum(*spectrum, input.separation.modal_combination, results);
      }
    else if (random)
      {
        const MonteCarloTable table =
          run_realizations_without_contact(analysis, pairs, directory, comm, results);
        if (hazard && table.interrupted) // the levels not begun: the same command runs them
          hazard->interrupted = true;
        else if (hazard)
          run_pounding_hazard(analysis, pairs, directory, comm, *hazard);
        if (table.interrupted || (hazard && hazard->interrupted))
          status = "interrupted", exit_status = interrupted_exit_status();
        else if (hazard && !hazard->failure.empty()) // the per-event results stand
          {
            status = "failed", exit_status = 2;
            if (rank == 0)
              std::cerr << "poundfe: numerical failure: site hazard: " << hazard->failure
                        << " (the per-event results and the levels' realizations are written)\n";
          }
        if (rank != 0)
          return exit_status;
        n_completed = results[0].largest_approach.size();
        method      = "Monte Carlo without contact: means of " + std::to_string(n_completed) +
                 " realizations";
        if (n_completed == 0)
          throw NumericalError("no realization completed (see realizations.csv)");
      }
    else
      {
        if (rank != 0)
          return 0;
        const RunStatus run = run_once(analysis, pairs, results);
        status              = run.name();
        method              = "time history without contact";
        if (run.kind == RunStatus::Kind::failed)
          {
            std::cerr << "poundfe: numerical failure: " << run.message
                      << " (results up to t = " << run.end_time << " s are written)\n";
            exit_status = 2;
          }
        else if (run.kind == RunStatus::Kind::interrupted)
          exit_status = interrupted_exit_status();
      }
    for (std::size_t p = 0; p < pairs.size(); ++p)
      apply_rules(input, pairs[p], results[p]);

    std::vector<Plot> plots;
    const SpectrumPeaks *by_modes = spectrum ? &*spectrum : nullptr;
    write_separation_table(directory, analysis.model, pairs, results, plots, by_modes);
    if (by_modes)
      write_spectrum_modes(directory, analysis.model, *by_modes);
    if (random)
      write_probability_table(directory, input, pairs, results, plots);
    if (hazard && !hazard->interrupted && hazard->failure.empty())
      write_pounding_hazard(directory, input, pairs, *hazard, plots);
    else if (hazard) // interrupted or failed: no table of an earlier run beside it
      remove_files(directory, pounding_hazard_files);
    if (input.output.plots && status == "completed")
      draw_plots(directory, plots);
    write_summary(directory, input, analysis.model, pairs, results, status, method, n_completed,
                  by_modes, hazard);

    pcout << "poundfe separation: " << method << "\n";
    report(std::cout, input, pairs, results, !by_spectrum);
    if (hazard && rank == 0)
      report_pounding_hazard(std::cout, input, pairs, *hazard);
    pcout << "results in " << directory << "/ (summary.json, separation.csv"
          << (random ? ", pounding_probability.csv, realizations.csv" : "")
          << (by_spectrum ? ", spectrum_modes.csv" : "")
          << (hazard && hazard->failure.empty() ? ", pounding_hazard.csv, pounding_given_pga.csv" : "")
          << (hazard ? ", pga_*g/" : "")
          << (input.output.plots && status == "completed" ? ", *.png" : "") << ")\n";
    return exit_status;
  }
} // namespace poundfe
