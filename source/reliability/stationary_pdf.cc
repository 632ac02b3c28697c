// The stationary PDF of a noisy system's response (method in
// include/poundfe/reliability/stationary_pdf.h, estimators in density.h).
//   Amplitude: a = sqrt(x^2 + v^2 / omega^2) (the energy-like envelope of a
//   linear oscillator of natural frequency omega).
#include <poundfe/reliability/stationary_pdf.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/excitation/excitation_parameters.h>
#include <poundfe/excitation/stochastic.h>
#include <poundfe/model/model_builder.h>
#include <poundfe/output/append_file.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace poundfe
{
  namespace
  {
    /// Samples x and v of one equation at steps first, first + every, ... <= last.
    class StationarySampler : public StepObserver
    {
    public:
      StationarySampler(const unsigned int equation, const unsigned long first,
                        const unsigned long every, const unsigned long last)
        : equation(equation), first(first), every(every), last(last)
      {}

      void
      initialize(const ResponseView &state) override
      {
        x.clear();
        v.clear();
        observe_step(state);
      }

      void
      observe_step(const ResponseView &state) override
      {
        const unsigned long s = state.step();
        if (s >= first && s <= last && (s - first) % every == 0)
          {
            x.push_back(state.displacement()[equation]);
            v.push_back(state.velocity()[equation]);
          }
      }

      std::vector<double> x, v;

    private:
      const unsigned int  equation;
      const unsigned long first, every, last;
    };

    std::string
    number(const double x)
    {
      std::string s;
      append_number(s, x);
      return s;
    }

    PdfSampling
    make_sampling(const Analysis &analysis, const RealizationRunner &runner,
                  const StationaryPdfParameters &p, const InputFile &input, const double dt,
                  const GroundMotionParameters &g)
    {
      const std::string              path  = "Stationary PDF/Response";
      std::istringstream             fields(p.response);
      const FloorNode at = read_floor_node(input, analysis.model, fields, path, p.response,
                                           "building floor node (the DOF is ux)");
      std::string rest;
      if (fields >> rest)
        input.fail(path, "'" + p.response + "': expected 'building floor node' (the DOF is ux)");
      const int equation = analysis.model.equation(Model::dof(at.node, Component::ux));
      if (equation < 0)
        input.fail(path, "'" + p.response + "': its ux is fixed");
      const PdfSampling s{static_cast<unsigned int>(equation), at.label + " ux",
                       static_cast<unsigned long>(std::llround(p.burn_in / dt)),
                       p.interval_steps(dt), runner.n_steps()};
      if (s.first >= s.last)
        input.fail("Stationary PDF/Burn-in time",
                   "the runs end at " + number(s.last * dt) + " s, before the burn-in ends");
      if (g.is_stochastic() && g.duration < s.last * dt * (1 - 1e-12))
        input.fail(p.sampling_time > 0 ? "Stationary PDF/Sampling time" :
                                         "Time integration/End time",
                   "the runs last " + number(s.last * dt) + " s but the noise ends at " +
                     number(g.duration) + " s (Ground motion/Stochastic/Duration)");
      return s;
    }

    double
    first_natural_frequency(const Analysis &analysis, const StationaryPdfParameters &p,
                            const InputFile &input)
    {
      if (p.omega > 0)
        return p.omega;
      if (analysis.modes.n_modes() == 0)
        input.fail("Stationary PDF/Omega", "the model has no computed mode: give omega");
      return analysis.modes.omega[0];
    }

    /// [-m, m] (or [0, m] for amplitudes), m = 1.25 max |value|: symmetric
    /// about the rest position, so a pilot that stayed in one well of a
    /// double well still spans both.
    BinGrid
    pilot_grid(const std::vector<double> &values, const unsigned int bins, const bool symmetric)
    {
      double largest = 0;
      for (const double v : values)
        largest = std::max(largest, std::abs(v));
      if (!(largest > 0))
        throw NumericalError("the pilot realization's response is zero: give "
                             "'Stationary PDF/Range'");
      return {symmetric ? -1.25 * largest : 0.0, 1.25 * largest, bins};
    }

    PdfLayout
    make_layout(const Analysis &analysis, RealizationRunner &runner, const PdfSampling &s,
                const StationaryPdfParameters &p, const InputFile &input)
    {
      PdfLayout layout;
      layout.omega = first_natural_frequency(analysis, p, input);
      layout.steps = std::to_string(s.first) + ":" + std::to_string(s.every) + ":" +
                     std::to_string(s.last);
      if (p.range.size() == 4)
        {
          layout.grids[0] = {p.range[0], p.range[1], p.bins};
          layout.grids[1] = {p.range[2], p.range[3], p.bins};
          const double x = std::max(std::abs(p.range[0]), std::abs(p.range[1]));
          const double v = std::max(std::abs(p.range[2]), std::abs(p.range[3]));
          layout.grids[2] = {0, layout.amplitude(x, v), p.bins};
          return layout;
        }
      // the pilot: realization 0, the same on every rank
      StationarySampler pilot(s.equation, s.first, s.every, s.last);
      if (!runner.run(0, {&pilot}))
        throw NumericalError("the pilot realization (0) failed: see Time integration");
      std::vector<double> a(pilot.x.size());
      for (std::size_t k = 0; k < a.size(); ++k)
        a[k] = layout.amplitude(pilot.x[k], pilot.v[k]);
      layout.grids = {{pilot_grid(pilot.x, p.bins, true), pilot_grid(pilot.v, p.bins, true),
                       pilot_grid(a, p.bins, false)}};
      return layout;
    }

    /// The completed rows summed in realization order.
    std::vector<double>
    summed_rows(const MonteCarloTable &table, const unsigned int size)
    {
      std::vector<double> total(size, 0.0);
      for (std::size_t r = 0; r < table.responses.size(); ++r)
        if (table.completed[r])
          for (unsigned int j = 0; j < size; ++j)
            total[j] += table.responses[r][j];
      return total;
    }
  } // namespace

  std::vector<std::string>
  PdfLayout::names() const
  {
    std::vector<std::string> n{"samples_steps_" + steps};
    for (unsigned int q = 0; q < 3; ++q)
      for (const char *power : {"sum_", "sum_squares_"})
        n.push_back(std::string(power) + pdf_quantities[q]);
    for (unsigned int q = 0; q < 3; ++q)
      {
        n.push_back(std::string(pdf_quantities[q]) + "_below_" + number(grids[q].low));
        for (unsigned int i = 0; i < grids[q].n_bins; ++i)
          n.push_back(std::string(pdf_quantities[q]) + "_bin" + std::to_string(i));
        n.push_back(std::string(pdf_quantities[q]) + "_above_" + number(grids[q].high));
      }
    for (unsigned int i = 0; i < grids[0].n_bins; ++i)
      for (unsigned int j = 0; j < grids[1].n_bins; ++j)
        n.push_back("xv_bin" + std::to_string(i) + "_" + std::to_string(j));
    return n;
  }

  void
  PdfLayout::accumulate(const std::vector<double> &x, const std::vector<double> &v,
                        std::vector<double> &row) const
  {
    row.assign(size(), 0.0);
    row[0] = x.size();
    for (std::size_t k = 0; k < x.size(); ++k)
      {
        const std::array<double, 3> value{{x[k], v[k], amplitude(x[k], v[k])}};
        std::array<int, 3>          bin{};
        for (unsigned int q = 0; q < 3; ++q)
          {
            row[1 + 2 * q] += value[q];
            row[2 + 2 * q] += value[q] * value[q];
            bin[q] = grids[q].bin(value[q]);
            row[histogram(q) + 1 + bin[q]] += 1;
          }
        const int n_x = grids[0].n_bins, n_v = grids[1].n_bins;
        if (bin[0] >= 0 && bin[0] < n_x && bin[1] >= 0 && bin[1] < n_v)
          row[joint() + bin[0] * n_v + bin[1]] += 1;
      }
  }

  namespace
  {
    /// e.bandwidth and e.rule by p.bandwidth_rule (`below`: samples under
    /// the grid; e.variance set).
    void
    choose_bandwidth(const BinGrid &grid, const std::vector<double> &counts, const double below,
                     const double n, const StationaryPdfParameters &p, QuantityEstimate &e)
    {
      const double iqr = binned_quantile(grid, counts, below, n, 0.75) -
                         binned_quantile(grid, counts, below, n, 0.25);
      e.bandwidth      = silverman_bandwidth(std::sqrt(e.variance), iqr, n);
      e.rule           = "Silverman";
      if (p.bandwidth_rule == BandwidthRule::silverman)
        return;
      if (p.bandwidth_rule == BandwidthRule::automatic &&
          find_peaks(grid,
                     kernel_density(grid, counts, n, std::max(e.bandwidth, grid.width())),
                     p.peak_threshold)
              .size() < 2)
        {
          e.rule = "Silverman (one peak)";
          return;
        }
      const double plug_in = sheather_jones_bandwidth(grid, counts, iqr);
      if (std::isfinite(plug_in))
        e.bandwidth = plug_in, e.rule = "Sheather-Jones";
      else
        e.rule = "Silverman (Sheather-Jones has no root)";
    }
  } // namespace

  QuantityEstimate
  estimate_quantity(const PdfLayout &layout, const std::vector<double> &total, const unsigned int q,
           const StationaryPdfParameters &p)
  {
    const BinGrid &grid = layout.grids[q];
    const double   n    = total[0];
    const auto     first = total.begin() + layout.histogram(q);
    const std::vector<double> counts(first + 1, first + 1 + grid.n_bins);
    QuantityEstimate          e;
    e.mean     = total[1 + 2 * q] / n;
    e.variance = std::max(0.0, total[2 + 2 * q] / n - e.mean * e.mean);
    e.outside  = (first[0] + first[grid.n_bins + 1]) / n;
    e.bandwidth = p.bandwidths[p.bandwidths.size() == 3 ? q : 0];
    if (e.bandwidth > 0)
      e.rule = "given";
    else
      choose_bandwidth(grid, counts, first[0], n, p, e);
    e.widened   = e.bandwidth < grid.width();
    e.bandwidth = std::max(e.bandwidth, grid.width());
    e.histogram = histogram_density(grid, counts, n);
    e.kde       = kernel_density(grid, counts, n, e.bandwidth);
    e.peaks     = find_peaks(grid, e.kde, p.peak_threshold);
    e.support   = density_support(grid, e.kde, p.support_threshold);
    return e;
  }

  StationaryPdfSetup
  setup_stationary_pdf(const Analysis &analysis, RealizationRunner &runner,
                       const StationaryPdfParameters &parameters, const InputFile &input,
                       const double time_step, const GroundMotionParameters &ground_motion)
  {
    StationaryPdfSetup setup;
    setup.sampling =
      make_sampling(analysis, runner, parameters, input, time_step, ground_motion);
    setup.layout = make_layout(analysis, runner, setup.sampling, parameters, input);
    return setup;
  }

  StationaryPdfResult
  run_stationary_pdf(const StationaryPdfSetup &setup, RealizationRunner &runner,
                     const StationaryPdfParameters &parameters, const std::string &file,
                     const MPI_Comm comm, const std::string &label, Progress &progress,
                     const unsigned long offset)
  {
    const PdfSampling &sampling = setup.sampling;
    const PdfLayout   &layout   = setup.layout;
    StationarySampler  sampler(sampling.equation, sampling.first, sampling.every, sampling.last);
    const RealizationJob job{layout.names(), runner.stochastic_load().seed(),
                             [&](const std::uint64_t r, std::vector<double> &row) {
                               const bool completed = runner.run(r, {&sampler});
                               layout.accumulate(sampler.x, sampler.v, row);
                               return completed;
                             }};
    StationaryPdfResult result;
    result.table = run_realizations(job, parameters.realizations, file, comm, label, &progress,
                                    offset);
    if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
      return result;
    result.total     = summed_rows(result.table, layout.size());
    result.n_samples = result.total[0];
    if (result.n_samples > 0)
      for (unsigned int q = 0; q < 3; ++q)
        result.estimates[q] = estimate_quantity(layout, result.total, q, parameters);
    return result;
  }
} // namespace poundfe
