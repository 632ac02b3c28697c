// `poundfe fragility`: Monte Carlo at each PGA level (reliability/montecarlo.h)
// and the lognormal fragility curves fitted to it; rank 0 writes the
// points, the curves, their plot and summary.json.
#include <poundfe/input/engine_parameters.h>
#include <poundfe/base/interruption.h>
#include <poundfe/base/numbers.h>
#include <poundfe/base/progress.h>
#include <poundfe/commands/command.h>
#include <poundfe/excitation/stochastic.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/output/append_file.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/plots.h>
#include <poundfe/reliability/montecarlo.h>
#include <poundfe/reliability/random_parameters.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

namespace poundfe::commands
{
  namespace
  {
    /// fragility_points.csv: the observed fractions at each level done.
    void
    write_points(const CommandRun &run, const std::vector<double> &levels,
                 const std::vector<FragilityCurve> &curves)
    {
      std::string points = "pga_g,realizations";
      for (const FragilityCurve &curve : curves)
        points += "," + curve.name + "_failures," + curve.name + "_fraction";
      points += "\n";
      for (std::size_t j = 0; j < levels.size(); ++j)
        {
          append_number(points, levels[j]);
          points += "," + std::to_string(curves.empty() ? 0 : curves[0].observed[j].n);
          for (const FragilityCurve &curve : curves)
            {
              points += "," + std::to_string(curve.observed[j].n_failures) + ",";
              append_number(points, curve.observed[j].probability);
            }
          points += "\n";
        }
      write_result_text(run.memory, run.directory, "fragility_points.csv", points);
    }

    /// fragility_curves.csv: the fits from 0 to 1.5 times the highest level.
    void
    write_fitted(const CommandRun &run, const std::vector<double> &levels,
                 const std::vector<FragilityCurve> &curves)
    {
      std::string fitted = "pga_g";
      for (const FragilityCurve &curve : curves)
        fitted += "," + curve.name;
      fitted += "\n";
      const double top = 1.5 * *std::max_element(levels.begin(), levels.end());
      for (unsigned int k = 1; k <= 200; ++k)
        {
          const double x = top * k / 200;
          append_number(fitted, x);
          for (const FragilityCurve &curve : curves)
            {
              fitted += ',';
              if (curve.fit.fitted)
                append_number(fitted, fragility(curve.fit, x));
            }
          fitted += "\n";
        }
      write_result_text(run.memory, run.directory, "fragility_curves.csv", fitted);
    }

    /// In memory, each level's realizations.csv under `folder`: the rows a
    /// run into files journals as they come (an interrupted level's too,
    /// which such a run keeps to resume from).
    void
    write_level_tables(const CommandRun &run, const FragilityLevels &done,
                       const std::string &folder)
    {
      if (run.memory)
        for (std::size_t j = 0; j < done.tables.size(); ++j)
          {
            const double level = j < done.levels.size() ? done.levels[j] : done.interrupted_level;
            write_result_text(run.memory, run.directory,
                              folder + fragility_level_folder(level) + "/realizations.csv",
                              realizations_text(done.tables[j]));
          }
    }

    /// The curves in summary.json and the console, and fragility.png's series.
    Plot
    write_curves(JsonWriter &json, const dealii::ConditionalOStream &out,
                 const std::vector<double> &levels, const std::vector<FragilityCurve> &curves)
    {
      json.begin_array("curves");
      std::ostringstream range[2];
      range[0].precision(17), range[1].precision(17);
      range[0] << *std::min_element(levels.begin(), levels.end());
      range[1] << *std::max_element(levels.begin(), levels.end());
      const std::string lowest = range[0].str(), highest = range[1].str();
      Plot plot{"fragility.png",
                "Fragility of each limit state against PGA (lognormal, maximum likelihood)",
                "PGA (g)", "P(exceedance | PGA)", {}};
      // the observed fractions reach 0 and 1: a margin keeps their markers whole
      plot.settings = "set xrange [0:" + highest + " * 1.1]\nset yrange [-0.02:1.05]\n";
      for (std::size_t i = 0; i < curves.size(); ++i)
        {
          const LognormalFragility &c = curves[i].fit;
          const std::string        &name = curves[i].name;
          json.begin_object().value("name", name).value("fitted", c.fitted);
          if (c.fitted)
            json.value("theta_g", c.theta).value("beta", c.beta).value("log_likelihood", c.log_likelihood);
          if (!c.note.empty())
            json.value("note", c.note);
          std::vector<double> fractions;
          for (const ProbabilityEstimate &p : curves[i].observed)
            fractions.push_back(p.probability);
          json.value("observed_fraction", fractions).end_object();
          // points and fit in one colour; the fit drawn over the PGA levels run
          const std::string column = std::to_string(3 + 2 * i + 1);
          const std::string colour = " lc " + std::to_string(i + 1);
          plot.series.push_back({"fragility_points.csv", "1:" + column, name + " (MC)",
                                 "points pt 7 ps 1.2" + colour});
          if (c.fitted)
            plot.series.push_back({"fragility_curves.csv",
                                   "1:(($1 >= " + lowest + " && $1 <= " + highest + ") ? $" +
                                     std::to_string(i + 2) + " : 1/0)",
                                   name + " fit", "lines lw 2" + colour});
          out << name << ": ";
          if (c.fitted)
            out << "theta = " << rounded(c.theta) << " g, beta = " << rounded(c.beta);
          else
            out << "not fitted (" << c.note << ")";
          out << "\n";
        }
      json.end_array();
      return plot;
    }

    /// With random model parameters: each curve's total dispersion (the
    /// run with them), its record-to-record part (the nominal model, the
    /// same loading normals) and the modelling part
    /// beta_M = sqrt(beta_T^2 - beta_RR^2) (theory §6.7).
    void
    write_dispersion_split(JsonWriter &json, const dealii::ConditionalOStream &out,
                           const std::vector<FragilityCurve> &total,
                           const std::vector<FragilityCurve> &nominal)
    {
      json.begin_array("dispersion");
      for (std::size_t i = 0; i < total.size(); ++i)
        {
          const LognormalFragility &t = total[i].fit, &r = nominal[i].fit;
          json.begin_object().value("name", total[i].name);
          out << total[i].name << ": ";
          if (!t.fitted || !r.fitted)
            {
              json.value("note", "not split: a curve is not fitted").end_object();
              out << "dispersion not split (a curve is not fitted)\n";
              continue;
            }
          const double modelling = std::sqrt(std::max(0.0, t.beta * t.beta - r.beta * r.beta));
          json.value("beta_total", t.beta)
            .value("beta_record_to_record", r.beta)
            .value("beta_modelling", modelling)
            .value("theta_nominal_g", r.theta);
          if (t.beta < r.beta)
            json.value("note", "beta_total < beta_record_to_record (sampling error): "
                               "beta_modelling set to 0");
          json.end_object();
          out << "beta = " << rounded(t.beta) << " = sqrt(" << rounded(r.beta)
              << "^2 record-to-record + " << rounded(modelling) << "^2 modelling)\n";
        }
      json.end_array();
    }

    /// Fibre members: at each level done, each storey's probability of each
    /// damage state (summary.json's "damage_states_per_level").
    void
    write_level_damage(JsonWriter &json, const RealizationRunner &runner,
                       const FragilityLevels &done)
    {
      if (runner.damage_state_columns().empty())
        return;
      json.begin_array("damage_states_per_level");
      for (std::size_t j = 0; j < done.levels.size(); ++j)
        {
          json.begin_object().value("pga_g", done.levels[j]);
          write_damage_probabilities(json, runner, done.counts[j]);
          json.end_object();
        }
      json.end_array();
    }
    /// Rank 0's results of the levels done (all, or those before an
    /// interruption): the tables, the fits, summary.json and the figure;
    /// whether the figure is drawn, nothing when no level was done.
    std::optional<bool>
    write_fragility(const CommandRun &run, const RealizationRunner &runner,
                    const FragilityLevels &done, const FragilityLevels *const nominal_done,
                    const bool interrupted, dealii::ConditionalOStream &pcout)
    {
      const InputParameters     &input      = *run.input;
      const std::string         &directory  = run.directory;
      const std::vector<double> &all_levels = input.fragility.pga_levels;
      const std::vector<double> &limits     = input.monte_carlo.drift_limits;
      const std::vector<double> &levels     = done.levels;
      if (interrupted)
        pcout << "fragility interrupted after " << levels.size() << " of " << all_levels.size()
              << " PGA levels: the points and curves are of these; the same command runs the "
                 "rest\n";
      JsonWriter json;
      begin_summary(json, "fragility", input, interrupted ? "interrupted" : "completed");
      json.value("intensity_measure", "PGA (g)")
        .value("pga_levels_g", all_levels)
        .value("completed_levels", levels.size())
        .value("realizations_per_level", input.fragility.realizations_per_level)
        .value("seed", static_cast<unsigned long>(runner.stochastic_load().seed()));
      write_level_tables(run, done, "");
      write_level_tables(run, nominal_done ? *nominal_done : FragilityLevels(), "record-to-record/");
      write_level_damage(json, runner, done);
      if (levels.empty()) // nothing to fit
        {
          json.end_object();
          write_result_text(run.memory, directory, "summary.json", json.str());
          return std::nullopt;
        }
      // One curve for pounding (if there are gaps) and one per drift limit.
      const std::vector<FragilityCurve> curves =
        fit_fragility_curves(done, limits, runner.has_gaps());
      write_points(run, levels, curves);
      write_fitted(run, levels, curves);
      const Plot plot = write_curves(json, pcout, levels, curves);
      if (nominal_done && nominal_done->levels.size() == levels.size())
        write_dispersion_split(json, pcout, curves,
                               fit_fragility_curves(*nominal_done, limits, runner.has_gaps()));
      json.end_object();
      const bool draws = input.output.plots && !interrupted && !run.memory;
      if (draws) // stop soon: the resumed run draws it
        draw_plots(directory, {plot});
      write_result_text(run.memory, directory, "summary.json", json.str());
      return draws;
    }
  } // namespace

  int
  fragility(const CommandRun &run)
  {
    const InputParameters     &input     = *run.input;
    const std::string         &directory = run.directory;
    const MPI_Comm             comm      = run.communicator;
    const unsigned int         rank      = dealii::Utilities::MPI::this_mpi_process(comm);
    dealii::ConditionalOStream pcout(run.out, rank == 0);
    dealii::TimerOutput timer(pcout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);

    timer.enter_subsection("set-up");
    const Analysis    analysis = prepare_analysis(input);
    const TimeHistoryParameters parameters = time_history_parameters(input);
    RealizationRunner runner(analysis, parameters);
    runner.set_section_limits(input.section_limits);
    attach_random_parameters(runner, input.random_parameters, input, input.model, input.contact, input.modal.eigensolver);
    // with random parameters, the nominal model too: the record-to-record part
    const std::unique_ptr<RealizationRunner> nominal =
      runner.n_parameters() > 0 ? std::make_unique<RealizationRunner>(analysis, parameters) :
                                  nullptr;
    const double      reference_pga = runner.reference_pga("fragility curves");
    if (rank == 0 && !run.memory) // an earlier run's realizations stay: it resumes from them
      prepare_output_directory(directory, {"realizations.csv"});
    const std::string journals = run.memory ? "" : directory; // "": none
    timer.leave_subsection();

    timer.enter_subsection("realizations");
    const std::vector<double> &all_levels = input.fragility.pga_levels;
    const std::vector<double> &limits     = input.monte_carlo.drift_limits;
    const unsigned long        per_level  = input.fragility.realizations_per_level;
    Progress progress(std::cerr, "realizations",
                      (nominal ? 2 : 1) * all_levels.size() * per_level);
    const FragilityLevels done = run_fragility_levels(runner, input.fragility, limits,
                                                      reference_pga, journals, comm, progress);
    FragilityLevels nominal_done;
    if (nominal && !done.interrupted)
      nominal_done = run_fragility_levels(*nominal, input.fragility, limits, reference_pga,
                                          run.memory ? "" : directory + "/record-to-record",
                                          comm, progress);
    progress.finish();
    timer.leave_subsection();
    const bool interrupted = done.interrupted || nominal_done.interrupted;
    const int  status      = interrupted ? interrupted_exit_status() : 0;
    if (rank != 0)
      return status;

    timer.enter_subsection("fit and output");
    const std::optional<bool> draws =
      write_fragility(run, runner, done, nominal ? &nominal_done : nullptr, interrupted, pcout);
    if (!draws)
      return status;
    timer.leave_subsection();

    pcout << "results in " << run.results_place()
          << " (summary.json, fragility_points.csv, fragility_curves.csv"
          << (*draws ? ", fragility.png" : "")
          << ", pga_*/realizations.csv)\n";
    print_timing(timer);
    return status;
  }
} // namespace poundfe::commands
