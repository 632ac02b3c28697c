// Multiple stripes and cloud: the fits, the hazard integration and the runs
// over the ranks (msa.h).
#include <poundfe/assessment/msa.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/base/standard_normal.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/csv_columns.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace poundfe
{
  double
  exceedance_probability(const LognormalFragility &fit, const double intensity)
  {
    return fit.fitted && intensity > 0 ? fragility(fit, intensity) : 0.0;
  }

  LognormalFragility
  fit_stripe_fragility(const std::vector<StripeCount> &stripes)
  {
    std::vector<double>        intensity;
    std::vector<unsigned long> exceeded, runs;
    for (const StripeCount &s : stripes)
      {
        Assert(s.intensity > 0 && s.exceeded <= s.runs, dealii::ExcMessage("bad stripe"));
        intensity.push_back(s.intensity), exceeded.push_back(s.exceeded), runs.push_back(s.runs);
      }
    LognormalFragility fit = fit_lognormal_fragility(intensity, exceeded, runs);
    const bool         partial = std::any_of(stripes.begin(), stripes.end(), [](const StripeCount &s) {
      return s.exceeded > 0 && s.exceeded < s.runs;
    });
    if (fit.fitted && !partial)
      fit.note = "no stripe is partly exceeded: the data do not bound beta (it tends to 0); "
                 "add stripes between the last one exceeded by none and the first by all";
    return fit;
  }

  std::vector<std::vector<unsigned int>>
  nested_limit_states(const std::vector<LimitState> &states,
                      const std::vector<const IdaPoint *> &points)
  {
    const unsigned int             n = states.size();
    std::vector<std::vector<char>> excess(n); // [state][point]
    for (unsigned int s = 0; s < n; ++s)
      for (const IdaPoint *p : points)
        if (!p->demands.empty())
          excess[s].push_back(states[s].exceeded(*p) ? 1 : 0);
    std::vector<std::vector<unsigned int>> within(n);
    for (unsigned int b = 0; b < n; ++b)
      {
        if (std::count(excess[b].begin(), excess[b].end(), 1) == 0)
          continue;
        for (unsigned int a = 0; a < n; ++a)
          {
            bool subset = a != b;
            for (std::size_t i = 0; subset && i < excess[b].size(); ++i)
              subset = !excess[b][i] || excess[a][i];
            if (subset)
              within[b].push_back(a);
          }
      }
    return within;
  }

  NestedRate
  order_nested_rates(const std::vector<LimitState> &states,
                     const std::vector<std::vector<unsigned int>> &within,
                     const std::vector<double> &rates)
  {
    NestedRate nested{within, rates, {}};
    for (unsigned int b = 0; b < states.size(); ++b)
      for (const unsigned int a : within[b])
        if (std::isfinite(rates[b]) && std::isfinite(rates[a]) && rates[b] > rates[a])
          {
            nested.bound[b] = std::min(nested.bound[b], rates[a]);
            nested.warnings.push_back(
              "'" + states[b].name + "' is nested in '" + states[a].name + "' (every run that "
              "exceeds it exceeds the other) but its fitted annual rate " + rounded(rates[b]) +
              " per year exceeds the other's " + rounded(rates[a]) + " (the fragilities are "
              "fitted one by one and cross): its rate is at most " + rounded(rates[a]));
          }
    return nested;
  }

  LognormalFragility
  CloudFit::fragility(const double threshold) const
  {
    LognormalFragility f;
    if (!fitted || !(b > 0) || !(dispersion > 0) || !(threshold > 0))
      {
        f.note = "no cloud fit with a positive slope and dispersion";
        return f;
      }
    f.theta  = std::pow(threshold / a, 1 / b);
    f.beta   = dispersion / b;
    f.fitted = true;
    return f;
  }

  CloudFit
  fit_cloud(const std::vector<double> &intensities, const std::vector<double> &demands)
  {
    Assert(intensities.size() == demands.size(), dealii::ExcMessage("cloud sizes"));
    std::vector<double> x, y;
    for (std::size_t i = 0; i < demands.size(); ++i)
      if (intensities[i] > 0 && demands[i] > 0 && std::isfinite(demands[i]))
        x.push_back(std::log(intensities[i])), y.push_back(std::log(demands[i]));
    CloudFit fit;
    fit.points = x.size();
    if (x.size() < 3)
      {
        fit.note = "fewer than three runs with a positive demand: no fit";
        return fit;
      }
    const double n  = x.size();
    double       mx = 0, my = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
      mx += x[i] / n, my += y[i] / n;
    double sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
      sxx += (x[i] - mx) * (x[i] - mx), sxy += (x[i] - mx) * (y[i] - my);
    if (!(sxx > 0))
      {
        fit.note = "every run has the same intensity: no slope";
        return fit;
      }
    fit.b = sxy / sxx;
    fit.a = std::exp(my - fit.b * mx);
    double squares = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
      {
        const double e = y[i] - (my + fit.b * (x[i] - mx));
        squares += e * e;
      }
    fit.dispersion = std::sqrt(squares / (n - 2));
    fit.fitted     = true;
    return fit;
  }

  double
  HazardCurve::rate_at(const double x) const
  {
    Assert(intensity.size() >= 2, dealii::ExcMessage("empty hazard curve"));
    if (x <= intensity.front())
      return rate.front();
    if (x >= intensity.back())
      return rate.back();
    const std::size_t i = std::upper_bound(intensity.begin(), intensity.end(), x) - intensity.begin();
    const double      t = std::log(x / intensity[i - 1]) / std::log(intensity[i] / intensity[i - 1]);
    return std::exp(std::log(rate[i - 1]) + t * std::log(rate[i] / rate[i - 1]));
  }

  double
  HazardCurve::intensity_of_return_period(const double return_period) const
  {
    const double target = 1 / return_period;
    for (std::size_t i = 0; i + 1 < intensity.size(); ++i)
      if (rate[i] >= target && rate[i + 1] <= target && rate[i] > rate[i + 1])
        {
          const double t = std::log(target / rate[i]) / std::log(rate[i + 1] / rate[i]);
          return intensity[i] * std::pow(intensity[i + 1] / intensity[i], t);
        }
    return std::nan("");
  }

  HazardCurve
  read_hazard_curve(const std::string &path, const std::string &column)
  {
    std::vector<std::string> header;
    try
      {
        header = read_csv_header(path);
      }
    catch (const OutputError &error)
      {
        throw InputError(path, 0, column, error.what());
      }
    const auto where = [&](const std::string &name) -> unsigned int {
      const auto it = std::find(header.begin(), header.end(), name);
      if (it == header.end())
        throw InputError(path, 1, name, "the hazard curve has no column '" + name + "'");
      return it - header.begin();
    };
    std::vector<std::vector<double>> columns;
    try
      {
        columns = read_csv_columns(path, {where(column), where("annual_rate_per_year")});
      }
    catch (const OutputError &error)
      {
        throw InputError(path, 0, column, error.what());
      }
    HazardCurve curve;
    for (std::size_t i = 0; i < columns[0].size(); ++i)
      {
        const double x = columns[0][i], rate = columns[1][i];
        if (!(x > 0 && rate > 0))
          continue;
        const int line = i + 2;
        if (!curve.intensity.empty() && !(x > curve.intensity.back()))
          throw InputError(path, line, column, "the intensities must ascend");
        if (!curve.rate.empty() && rate > curve.rate.back())
          throw InputError(path, line, "annual_rate_per_year",
                           "the annual rates of exceedance must not increase with the intensity");
        curve.intensity.push_back(x), curve.rate.push_back(rate);
      }
    if (curve.intensity.size() < 2)
      throw InputError(path, 0, column, "the hazard curve needs two rows with a positive "
                                        "intensity and rate");
    return curve;
  }

  double
  exceedance_rate(const HazardCurve &curve, const LognormalFragility &fit)
  {
    if (!fit.fitted)
      return std::nan("");
    constexpr unsigned int parts = 64;
    double                 sum   = 0;
    for (std::size_t i = 0; i + 1 < curve.intensity.size(); ++i)
      for (unsigned int k = 0; k < parts; ++k)
        {
          const double ratio = curve.intensity[i + 1] / curve.intensity[i];
          const double x0    = curve.intensity[i] * std::pow(ratio, double(k) / parts);
          const double x1    = curve.intensity[i] * std::pow(ratio, double(k + 1) / parts);
          sum += 0.5 * (exceedance_probability(fit, x0) + exceedance_probability(fit, x1)) *
                 (curve.rate_at(x0) - curve.rate_at(x1));
        }
    return sum + exceedance_probability(fit, curve.intensity.back()) * curve.rate.back();
  }

  bool
  LimitState::exceeded(const IdaPoint &point) const
  {
    return point.collapsed || (column >= 0 && point.demands.at(column) > threshold);
  }

  namespace
  {
    /// The rows of `tasks` (journaled in `journal`/`part`/realizations.csv;
    /// an empty `journal`: in memory, as counters.journals' part/...), dealt
    /// to the free ranks, as points in the tasks' order.
    std::vector<IdaPoint>
    run_msa_tasks(IdaRunner &runner, const std::vector<IdaTask> &tasks, const std::string &journal,
                  const std::string &part, const MPI_Comm comm, Progress *const progress,
                  IdaResult &counters)
    {
      const std::string folder = journal + "/" + part;
      if (dealii::Utilities::MPI::this_mpi_process(comm) == 0 && !journal.empty())
        create_directories(folder);
      const std::string file = journal.empty() ? "" : folder + "/realizations.csv";
      const std::vector<std::vector<double>> rows =
        run_ida_tasks(runner, tasks, file, comm, progress, counters.n_runs, counters);
      if (journal.empty()) // the journal's text under its part's name
        counters.journals.back().first = part + "/" + counters.journals.back().first;
      // a row is the first task of its record and intensity without one
      // (deal_runs refused a journal of other runs); a point without
      // demands was not run (interrupted)
      std::vector<IdaPoint> points(tasks.size());
      for (const std::vector<double> &row : rows)
        {
          std::size_t i = 0;
          while (i < tasks.size() && !(row[0] == tasks[i].record && row[1] == tasks[i].intensity &&
                                       points[i].demands.empty()))
            ++i;
          Assert(i < tasks.size(), dealii::ExcMessage("a row of no task"));
          IdaPoint &point    = points[i];
          point.intensity    = row[1];
          point.scale_factor = row[1] / runner.base_intensities()[tasks[i].record];
          point.collapsed    = row[2] != 0;
          point.demands.assign(row.begin() + 3, row.end());
        }
      counters.n_runs += rows.size();
      return points;
    }
  } // namespace

  MsaResult
  run_msa(IdaRunner &runner, const std::vector<double> &stripes, const bool cloud,
          const std::string &journal, const MPI_Comm comm, Progress *const progress)
  {
    const auto         start     = std::chrono::steady_clock::now();
    const unsigned int n_records = runner.suite().records.size();
    MsaResult          result;
    result.stripes = stripes;
    std::vector<IdaTask> tasks;
    for (const double x : stripes)
      for (unsigned int r = 0; r < n_records; ++r)
        tasks.push_back({r, x});
    const std::vector<IdaPoint> points =
      run_msa_tasks(runner, tasks, journal, "stripes", comm, progress, result.counters);
    for (std::size_t j = 0; j < stripes.size(); ++j)
      result.runs.emplace_back(points.begin() + j * n_records, points.begin() + (j + 1) * n_records);
    if (cloud && !result.counters.interrupted)
      {
        std::vector<IdaTask> own;
        for (unsigned int r = 0; r < n_records; ++r)
          own.push_back({r, runner.base_intensities()[r]});
        result.cloud = run_msa_tasks(runner, own, journal, "cloud", comm, progress, result.counters);
      }
    result.counters.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }
} // namespace poundfe
