// `poundfe stationary-pdf`: the stationary densities of a noisy response
// (reliability/stationary_pdf.h computes them); rank 0 writes pdf.csv,
// joint_pdf.csv, summary.json and the plots. With the section's Parameter
// and Values, one such analysis per value and the P-bifurcation diagram.
#include <poundfe/input/engine_parameters.h>
#include <poundfe/base/interruption.h>
#include <poundfe/base/progress.h>
#include <poundfe/commands/command.h>
#include <poundfe/excitation/stochastic.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/input/sweep.h>
#include <poundfe/output/append_file.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/plots.h>
#include <poundfe/reliability/stationary_pdf.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>

namespace poundfe::commands
{
  namespace
  {
    const std::array<const char *, 3> value_unit    = {{"m", "m_s", "m"}};
    const std::array<const char *, 3> density_unit  = {{"1_m", "s_m", "1_m"}};
    const std::array<const char *, 3> quantity_name = {
      {"displacement x (m)", "velocity v (m/s)", "amplitude a (m)"}};

    /// Where one analysis's results go: the run's directory, or a value's
    /// folder in it ("<column>_<value>/"); in memory, under the same names.
    struct StationaryPdfPlace
    {
      const CommandRun &run;
      std::string       folder; // "" or "<name>/"

      std::string
      directory() const
      {
        return folder.empty() ? run.directory :
                                run.directory + "/" + folder.substr(0, folder.size() - 1);
      }

      void
      write(const std::string &name, const std::string &text) const
      {
        write_result_text(run.memory, run.directory, folder + name, text);
      }
    };

    void
    write_pdf_csv(const StationaryPdfPlace &place, const PdfLayout &layout,
                  const std::array<QuantityEstimate, 3> &e)
    {
      std::string text;
      for (unsigned int q = 0; q < 3; ++q)
        text += std::string(q ? "," : "") + pdf_quantities[q] + "_" + value_unit[q] + ",p_" +
                pdf_quantities[q] + "_histogram_" + density_unit[q] + ",p_" + pdf_quantities[q] + "_kde_" +
                density_unit[q];
      text += "\n";
      for (unsigned int i = 0; i < layout.grids[0].n_bins; ++i)
        for (unsigned int q = 0; q < 3; ++q)
          {
            for (const double x : {layout.grids[q].center(i), e[q].histogram[i]})
              append_number(text, x), text += ',';
            append_number(text, e[q].kde[i]);
            text += q < 2 ? "," : "\n";
          }
      place.write("pdf.csv", text);
    }

    /// p(x, v) = c_ij / (N w_x w_v); a blank line after each x (gnuplot's grid).
    void
    write_joint_csv(const StationaryPdfPlace &place, const PdfLayout &layout,
                    const std::vector<double> &total)
    {
      const BinGrid &gx = layout.grids[0], &gv = layout.grids[1];
      const double   scale = 1 / (total[0] * gx.width() * gv.width());
      std::string    text  = "x_m,v_m_s,p_xv_s_m2\n";
      for (unsigned int i = 0; i < gx.n_bins; ++i)
        {
          for (unsigned int j = 0; j < gv.n_bins; ++j)
            {
              for (const double x : {gx.center(i), gv.center(j)})
                append_number(text, x), text += ',';
              append_number(text, total[layout.joint() + i * gv.n_bins + j] * scale);
              text += '\n';
            }
          text += '\n';
        }
      place.write("joint_pdf.csv", text);
    }

    /// The intervals as [low1, high1, low2, high2, ...].
    std::vector<double>
    support_ends(const std::vector<SupportInterval> &support)
    {
      std::vector<double> ends;
      for (const SupportInterval &s : support)
        ends.insert(ends.end(), {s.low, s.high});
      return ends;
    }

    std::vector<double>
    peak_values(const std::vector<Peak> &peaks, const bool locations)
    {
      std::vector<double> values;
      for (const Peak &peak : peaks)
        values.push_back(locations ? peak.location : peak.height);
      return values;
    }

    void
    write_estimates(JsonWriter &json, const PdfLayout &layout,
                    const std::array<QuantityEstimate, 3> &e)
    {
      for (unsigned int q = 0; q < 3; ++q)
        json.begin_object(pdf_quantities[q])
          .value("mean", e[q].mean)
          .value("variance", e[q].variance)
          .value("standard_deviation", std::sqrt(e[q].variance))
          .value("range", std::vector<double>{layout.grids[q].low, layout.grids[q].high})
          .value("fraction_outside_range", e[q].outside)
          .value("kernel_bandwidth", e[q].bandwidth)
          .value("bandwidth_rule", e[q].rule +
                                     (e[q].widened ? ", raised to the bin width" : ""))
          .value("n_peaks", e[q].peaks.size())
          .value("peak_locations", peak_values(e[q].peaks, true))
          .value("peak_densities", peak_values(e[q].peaks, false))
          .value("n_support_intervals", e[q].support.size())
          .value("support_intervals", support_ends(e[q].support))
          .end_object();
    }

    /// pdf.png: one panel per quantity, histogram and kernel density.
    std::vector<Plot>
    pdf_plots(const unsigned long n_samples, const unsigned long n_realizations)
    {
      std::array<Plot, 3> panel;
      for (unsigned int q = 0; q < 3; ++q)
        {
          const std::string c = std::to_string(3 * q + 1);
          panel[q]            = Plot{"", "", quantity_name[q], "probability density",
                          {{"pdf.csv", c + ":" + std::to_string(3 * q + 2), "histogram", "histeps"},
                           {"pdf.csv", c + ":" + std::to_string(3 * q + 3), "Gaussian KDE",
                            "lines lw 2"}}};
        }
      Plot pdf       = panel[0];
      pdf.file       = "pdf.png";
      pdf.title      = "stationary PDFs, " + std::to_string(n_samples) + " samples of " +
                  std::to_string(n_realizations) + " realizations";
      pdf.below      = {panel[1], panel[2]};
      Plot joint{"joint_pdf.png", "joint PDF p(x, v) (2-D histogram)", quantity_name[0],
                 quantity_name[1], {{"joint_pdf.csv", "1:2:3", "", "image"}}};
      return {pdf, joint};
    }

    /// What a P-bifurcation needs of one run: the binned x and its kernel
    /// density's bandwidth and peaks (rank 0), and whether it was stopped
    /// (every rank).
    struct XDensity
    {
      bool                interrupted = false;
      BinGrid             grid;
      std::vector<double> counts;
      double              n = 0, bandwidth = 1;
      std::vector<Peak>   peaks;
      std::vector<SupportInterval> support;
    };

    /// Rank 0: pdf.csv, joint_pdf.csv, summary.json and the plots.
    XDensity
    write_results(const InputParameters &input, const StationaryPdfSetup &setup,
                  const StationaryPdfResult &result, const std::uint64_t seed,
                  const StationaryPdfPlace &place, const unsigned int n_ranks)
    {
      const PdfSampling     &s      = setup.sampling;
      const PdfLayout       &layout = setup.layout;
      const MonteCarloTable &table  = result.table;
      const unsigned long    n_done = table.realizations.size();
      const unsigned long    n_completed =
        std::count(table.completed.begin(), table.completed.end(), true);
      const unsigned long n_samples = result.n_samples;
      const double        dt        = input.time_integration.newmark.time_step;
      JsonWriter          json;
      begin_summary(json, "stationary-pdf", input, table.interrupted ? "interrupted" : "completed");
      json.value("response", s.label)
        .value("realizations", input.stationary_pdf.realizations)
        .value("realizations_done", n_done)
        .value("completed_realizations", n_completed)
        .value("seed", static_cast<unsigned long>(seed))
        .value("burn_in_s", s.first * dt)
        .value("end_time_s", s.last * dt)
        .value("sample_interval_s", s.every * dt)
        .value("samples", n_samples)
        .value("omega_rad_s", layout.omega)
        .value("bins", layout.grids[0].n_bins)
        .value("kernel_density", "Gaussian kernel on the bin centres from the binned samples")
        .value("peak_threshold", input.stationary_pdf.peak_threshold)
        .value("ranks", n_ranks)
        .value("realizations_run_now", table.n_run_now)
        .value("wall_time_s", table.wall_time)
        .value("samples_per_second", table.wall_time > 0 && n_completed > 0
                                       ? double(n_samples) / n_completed * table.n_run_now /
                                           table.wall_time
                                       : 0.0);
      XDensity x;
      x.interrupted = table.interrupted;
      x.grid        = layout.grids[0];
      if (n_samples > 0)
        {
          const std::array<QuantityEstimate, 3> &e = result.estimates;
          write_estimates(json, layout, e);
          write_pdf_csv(place, layout, e);
          write_joint_csv(place, layout, result.total);
          // stop soon: the resumed run draws them
          if (input.output.plots && !table.interrupted && !place.run.memory)
            draw_plots(place.directory(), pdf_plots(n_samples, n_completed));
          const auto first = result.total.begin() + layout.histogram(0) + 1;
          x.counts.assign(first, first + x.grid.n_bins);
          x.n         = result.total[0];
          x.bandwidth = e[0].bandwidth;
          x.peaks     = e[0].peaks;
          x.support   = e[0].support;
        }
      json.end_object();
      if (place.run.memory) // the journal's rows, which a run into files appended as they came
        place.write("realizations.csv", realizations_text(table));
      place.write("summary.json", json.str());
      return x;
    }

    /// One stationary-PDF analysis of `file_input` into `directory`, on every
    /// rank of `comm`; progress counts from `offset`. With a sampling time the
    /// runs end at burn-in + sampling time.
    XDensity
    analyse(const InputParameters &file_input, const StationaryPdfPlace &place, const MPI_Comm comm,
            const dealii::ConditionalOStream &out, const std::string &label, Progress &progress,
            const unsigned long offset)
    {
      InputParameters                input = file_input;
      const StationaryPdfParameters &p     = input.stationary_pdf;
      if (p.sampling_time > 0)
        input.time_integration.end_time = p.burn_in + p.sampling_time;
      const Analysis           analysis = prepare_analysis(input);
      const unsigned int       rank     = dealii::Utilities::MPI::this_mpi_process(comm);
      RealizationRunner        runner(analysis, time_history_parameters(input));
      const StationaryPdfSetup setup =
        setup_stationary_pdf(analysis, runner, p, input, input.time_integration.newmark.time_step,
                             input.ground_motion);
      const std::string directory = place.directory();
      // an earlier run's realizations stay: it resumes from them
      if (rank == 0 && !place.run.memory)
        prepare_output_directory(directory, {"realizations.csv"});

      const std::string         journal = place.run.memory ? "" : directory + "/realizations.csv";
      const StationaryPdfResult result =
        run_stationary_pdf(setup, runner, p, journal, comm, label, progress, offset);
      if (rank != 0)
        {
          XDensity stopped;
          stopped.interrupted = result.table.interrupted;
          return stopped;
        }
      const XDensity x = write_results(input, setup, result, runner.stochastic_load().seed(),
                                       place, dealii::Utilities::MPI::n_mpi_processes(comm));
      if (result.table.interrupted)
        out << label << "stationary PDF interrupted after " << result.table.realizations.size()
            << " of " << p.realizations << " realizations: the estimates are over these; "
            << "the same command runs the rest\n";
      out << label << "stationary PDF of " << setup.sampling.label << ": "
          << result.table.realizations.size() << " realizations; results in "
          << (place.run.memory ? "memory" : directory + "/")
          << " (summary.json, pdf.csv, joint_pdf.csv, realizations.csv)\n";
      return x;
    }

    /// p_bifurcation_density.csv: the kernel density of x of every value on
    /// one x grid (the union of the values' ranges), with the cell each
    /// point fills in the image (halfway to the neighbouring values: they
    /// need not be equally spaced). At least two values.
    void
    write_density_map(const CommandRun &run, const std::string &column,
                      const std::vector<double> &values, const std::vector<XDensity> &x)
    {
      BinGrid common = x[0].grid;
      for (const XDensity &d : x)
        common = {std::min(common.low, d.grid.low), std::max(common.high, d.grid.high),
                  std::max(common.n_bins, d.grid.n_bins)};
      std::vector<double> points(common.n_bins);
      for (unsigned int i = 0; i < common.n_bins; ++i)
        points[i] = common.center(i);
      std::string text = column + ",x_m,p_x_kde_1_m," + column + "_low," + column +
                         "_high,x_low_m,x_high_m\n";
      const std::size_t n = x.size();
      for (std::size_t j = 0; j < n; ++j)
        {
          const double low  = j > 0 ? (values[j - 1] + values[j]) / 2
                                    : 1.5 * values[0] - 0.5 * values[1];
          const double high = j + 1 < n ? (values[j] + values[j + 1]) / 2
                                        : 1.5 * values[n - 1] - 0.5 * values[n - 2];
          const std::vector<double> f =
            kernel_density(x[j].grid, x[j].counts, x[j].n, x[j].bandwidth, points);
          for (unsigned int i = 0; i < common.n_bins; ++i)
            {
              const double half = common.width() / 2;
              for (const double v : {values[j], points[i], f[i], low, high, points[i] - half})
                append_number(text, v), text += ',';
              append_number(text, points[i] + half);
              text += '\n';
            }
        }
      write_result_text(run.memory, run.directory, "p_bifurcation_density.csv", text);
    }

    /// The array `name` of summary.json: every pair of neighbouring values
    /// between which count(j) changes, with the two counts as `what`.
    template <typename Count>
    void
    write_count_changes(JsonWriter &json, const std::string &name, const std::string &what,
                        const std::vector<double> &values, const Count &count)
    {
      json.begin_array(name);
      for (std::size_t j = 1; j < values.size(); ++j)
        if (count(j) != count(j - 1))
          json.begin_object()
            .value("between", std::vector<double>{values[j - 1], values[j]})
            .value(what, std::vector<double>{double(count(j - 1)), double(count(j))})
            .end_object();
      json.end_array();
    }

    /// p_bifurcation.csv (value, number of peaks, their locations, the number
    /// of support intervals and their hull) and the
    /// summary's entries; returns the most peaks of a value.
    std::size_t
    write_peaks(const CommandRun &run, const std::string &column,
                const std::vector<double> &values, const std::vector<XDensity> &x, JsonWriter &json)
    {
      std::size_t most = 1;
      for (const XDensity &d : x)
        most = std::max(most, d.peaks.size());
      std::string text = column + ",n_peaks";
      for (std::size_t k = 1; k <= most; ++k)
        text += ",peak" + std::to_string(k) + "_x_m";
      text += ",n_support_intervals,support_low_m,support_high_m\n";
      json.begin_array("values");
      for (std::size_t j = 0; j < x.size(); ++j)
        {
          append_number(text, values[j]);
          text += ',' + std::to_string(x[j].peaks.size());
          for (std::size_t k = 0; k < most; ++k)
            {
              text += ',';
              if (k < x[j].peaks.size())
                append_number(text, x[j].peaks[k].location);
            }
          text += ',' + std::to_string(x[j].support.size()) + ',';
          if (!x[j].support.empty()) // the hull of the intervals
            {
              append_number(text, x[j].support.front().low);
              text += ',';
              append_number(text, x[j].support.back().high);
            }
          else
            text += ',';
          text += '\n';
          json.begin_object()
            .value("value", values[j])
            .value("n_peaks", x[j].peaks.size())
            .value("peak_locations", peak_values(x[j].peaks, true))
            .value("n_support_intervals", x[j].support.size())
            .value("support_intervals", support_ends(x[j].support))
            .end_object();
        }
      json.end_array();
      // The soft bifurcations (a peak more or less) and the hard ones (the
      // support splits or joins).
      write_count_changes(json, "peak_count_changes", "n_peaks", values,
                          [&](std::size_t j) { return x[j].peaks.size(); });
      write_count_changes(json, "support_changes", "n_support_intervals", values,
                          [&](std::size_t j) { return x[j].support.size(); });
      write_result_text(run.memory, run.directory, "p_bifurcation.csv", text);
      return most;
    }

    Plot
    p_bifurcation_plot(const std::string &parameter, const std::size_t most_peaks)
    {
      Plot plot{"p_bifurcation.png",
                "P-bifurcation: kernel density of x against " + parameter + " (green: peaks)",
                parameter, "displacement x (m)",
                {{"p_bifurcation_density.csv", "1:2:4:5:6:7:3", "",
                  "boxxyerror fs solid 1.0 noborder fc palette"}}};
      for (std::size_t k = 0; k < most_peaks; ++k)
        plot.series.push_back({"p_bifurcation.csv", "1:" + std::to_string(k + 3),
                               "", "points pt 7 ps 0.8 lc rgb 'green'"});
      return plot;
    }
  } // namespace

  namespace
  {
    /// The P-bifurcation: one stationary-PDF run per value, each in its own
    /// directory (resumable), then the density of x against the value.
    int
    p_bifurcation(const CommandRun &run, const dealii::ConditionalOStream &out)
    {
      const InputParameters     &input     = *run.input;
      const std::string         &directory = run.directory;
      const MPI_Comm             comm      = run.communicator;
      const SweepParameters     &sweep  = input.stationary_pdf.sweep;
      const std::vector<double>  values = sweep.values();
      std::vector<InputParameters> inputs; // every value checked before anything runs
      for (const double v : values)
        inputs.push_back(sweep_input(sweep, input, v));
      // each value's directory resumes
      if (dealii::Utilities::MPI::this_mpi_process(comm) == 0 && !run.memory)
        prepare_output_directory(directory);
      const unsigned long  per_value = input.stationary_pdf.realizations;
      Progress             progress(std::cerr, "realizations", values.size() * per_value);
      std::vector<XDensity> done;
      for (std::size_t j = 0; j < values.size(); ++j)
        {
          const std::string name  = sweep.column_name() + "_" + format_value(values[j]);
          XDensity          x     = analyse(inputs[j], {run, name + "/"}, comm, out,
                                      name + ": ", progress, j * per_value);
          if (x.interrupted)
            break;
          done.push_back(std::move(x));
        }
      progress.finish();
      const bool interrupted = done.size() < values.size();
      const int  status      = interrupted ? interrupted_exit_status() : 0;
      if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
        return status;
      JsonWriter json;
      begin_summary(json, "stationary-pdf", input, interrupted ? "interrupted" : "completed");
      json.value("parameter", sweep.parameter).value("values_done", done.size());
      const std::vector<double> swept(values.begin(), values.begin() + done.size());
      if (done.size() >= 2)
        {
          const std::size_t most = write_peaks(run, sweep.column_name(), swept, done, json);
          write_density_map(run, sweep.column_name(), swept, done);
          if (input.output.plots && !interrupted && !run.memory)
            draw_plots(directory, {p_bifurcation_plot(sweep.axis_label(), most)});
        }
      json.end_object();
      write_result_text(run.memory, directory, "summary.json", json.str());
      out << "P-bifurcation over " << sweep.parameter << ": " << done.size() << " of "
          << values.size() << " values; results in " << run.results_place()
          << " (summary.json, p_bifurcation.csv, p_bifurcation_density.csv)\n";
      return status;
    }
  } // namespace

  int
  stationary_pdf(const CommandRun &run)
  {
    const InputParameters     &input = *run.input;
    dealii::ConditionalOStream pcout(run.out,
                                     dealii::Utilities::MPI::this_mpi_process(run.communicator) == 0);
    if (!input.stationary_pdf.sweep.values().empty())
      return p_bifurcation(run, pcout);
    Progress       progress(std::cerr, "realizations", input.stationary_pdf.realizations);
    const XDensity x = analyse(input, {run, ""}, run.communicator, pcout, "", progress, 0);
    progress.finish();
    return x.interrupted ? interrupted_exit_status() : 0;
  }
} // namespace poundfe::commands
