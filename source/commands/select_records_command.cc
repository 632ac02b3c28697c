// `poundfe select-records`: selects Selection/Records records of a suite
// and their scale factors to match a target spectrum by least squares on
// ln Sa over a period range (assessment/record_selection.h; the targets:
// excitation/target_spectrum.h and EC8's of response_spectrum.h); writes
// selected_suite.csv (a record suite IDA/Suite reads: the records with
// their scale factors), selection.csv (per period the target, its
// +/- 1 sigma, the selected set's geometric mean and +/- 1 sigma, and each
// selected record's scaled Sa), selection.png and summary.json.
#include <poundfe/assessment/ida.h>
#include <poundfe/assessment/record_selection.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/commands/command.h>
#include <poundfe/excitation/intensity_measures.h>
#include <poundfe/excitation/record_suite.h>
#include <poundfe/excitation/response_spectrum.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/output/append_file.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/csv_columns.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/plots.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace poundfe::commands
{
  namespace
  {
    /// The user's table (period_s, sa_g) at `periods`, interpolated in
    /// (ln T, ln Sa); every Sa must be positive, the periods within it.
    std::vector<double>
    table_spectrum(const InputParameters &input, const std::vector<double> &periods)
    {
      const std::string path = input.resolve(input.selection.table);
      std::vector<std::vector<double>> columns;
      try
        {
          const std::vector<std::string> header = read_csv_header(path);
          std::vector<unsigned int>       at;
          for (const std::string name : {"period_s", "sa_g"})
            {
              const auto it = std::find(header.begin(), header.end(), name);
              if (it == header.end())
                throw InputError(path, 1, name, "the spectrum table has no column '" + name + "'");
              at.push_back(it - header.begin());
            }
          columns = read_csv_columns(path, at);
        }
      catch (const OutputError &error)
        {
          throw InputError(path, 0, "Selection/Spectrum table", error.what());
        }
      const std::vector<double> &t = columns[0], &sa = columns[1];
      for (std::size_t i = 0; i < t.size(); ++i)
        {
          if (!(sa[i] > 0))
            throw InputError(path, i + 2, "sa_g", "a target spectrum must be positive, got " +
                                                    rounded(sa[i]) + " g");
          if (!(t[i] > 0) || (i > 0 && !(t[i] > t[i - 1])))
            throw InputError(path, i + 2, "period_s", "the periods must be positive and ascend");
        }
      if (t.size() < 2)
        throw InputError(path, 0, "Selection/Spectrum table", "the table needs two periods");
      if (periods.front() < t.front() || periods.back() > t.back())
        input.fail(periods.front() < t.front() ? "Selection/Minimum period" : "Selection/Maximum period",
                   "the period range is outside the spectrum table's (" + rounded(t.front()) +
                     " to " + rounded(t.back()) + " s)");
      std::vector<double> values;
      for (const double p : periods)
        {
          const std::size_t i = std::min<std::size_t>(
            t.size() - 1, std::max<std::size_t>(1, std::lower_bound(t.begin(), t.end(), p) - t.begin()));
          const double w = std::log(p / t[i - 1]) / std::log(t[i] / t[i - 1]);
          values.push_back(sa[i - 1] * std::pow(sa[i] / sa[i - 1], w));
        }
      return values;
    }

    /// The target at the selection's periods (g).
    TargetSpectrum
    target_spectrum(const InputParameters &input)
    {
      const SelectionParameters &s = input.selection;
      const double               zeta = input.ida.damping_ratio;
      TargetSpectrum             target;
      target.periods = period_grid(s.min_period, s.max_period, s.n_periods, true);
      target.sigma.assign(target.periods.size(), 0.0);
      if (s.target == SelectionTarget::table)
        target.median = table_spectrum(input, target.periods);
      else if (s.target == SelectionTarget::cms)
        {
          if (std::abs(zeta - 0.05) > 1e-12)
            input.fail("IDA/Damping ratio", "a conditional mean spectrum (BSSA14) is of 5 % "
                                            "damping: set 0.05");
          target.median.clear(), target.sigma.clear();
          for (const LogNormalValue &v : conditional_mean_spectrum(
                 s.scenario, s.conditioning_period, s.epsilon, target.periods))
            target.median.push_back(v.median), target.sigma.push_back(v.sigma);
        }
      else
        for (const double t : target.periods)
          target.median.push_back(
            s.target == SelectionTarget::asce7 ?
              asce7_design_spectrum(s.sds, s.sd1, s.tl, t) :
              ec8_elastic_spectrum(s.target == SelectionTarget::ec8_type_1 ? DesignSpectrum::ec8_type_1 :
                                                                             DesignSpectrum::ec8_type_2,
                                   input.spectrum.ground_type,
                                   input.spectrum.design_ground_acceleration, zeta, t));
      return target;
    }

    /// Refuses a fit's periods outside those every record resolves
    /// (record_suite.h): a record's Sa there is not of its own motion.
    void
    refuse_fit_periods_the_records_do_not_resolve(const RecordSuite &suite,
                                                  const InputParameters &input)
    {
      const ResolvedPeriods      resolved = resolved_periods(suite);
      const SelectionParameters &s        = input.selection;
      if (resolved.holds(s.min_period) && resolved.holds(s.max_period))
        return;
      input.fail(resolved.holds(s.min_period) ? "Selection/Maximum period" : "Selection/Minimum period",
                 "the fit's periods, " + rounded(s.min_period, 6) + " to " +
                   rounded(s.max_period, 6) +
                   " s, lie outside the periods every record of the suite resolves, " +
                   resolved.text());
    }

    /// Each record's Sa (g) at the target's periods (IDA/Pair measure for pairs).
    std::vector<std::vector<double>>
    record_spectra(const RecordSuite &suite, const InputParameters &input,
                   const std::vector<double> &periods)
    {
      std::vector<std::vector<double>> spectra;
      for (const SuiteRecord &record : suite.records)
        {
          spectra.emplace_back();
          for (const double t : periods)
            {
              spectra.back().push_back(intensity_of(record.components, IntensityMeasure::sa,
                                                    input.ida.pair, {t}, input.ida.damping_ratio));
              if (!(spectra.back().back() > 0))
                throw InputError(suite.file, record.line, "file",
                                 "record '" + record.name + "' has Sa = 0 at " + rounded(t) + " s");
            }
        }
      return spectra;
    }

    /// Scaling = intensity: each record's factor to Selection/Target intensity.
    std::vector<double>
    intensity_scales(const RecordSuite &suite, const InputParameters &input)
    {
      const IdaParameters &ida = input.ida;
      if ((ida.measure == IntensityMeasure::sa || ida.measure == IntensityMeasure::sa_avg) &&
          ida.period == 0)
        input.fail("IDA/Period", "select-records builds no model: scaling to Sa needs a Period > 0");
      refuse_periods_the_records_do_not_resolve(ida, ida.period, suite, input);
      std::vector<double> scales;
      for (const SuiteRecord &record : suite.records)
        scales.push_back(input.selection.target_intensity /
                         intensity_of(record.components, ida.measure, ida.pair,
                                      ida.measure_periods(ida.period), ida.damping_ratio));
      return scales;
    }

    /// selected_suite.csv: the selected records with their scale factors.
    void
    write_suite(const std::string &directory, const RecordSuite &suite,
                const RecordSelection &selection)
    {
      std::string text = std::string("name,file") + (suite.pairs() ? ",file2" : "") +
                         ",scale,event,station,magnitude,distance_km,vs30_m_s\n";
      for (const SelectedRecord &s : selection.records)
        {
          const SuiteRecord &r = suite.records[s.index];
          text += r.name;
          for (const std::string &file : r.files)
            text += "," + std::filesystem::absolute(file).lexically_normal().string();
          append_field(text, r.scale_factor * s.scale);
          text += "," + r.event + "," + r.station;
          for (const double x : {r.magnitude, r.distance_km, r.vs30_m_s})
            append_field(text, x);
          text += "\n";
        }
      write_file_atomically(directory + "/selected_suite.csv", text);
    }

    /// selection.csv: per period the target, the set and each scaled record.
    void
    write_spectra(const std::string &directory, const RecordSuite &suite,
                  const TargetSpectrum &target, const RecordSelection &selection,
                  const std::vector<std::vector<double>> &spectra)
    {
      std::string text = "period_s,target_g,target_minus_g,target_plus_g,mean_g,mean_minus_g,"
                         "mean_plus_g";
      for (const SelectedRecord &s : selection.records)
        text += "," + suite.records[s.index].name;
      text += "\n";
      for (std::size_t i = 0; i < target.periods.size(); ++i)
        {
          append_number(text, target.periods[i]);
          for (const double x : {target.median[i], target.median[i] * std::exp(-target.sigma[i]),
                                 target.median[i] * std::exp(target.sigma[i]), selection.mean[i],
                                 selection.mean[i] * std::exp(-selection.sigma[i]),
                                 selection.mean[i] * std::exp(selection.sigma[i])})
            append_field(text, x);
          for (const SelectedRecord &s : selection.records)
            append_field(text, s.scale * spectra[s.index][i]);
          text += "\n";
        }
      write_file_atomically(directory + "/selection.csv", text);
    }

    /// selection.png: the scaled records (grey), their mean and spread, the target.
    Plot
    selection_plot(const RecordSelection &selection)
    {
      Plot plot{"selection.png", "Selected records against the target", "period (s)", "Sa (g)", {}};
      for (std::size_t k = 0; k < selection.records.size(); ++k)
        plot.series.push_back({"selection.csv", "1:" + std::to_string(8 + k), "",
                               "lines lw 1 lc rgb 'gray'"});
      plot.series.push_back({"selection.csv", "1:2", "target", "lines lw 3 lc rgb 'black'"});
      plot.series.push_back({"selection.csv", "1:3", "target +/- 1 sigma", "lines lw 2 dt 2 lc rgb 'black'"});
      plot.series.push_back({"selection.csv", "1:4", "", "lines lw 2 dt 2 lc rgb 'black'"});
      plot.series.push_back({"selection.csv", "1:5", "selected: geometric mean", "lines lw 3 lc rgb 'red'"});
      plot.series.push_back({"selection.csv", "1:6", "selected +/- 1 sigma", "lines lw 2 dt 3 lc rgb 'red'"});
      plot.series.push_back({"selection.csv", "1:7", "", "lines lw 2 dt 3 lc rgb 'red'"});
      plot.log_x = true;
      plot.log_y = true;
      return plot;
    }

    /// summary.json's selection; the report's lines.
    void
    write_summary(JsonWriter &json, std::ostream &out, const RecordSuite &suite,
                  const RecordSelection &selection, const InputParameters &input)
    {
      const SelectionParameters &s = input.selection;
      json.value("target", selection_target_names().name(s.target))
        .value("scaling", s.scale_to_intensity ? "intensity" : "least-squares")
        .value("periods_s", std::vector<double>{s.min_period, s.max_period})
        .value("candidates", static_cast<unsigned long>(suite.records.size()))
        .value("within_scale_limits", selection.n_within)
        .value("max_mean_log_misfit", selection.max_mean_misfit);
      json.begin_array("records");
      for (const SelectedRecord &r : selection.records)
        {
          const std::string &name = suite.records[r.index].name;
          json.begin_object().value("name", name).value("scale_factor", r.scale)
            .value("log_misfit", r.misfit).end_object();
          out << name << ": scale " << rounded(r.scale) << ", rms ln misfit " << rounded(r.misfit)
              << "\n";
        }
      json.end_array();
      out << "the set's geometric mean is within a factor exp(" << rounded(selection.max_mean_misfit)
          << ") = " << rounded(std::exp(selection.max_mean_misfit)) << " of the target\n";
    }
  } // namespace

  int
  select_records(const CommandRun &run)
  {
    const InputParameters     &input = *run.input;
    const SelectionParameters &s     = input.selection;
    const std::string &named = s.candidates.empty() ? input.ida.suite : s.candidates;
    const std::string  entry = s.candidates.empty() ? "IDA/Suite" : "Selection/Candidates";
    if (named.empty())
      input.fail("Selection/Candidates", "select-records needs a suite (Selection/Candidates "
                                         "or IDA/Suite)");
    const RecordSuite suite = read_record_suite(input.resolve(named), entry);
    if (suite.records.size() < s.n_records)
      input.fail("Selection/Records", "the suite has " + std::to_string(suite.records.size()) +
                                        " records, fewer than the " + std::to_string(s.n_records) +
                                        " requested");
    refuse_fit_periods_the_records_do_not_resolve(suite, input);
    const TargetSpectrum target = target_spectrum(input);
    const std::vector<std::vector<double>> spectra = record_spectra(suite, input, target.periods);
    const RecordSelection selection =
      poundfe::select_records(spectra, target, s.n_records, s.scale_limits[0], s.scale_limits[1],
                     s.scale_to_intensity ? intensity_scales(suite, input) : std::vector<double>{});
    if (selection.records.size() < s.n_records)
      input.fail("Selection/Scale limits",
                 "only " + std::to_string(selection.n_within) + " of the " +
                   std::to_string(suite.records.size()) + " records have a scale factor within [" +
                   rounded(s.scale_limits[0]) + ", " + rounded(s.scale_limits[1]) + "]; " +
                   std::to_string(s.n_records) + " requested");
    write_suite(run.directory, suite, selection);
    write_spectra(run.directory, suite, target, selection, spectra);
    JsonWriter json;
    begin_summary(json, "select-records", input, "completed");
    write_summary(json, run.out, suite, selection, input);
    json.end_object();
    if (input.output.plots)
      draw_plots(run.directory, {selection_plot(selection)});
    write_file_atomically(run.directory + "/summary.json", json.str());
    run.out << "results in " << run.directory << "/ (summary.json, selected_suite.csv, "
            << "selection.csv" << (input.output.plots ? ", selection.png" : "") << ")\n";
    return 0;
  }
} // namespace poundfe::commands
