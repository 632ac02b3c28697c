// `poundfe sweep`: the run's peaks against the values of one parameter.
//   read:   the first value's input (input/sweep.h). When the parameter is a
//           registered model parameter that sets as the builder makes it
//           (model/parameter_registry.h: ModelParameter::set_as_built), its
//           model is built once and every value is checked on it; otherwise
//           every value's input is read, all checked before any run
//   runs:   each value's time history with the peak observer only, its
//           scalars one row of the table: on the model built once with the
//           value set in place (as a realization of a random structure), or
//           on the model built from the value's input
//   output: sweep.csv, summary.json, sweep.png; the console report
// The convergence to rigid contact (Contact/Model = nonsmooth with
// Parameter = Contact/Stiffness): the values are the penalty law's
// stiffnesses (each run with Contact/Model = penalty), and the file's own
// model, rigid contact, is run once more as their limit: rigid_limit.csv
// (its row), contact_convergence.csv (per stiffness, each peak drift and
// displacement's relative difference from the rigid limit), contact_convergence.png and
// summary.json's rigid_limit. A sweep mode rather than a command: the runs
// are a sweep's, on a registered parameter, and only their limit is added.
#include <poundfe/base/console.h>
#include <poundfe/base/interruption.h>
#include <poundfe/base/progress.h>
#include <poundfe/commands/command.h>
#include <poundfe/dynamics/model_parameter.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/input/sweep.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/csv_writer.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/peak_response.h>
#include <poundfe/output/plots.h>

#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <iostream>
#include <memory>
#include <stdexcept>

namespace poundfe
{
  namespace
  {
    /// The scalars of one run, named with their units: the peak drift ratio
    /// of each storey, the peak displacement (m) and absolute acceleration
    /// (m/s^2) of each floor, the largest drift ratio, with gaps the impacts,
    /// the peak contact force (N) and the smallest clearance (m), and the
    /// energy balance error.
    std::vector<std::string>
    scalar_names(const Analysis &analysis)
    {
      const FloorResponse      floors(analysis.model);
      std::vector<std::string> names = floors.column_names("storey", "peak_drift_ratio");
      for (const char *what : {"peak_displacement_m", "peak_acc_m_s2"})
        for (const std::string &name : floors.column_names("floor", what))
          names.push_back(name);
      names.push_back("max_drift_ratio");
      if (!analysis.model.gaps.empty())
        for (const char *name : {"n_impacts", "peak_contact_force_N", "min_clearance_m"})
          names.push_back(name);
      for (const std::string &name : plan_scalar_names(analysis.model))
        names.push_back(name);
      names.push_back("max_energy_error");
      return names;
    }

    std::vector<double>
    scalars(const Analysis &analysis, const PeakResponse &peaks, const ResponseView &state)
    {
      const FloorResponse &floors = peaks.floors();
      std::vector<double>  row    = floors.peak_drift_ratio();
      for (const std::vector<double> *v : {&floors.peak_displacement(), &floors.peak_acceleration()})
        row.insert(row.end(), v->begin(), v->end());
      row.push_back(peaks.largest_drift_ratio());
      if (!analysis.model.gaps.empty())
        {
          double peak_force = 0;
          for (const Impact &impact : state.impact_log().impacts())
            peak_force = std::max(peak_force, impact.peak_force);
          row.push_back(state.impact_log().impacts().size());
          row.push_back(peak_force);
          row.push_back(peaks.min_clearance());
        }
      append_plan_scalars(analysis.model, peaks, row);
      row.push_back(state.max_energy_error());
      return row;
    }

    struct SweepTable
    {
      std::vector<std::string>         names;
      std::vector<double>              values;
      std::vector<bool>                completed;
      std::vector<std::vector<double>> rows;
      unsigned int                     n_storeys = 0; // the first columns
      bool interrupted = false; // SIGINT/SIGTERM: the values finished are the result
    };

    /// One run of `analysis` (the model at `value`) with the peak observer;
    /// its row in `table`. False (no row) when a signal stopped the run.
    bool
    run_value(const Analysis &analysis, const TimeHistoryParameters &parameters,
              const InputFile &input, const SweepParameters &sweep, const double value,
              SweepTable &table)
    {
      const Excitation excitation = make_excitation(analysis, parameters);
      TimeHistory      history(analysis, parameters);
      PeakResponse       peaks(analysis.model, history.nonlinear_elements());
      const RunStatus    status = history.run(excitation, {&peaks}, true);
      if (status.kind == RunStatus::Kind::interrupted)
        return false;
      const std::vector<std::string> names = scalar_names(analysis);
      if (table.rows.empty())
        {
          table.names     = names;
          table.n_storeys = peaks.floors().n_floors();
        }
      else if (names != table.names)
        input.fail(sweep.section + "/Parameter",
                   "changes the model's floors or gaps at " + format_value(value) +
                     ": every value needs the same table columns");
      table.values.push_back(value);
      table.completed.push_back(status.completed());
      table.rows.push_back(scalars(analysis, peaks, history.state()));
      return true;
    }

    /// The swept parameter in the model of the first value's input, built
    /// once, when it is a registered model parameter that sets as the
    /// builder makes it; nullptr otherwise (an entry that is not registered:
    /// the mesh, the ground motion, ...; or one the builder derives more
    /// from, as a separation that places frames), whose values' inputs are
    /// read and built one by one. Every value is checked on it (InputError).
    std::unique_ptr<ModelRealization>
    built_once(const InputParameters &first, const Analysis &analysis,
               const std::vector<double> &values)
    {
      const SweepParameters &sweep = first.sweep;
      // rigid contact takes e from each value's input, not from the model
      // (the registered restitution refits a penalty law's damping only)
      if (first.time_integration.contact_model == ContactModel::nonsmooth)
        return nullptr;
      std::vector<ModelParameter> parameter;
      try
        {
          parameter.push_back(model_parameter(
            sweep.parameter, analysis.model,
            std::make_shared<const std::vector<HingeOrigin>>(hinge_origins(analysis.model, first.model)),
            std::make_shared<const ModelInputs>(ModelInputs{first.model, first.contact})));
        }
      catch (const std::invalid_argument &)
        {
          return nullptr;
        }
      if (!parameter.front().set_as_built(analysis.model))
        return nullptr;
      auto model = std::make_unique<ModelRealization>(analysis, std::move(parameter),
                                                      first.modal.eigensolver);
      for (const double value : values)
        try
          {
            model->check({value});
          }
        catch (const std::invalid_argument &e)
          {
            throw InputError(first.file, 0, sweep.parameter,
                             "at " + sweep.section + " value " + sweep.parameter + " = " +
                               format_value(value) + ": " + e.what());
          }
      return model;
    }

    /// A peak response's critical value of the swept parameter (e.g. the
    /// critical incidence angle of a 3D model): the value of the completed
    /// run with the largest peak.
    struct Critical
    {
      std::string name;
      double      value = 0, peak = 0;
    };

    /// The critical value of every peak column (not the smallest clearance
    /// nor the energy error, whose extreme is not a demand); none when no
    /// run completed.
    std::vector<Critical>
    critical_values(const SweepTable &table)
    {
      std::vector<Critical> critical;
      for (std::size_t c = 0; c < table.names.size(); ++c)
        {
          if (table.names[c] == "min_clearance_m" || table.names[c] == "max_energy_error")
            continue;
          Critical best{table.names[c], 0, -1};
          for (std::size_t i = 0; i < table.rows.size(); ++i)
            if (table.completed[i] && table.rows[i][c] > best.peak)
              best = {table.names[c], table.values[i], table.rows[i][c]};
          if (best.peak >= 0)
            critical.push_back(best);
        }
      return critical;
    }

    /// sweep.csv: the swept value, whether its run completed, its peaks.
    void
    write_sweep_table(const CommandRun &run, const SweepTable &table)
    {
      std::vector<std::string> header{run.input->sweep.column_name(), "completed"};
      header.insert(header.end(), table.names.begin(), table.names.end());
      const std::unique_ptr<TableWriter> csv =
        result_table_writer(run.memory, run.directory, "sweep", header);
      std::vector<double> row;
      for (std::size_t i = 0; i < table.rows.size(); ++i)
        {
          row.assign(1, table.completed[i] ? 1 : 0);
          row.insert(row.end(), table.rows[i].begin(), table.rows[i].end());
          csv->add_row(table.values[i], row);
        }
      csv->commit();
    }

    /// summary.json: the table by columns, the critical values and, for a
    /// convergence to rigid contact, the rigid limit's row.
    void
    write_sweep_summary(const CommandRun &run, const SweepTable &table, const double wall_time,
                        const bool interrupted, const bool model_built_once,
                        const SweepTable &limit)
    {
      const InputParameters &input = *run.input;
      const SweepParameters &sweep = input.sweep;
      JsonWriter             json;
      const bool             all = std::all_of(table.completed.begin(), table.completed.end(),
                                   [](const bool c) { return c; });
      begin_summary(json, "sweep", input, interrupted ? "interrupted" : all ? "completed" : "failed");
      json.value("parameter", sweep.parameter).value("command_swept", sweep.command)
        .value("n_values", table.values.size()).value("wall_time_s", wall_time)
        .value("model_built_once", model_built_once)
        .begin_object("table").value(sweep.column_name(), table.values);
      std::vector<double> completed(table.completed.begin(), table.completed.end());
      json.value("completed", completed);
      for (std::size_t c = 0; c < table.names.size(); ++c)
        {
          std::vector<double> column;
          for (const std::vector<double> &row : table.rows)
            column.push_back(row[c]);
          json.value(table.names[c], column);
        }
      json.end_object().begin_object("critical");
      for (const Critical &c : critical_values(table))
        json.begin_object(c.name).value("value", c.value).value("peak", c.peak).end_object();
      json.end_object();
      if (!limit.rows.empty()) // rigid contact, the limit of the swept stiffnesses
        {
          json.begin_object("rigid_limit").value("completed", bool(limit.completed.front()));
          for (std::size_t c = 0; c < limit.names.size(); ++c)
            json.value(limit.names[c], limit.rows.front()[c]);
          json.end_object();
        }
      json.end_object();
      write_result_text(run.memory, run.directory, "summary.json", json.str());
    }

    /// sweep.png: the storeys' peak drift ratios (and a 3D model's along y)
    /// against the swept value.
    void
    draw_sweep_plot(const std::string &directory, const SweepParameters &sweep,
                    const SweepTable &table)
    {
      Plot plot{"sweep.png", "peak inter-storey drift ratio against " + sweep.axis_label(),
                sweep.axis_label(), "peak drift ratio", {}};
      const auto along_y = [](const std::string &name) { // a 3D model's drifts along y
        const std::string suffix = "_peak_drift_ratio_y";
        return name.size() > suffix.size() &&
               name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
      };
      for (unsigned int c = 0; c < table.names.size(); ++c)
        if (c < table.n_storeys || along_y(table.names[c]))
          plot.series.push_back({"sweep.csv", "1:" + std::to_string(3 + c), table.names[c],
                                 "linespoints"});
      draw_plots(directory, {plot});
    }

    void
    write_sweep(const CommandRun &run, const SweepTable &table, const double wall_time,
                const bool interrupted, const bool model_built_once, const SweepTable &limit)
    {
      if (!run.memory)
        prepare_output_directory(run.directory);
      write_sweep_table(run, table);
      write_sweep_summary(run, table, wall_time, interrupted, model_built_once, limit);
      if (run.input->output.plots && !table.rows.empty() && !run.memory)
        draw_sweep_plot(run.directory, run.input->sweep, table);
    }

    /// Whether the sweep is the convergence of the penalty law's stiffness
    /// to rigid contact, the file's Contact/Model = nonsmooth.
    bool
    contact_convergence(const InputParameters &input)
    {
      return input.sweep.parameter == "Contact/Stiffness" &&
             input.time_integration.contact_model == ContactModel::nonsmooth;
    }

    /// The columns whose convergence is shown: the peak drifts and
    /// displacements, nonzero at the limit. Not the floor accelerations:
    /// the rigid model's are the smooth part, without the impulses, while a
    /// penalty law's contain its contact force, growing with the stiffness,
    /// so the two are not the same quantity and their difference no error.
    std::vector<unsigned int>
    converging_columns(const SweepTable &table, const std::vector<double> &rigid)
    {
      const auto ends_with = [](const std::string &name, const std::string &suffix) {
        return name.size() >= suffix.size() &&
               name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
      };
      std::vector<unsigned int> columns;
      for (unsigned int c = 0; c < table.names.size(); ++c)
        for (const char *suffix : {"drift_ratio", "peak_displacement_m"})
          if (ends_with(table.names[c], suffix) && rigid[c] != 0)
            {
              columns.push_back(c);
              break;
            }
      return columns;
    }

    /// rigid_limit.csv (rigid contact's row), contact_convergence.csv (per
    /// stiffness |x_k - x_rigid| / |x_rigid| of each converging column) and
    /// contact_convergence.png (the drifts' on log-log axes).
    void
    write_contact_convergence(const CommandRun &run, const SweepTable &table,
                              const SweepTable &limit)
    {
      const std::vector<double> &rigid = limit.rows.front();
      std::vector<std::string>   header{"completed"};
      header.insert(header.end(), limit.names.begin(), limit.names.end());
      const std::unique_ptr<TableWriter> limit_csv =
        result_table_writer(run.memory, run.directory, "rigid_limit", header);
      limit_csv->add_row(limit.completed.front() ? 1 : 0, rigid);
      limit_csv->commit();
      const std::vector<unsigned int> columns = converging_columns(table, rigid);
      header.assign(1, run.input->sweep.column_name());
      for (const unsigned int c : columns)
        header.push_back(table.names[c] + "_relative_error");
      const std::unique_ptr<TableWriter> csv =
        result_table_writer(run.memory, run.directory, "contact_convergence", header);
      for (std::size_t i = 0; i < table.rows.size(); ++i)
        {
          std::vector<double> row;
          for (const unsigned int c : columns)
            row.push_back(std::abs(table.rows[i][c] - rigid[c]) / std::abs(rigid[c]));
          csv->add_row(table.values[i], row);
        }
      csv->commit();
      if (!run.input->output.plots || run.memory || table.rows.empty())
        return;
      Plot plot{"contact_convergence.png", "peak drift ratios: penalty law against rigid contact",
                "contact stiffness", "relative difference from rigid contact", {}};
      plot.log_x = plot.log_y = true;
      for (unsigned int k = 0; k < columns.size(); ++k)
        if (table.names[columns[k]].find("drift_ratio") != std::string::npos)
          plot.series.push_back({"contact_convergence.csv", "1:" + std::to_string(2 + k),
                                 table.names[columns[k]], "linespoints"});
      draw_plots(run.directory, {plot});
    }

    /// Each value's run, in order, with a progress line on a terminal: on
    /// `model` with the value set, or (none) on each value's input.
    SweepTable
    run_values(const std::vector<InputParameters> &inputs, const Analysis &first_analysis,
               ModelRealization *model, const std::vector<double> &values)
    {
      SweepTable table;
      Progress   progress(std::cerr, "sweep: values", values.size());
      const InputParameters      &first      = inputs.front();
      const TimeHistoryParameters parameters = time_history_parameters(first);
      for (std::size_t i = 0; i < values.size() && !table.interrupted; ++i)
        {
          if (interruption_requested())
            table.interrupted = true;
          else if (model)
            {
              model->apply({values[i]});
              table.interrupted = !run_value(model->analysis(), parameters, first, first.sweep,
                                             values[i], table);
            }
          else if (i == 0)
            table.interrupted =
              !run_value(first_analysis, parameters, first, first.sweep, values[i], table);
          else
            table.interrupted = !run_value(prepare_analysis(inputs[i]),
                                           time_history_parameters(inputs[i]), inputs[i],
                                           first.sweep, values[i], table);
          progress.update(i + 1);
        }
      return table;
    }

    /// What was swept in how long, the files written and the critical
    /// values of the largest demands, on the terminal.
    void
    print_sweep_results(const CommandRun &run, const std::size_t n_values, const SweepTable &table,
                        const SweepTable &limit, const double wall_time)
    {
      const SweepParameters &sweep = run.input->sweep;
      run.out << "poundfe sweep: " << n_values << " values of " << sweep.parameter << " in "
              << wall_time << " s\nresults in " << run.results_place()
              << " (sweep.csv, summary.json" << (run.memory ? "" : ", sweep.png")
              << (limit.rows.empty() ? "" : ", rigid_limit.csv, contact_convergence.csv") << ")\n";
      for (const Critical &c : critical_values(table)) // the largest demands
        if (c.name == "max_drift_ratio" ||
            c.name.find("_max_corner_drift_ratio") != std::string::npos)
          run.out << "critical " << sweep.parameter << " for " << c.name << ": " << c.value
                  << " (peak " << c.peak << ")\n";
    }
  } // namespace

} // namespace poundfe

namespace poundfe::commands
{
  int
  sweep(const CommandRun &run)
  {
    const InputParameters &input = *run.input;
    const SweepParameters &sweep = input.sweep;
    dealii::TimerOutput timer(run.out, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);

    timer.enter_subsection("read");
    sweep.require(input);
    const std::vector<double> values = sweep.values();
    // all read and checked first: bad input writes nothing; the swept
    // stiffnesses of a convergence to rigid contact are the penalty law's
    const bool convergence = contact_convergence(input);
    const std::vector<ParameterOverride> penalty =
      convergence ? std::vector<ParameterOverride>{{"Contact/Model", "penalty"}} :
                    std::vector<ParameterOverride>{};
    std::vector<InputParameters> inputs{sweep_input(sweep, input, values.front(), penalty)};
    const Analysis first_analysis = prepare_analysis(inputs.front());
    const std::unique_ptr<ModelRealization> model =
      built_once(inputs.front(), first_analysis, values);
    for (std::size_t i = 1; i < values.size() && !model; ++i)
      inputs.push_back(sweep_input(sweep, input, values[i], penalty));
    const std::unique_ptr<const Analysis> rigid =
      convergence ? std::make_unique<const Analysis>(prepare_rigid_limit_analysis(input)) :
                    nullptr;
    timer.leave_subsection();

    timer.enter_subsection("runs");
    SweepTable table = run_values(inputs, first_analysis, model.get(), values);
    SweepTable limit; // rigid contact's row
    if (rigid && !table.interrupted)
      table.interrupted = !run_value(*rigid, time_history_parameters(input), input, sweep,
                                     std::numeric_limits<double>::infinity(), limit);
    timer.leave_subsection();
    const double wall_time =
      timer.get_summary_data(dealii::TimerOutput::total_wall_time).at("runs");

    timer.enter_subsection("output");
    write_sweep(run, table, wall_time, table.interrupted, model != nullptr, limit);
    if (!limit.rows.empty())
      write_contact_convergence(run, table, limit);
    timer.leave_subsection();
    if (table.interrupted)
      {
        run.err << "poundfe: sweep interrupted ("
                << (run.memory ? "the summary" : run.directory + "/summary.json")
                << " says interrupted): " << table.values.size() << " of "
                << values.size() << " values kept in sweep.csv\n";
        return interrupted_exit_status();
      }

    const auto n_failed = std::count(table.completed.begin(), table.completed.end(), false);
    print_sweep_results(run, values.size(), table, limit, wall_time);
    print_timing(timer);
    if (n_failed > 0)
      {
        run.err << "poundfe: numerical failure at " << n_failed
                << " values (completed = 0 in sweep.csv)\n";
        return 2;
      }
    return 0;
  }
} // namespace poundfe::commands
