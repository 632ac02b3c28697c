// The demand tables of `poundfe ida` and `poundfe msa` (msa: stripes and cloud)
// and the collapse margin of `poundfe ida` (commands/ida_loss.h).
#include "ida_loss.h"

#include <poundfe/assessment/collapse_margin.h>
#include <poundfe/assessment/ida_demands.h>
#include <poundfe/base/numbers.h>
#include <poundfe/excitation/intensity_measures.h>
#include <poundfe/commands/command.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/demand_table.h>
#include <poundfe/output/json_writer.h>

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <cstdio>

namespace poundfe::commands
{
  void
  write_demand_samples(const CommandRun &run, const Model &model, const IdaRunner &runner,
                       const IdaParameters &ida, const std::vector<IdaDemandSample> &samples,
                       const std::vector<std::string> &labels, JsonWriter &json,
                       std::ostream &out, std::vector<std::string> &files)
  {
    Assert(labels.size() == samples.size(), dealii::ExcMessage("a label per sample"));
    const std::string unit = intensity_unit(ida.measure);
    // Sa(T) of the rows (every record is scaled to it), as pelicun names a
    // spectral acceleration: SA_<T in s, two decimals>
    std::string spectral_type;
    if (ida.measure == IntensityMeasure::sa)
      {
        char period[32];
        std::snprintf(period, sizeof period, "%.2f", runner.measure_periods().at(0));
        spectral_type = std::string("SA_") + period;
      }
    json.begin_array("demand_tables");
    for (std::size_t k = 0; k < samples.size(); ++k)
      {
        const IdaDemandSample   &sample = samples[k];
        std::vector<std::string> names;
        for (unsigned int b = 0; b < model.buildings.size(); ++b)
          {
            DemandTable table(model, b, false, spectral_type);
            for (const ResponseDemands &row : sample.rows)
              table.add(row);
            names.push_back(demand_table_file(model, b, labels[k]));
            write_result_text(run.memory, run.directory, names.back(), table.csv());
          }
        std::vector<std::string> records;
        for (const unsigned int r : sample.records)
          records.push_back(runner.suite().records[r].name);
        const bool cloud = std::isnan(sample.intensity); // each row at its own
        json.begin_object();
        if (cloud)
          json.value("cloud", true);
        else
          json.value("intensity", sample.intensity);
        json.value("files", names)
          .value("records", records)
          .value("collapsed", sample.collapsed)
          .value("not_reached", sample.not_reached)
          .end_object();
        out << "demands "
            << (cloud ? "of the cloud (each record at its own intensity)" :
                        "at " + rounded(sample.intensity) + " " + unit)
            << ": "
            << sample.rows.size() << " records, " << sample.collapsed << " collapsed";
        if (sample.not_reached > 0)
          out << ", " << sample.not_reached << " not run that high";
        out << " (" << names.front() << (names.size() > 1 ? ", ..." : "") << ")\n";
        files.insert(files.end(), names.begin(), names.end());
      }
    json.end_array();
  }

  void
  write_ida_demand_tables(const CommandRun &run, const Model &model,
                          const IdaRunner &runner, const IdaResult &result,
                          const IdaParameters &ida, JsonWriter &json, std::ostream &out,
                          std::vector<std::string> &files)
  {
    if (ida.demand_intensities.empty())
      return;
    std::vector<IdaDemandSample> samples;
    std::vector<std::string>     labels;
    for (const double x : ida.demand_intensities)
      {
        samples.push_back(ida_demands_at(runner, result, x));
        labels.push_back("_im" + std::to_string(samples.size()));
      }
    write_demand_samples(run, model, runner, ida, samples, labels, json, out, files);
  }

  void
  write_collapse_margin(const IdaRunner &runner, const IdaResult &result,
                        const IdaParameters &ida, JsonWriter &json, std::ostream &out)
  {
    const CollapseMarginParameters &p = ida.collapse_margin;
    if (!p.requested())
      return;
    std::vector<double> collapse;
    unsigned int        censored = 0;
    for (const IdaRecordResult &record : result.records)
      if (record.collapse_intensity)
        collapse.push_back(*record.collapse_intensity);
      else if (record.done)
        ++censored;
    const double median      = median_collapse_intensity(collapse, censored);
    const bool   lower_bound = std::isinf(median);
    const CollapseMargin m   = collapse_margin(p, lower_bound ? ida.upper_intensity : median,
                                               lower_bound, runner.measure_periods().at(0));
    json.begin_object("collapse_margin")
      .value("s_ct_g", m.s_ct)
      .value("s_ct_lower_bound", m.lower_bound)
      .value("s_mt_g", m.s_mt)
      .value("period_s", m.period)
      .value("period_based_ductility", m.ductility)
      .value("seismic_design_category", design_category_names().name(p.category))
      .value("cmr", m.cmr)
      .value("ssf", m.ssf)
      .value("acmr", m.acmr)
      .value("beta_rtr", m.beta_rtr)
      .value("beta_total_exact", m.beta_total_exact)
      .value("beta_total", m.beta_total)
      .value("acceptable_acmr_10", m.acceptable_10)
      .value("acceptable_acmr_20", m.acceptable_20)
      .value("passes_acmr_10", m.passes_10)
      .value("passes_acmr_20", m.passes_20)
      .end_object();
    const std::string at_least = m.lower_bound ? ">= " : "";
    out << "FEMA P-695: S_CT " << at_least << rounded(m.s_ct) << " g, S_MT " << rounded(m.s_mt)
        << " g, CMR " << at_least << rounded(m.cmr) << ", SSF " << rounded(m.ssf) << ", ACMR "
        << at_least << rounded(m.acmr) << "; beta_TOT " << rounded(m.beta_total)
        << ", acceptable ACMR " << rounded(m.acceptable_20) << " (20 %): "
        << (m.passes_20 ? "passes" : (m.lower_bound ? "not shown" : "fails")) << ", "
        << rounded(m.acceptable_10) << " (10 %, a group's mean): "
        << (m.passes_10 ? "passes" : (m.lower_bound ? "not shown" : "fails")) << "\n";
  }
} // namespace poundfe::commands
