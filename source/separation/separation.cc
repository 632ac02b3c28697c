// Separation of adjacent buildings: the rules, the time-history minimum and
// the probability of pounding against the gap width. Equations and sources
// in include/poundfe/separation/separation.h and doc/theory.md §7.1.
#include <poundfe/reliability/montecarlo.h>
#include <poundfe/hazard/pounding_hazard.h>
#include <poundfe/dynamics/realization.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/excitation/stochastic.h>
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
  fundamental_mode(const Analysis &analysis, const unsigned int b, const Eigensolver eigensolver)
  {
    const LinearSystem &system = analysis.system;
    const auto          range  = analysis.model.equation_range(b);
    Modes               own;
    const Modes        *modes = &analysis.building_modes[b];
    if (modes->n_modes() == 0) // not computed by prepare_analysis: no modes wanted
      {
        own   = compute_modes(block(system.mass, range), block(system.stiffness, range),
                              system.influence.segment(range[0], range[1] - range[0]), 1,
                              eigensolver);
        modes = &own;
      }
    FundamentalMode mode;
    mode.omega              = modes->omega[0];
    mode.damping_ratio = modal_damping_ratio(system, range, modes->shapes.col(0), mode.omega);
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

  } // namespace

  /// Fill the rules of every level from its u_left, u_right.
  void
  apply_rules(const SeparationParameters &p, const AdjacentPair &pair, PairResult &result)
  {
    for (std::size_t l = 0; l < pair.levels.size(); ++l)
      {
        LevelResult &r = result.levels[l];
        r.rules = separation_rules(r.u_left, r.u_right, result.rho, code_factors(p, pair.left),
                                   code_factors(p, pair.right), pair.levels[l].floors_coincide,
                                   p.coinciding_levels_factor);
      }
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
    return gap_grid(p, top);
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

  /// The results before any run: each building's fundamental mode, rho, the levels.
  std::vector<PairResult>
  pair_results_before_run(const Analysis &analysis, const std::vector<AdjacentPair> &pairs,
                          const Eigensolver eigensolver)
  {
    std::vector<FundamentalMode> modes;
    for (unsigned int b = 0; b < analysis.model.buildings.size(); ++b)
      modes.push_back(fundamental_mode(analysis, b, eigensolver));
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
  run_without_contact(const Analysis &analysis, const TimeHistoryParameters &parameters,
                      const std::vector<AdjacentPair> &pairs,
           std::vector<PairResult> &results)
  {
    TimeHistory        history(analysis, parameters);
    SeparationObserver observer(analysis.model, pairs);
    const Excitation   excitation = make_excitation(analysis, parameters);
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

  /// Monte Carlo over the random loading: the means of the peaks and the
  /// largest approach of every realization. Returns the table (rank 0).
  MonteCarloTable
  run_realizations_without_contact(const Analysis &analysis, const TimeHistoryParameters &parameters,
                                   const std::vector<AdjacentPair> &pairs,
                                   const unsigned long n, const std::string &directory,
                                   const MPI_Comm comm, std::vector<PairResult> &results,
                                   const std::function<void(RealizationRunner &)> &attach_parameters,
                                   const RandomSeparations &separations)
  {
    RealizationRunner  runner(analysis, parameters);
    if (attach_parameters)
      attach_parameters(runner);
    SeparationObserver observer(analysis.model, pairs);
    RealizationJob     job;
    job.names = realization_columns(pairs);
    for (const unsigned int p : separations.pairs)
      job.names.push_back(pairs[p].name + "_random_separation_m");
    job.seed = runner.stochastic_load().seed();
    std::vector<double> xi, u, x;
    job.run  = [&](const std::uint64_t r, std::vector<double> &row) {
      const bool completed = runner.run(r, Observers{&observer});
      row.clear();
      for (const auto &pair : observer.responses())
        for (const SeparationObserver::LevelResponse &level : pair)
          for (const double x : {level.peak_left, level.peak_right, level.max_approach})
            row.push_back(x);
      // the separations' normals follow the runner's in the realization's stream
      xi.resize(runner.n_variables() + separations.pairs.size());
      standard_normals(job.seed, r, xi);
      if (separations.joint) // correlated: (structure, separations) = T(u)
        {
          u.assign(xi.begin() + runner.n_load_variables(), xi.end());
          separations.joint->to_physical(u, x);
          row.insert(row.end(), x.end() - separations.pairs.size(), x.end());
        }
      else
        for (std::size_t k = 0; k < separations.pairs.size(); ++k)
          row.push_back(separations.distributions[k].quantile(
            standard_normal_cdf(xi[runner.n_variables() + k])));
      return completed;
    };
    Progress            progress(std::cerr, "realizations", n);
    MonteCarloTable     table = run_realizations(
      job, n, directory.empty() ? "" : directory + "/realizations.csv", comm, "", &progress);
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
    for (std::size_t k = 0; k < separations.pairs.size(); ++k, ++column)
      results[separations.pairs[k]].random_separation = table.completed_values(column);
    return table;
  }

  ProbabilityEstimate
  pounding_at_random_separation(const PairResult &result)
  {
    AssertDimension(result.random_separation.size(), result.largest_approach.size());
    unsigned long n_pounding = 0;
    for (std::size_t r = 0; r < result.largest_approach.size(); ++r)
      n_pounding += result.largest_approach[r] > result.random_separation[r];
    return estimate_probability(n_pounding, result.largest_approach.size());
  }

  ApproachJob
  largest_approach_job(RealizationRunner &runner, SeparationObserver &observer,
                       const std::vector<AdjacentPair> &pairs)
  {
    ApproachJob job;
    for (const AdjacentPair &pair : pairs)
      job.pair_names.push_back(pair.name);
    job.seed = runner.stochastic_load().seed();
    job.run  = [&runner, &observer](const std::uint64_t r, const double amplitude_factor,
                                    std::vector<double> &row) {
      const bool completed = runner.run(r, Observers{&observer}, amplitude_factor);
      row.clear();
      for (const auto &pair : observer.responses())
        {
          double largest = -std::numeric_limits<double>::infinity();
          for (const SeparationObserver::LevelResponse &level : pair)
            largest = std::max(largest, level.max_approach);
          row.push_back(largest);
        }
      return completed;
    };
    return job;
  }
} // namespace poundfe
