// Parameter sweeps (input/sweep.h): the values of a Sweep-like section,
// one checked input per value (read_parameters with an override), and the
// `sweep` command, which runs each value's time history with the peak
// observer only and tabulates the run's scalars against the value.
#include <poundfe/input/input_parameters.h>
#include <poundfe/dynamics/run.h>
#include <poundfe/input/sweep.h>
#include <poundfe/base/interruption.h>
#include <poundfe/base/choices.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/base/progress.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/csv_writer.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/peak_response.h>
#include <poundfe/output/plots.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>

namespace poundfe
{
  namespace
  {
    /// A finite number, the whole of `text` (blanks around allowed).
    bool
    read_number(const std::string &text, double &x)
    {
      const std::optional<double> value = parse_number(text);
      if (value)
        x = *value;
      return value.has_value();
    }

    /// The values of `text`; on a syntax error an empty list and `error` says why.
    std::vector<double>
    parse_values(const std::string &text, std::string &error)
    {
      std::istringstream words(text);
      std::string        first;
      words >> first;
      std::vector<double> values;
      if (first == "linspace")
        {
          std::string a_text, b_text, n_text, extra;
          double      a = 0, b = 0, n = 0;
          if (!(words >> a_text >> b_text >> n_text) || (words >> extra) ||
              !read_number(a_text, a) || !read_number(b_text, b) || !read_number(n_text, n) ||
              n < 1 || n > 100000 || n != std::floor(n) || (n == 1 && a != b))
            {
              error = "expected 'linspace a b n' with n a whole number in 1..100000 "
                      "(n = 1 needs a = b), got '" + text + "'";
              return {};
            }
          for (unsigned int i = 0; i < n; ++i) // to 15 digits: 0.775, not 0.7749999999999999
            {
              char buffer[32];
              std::snprintf(buffer, sizeof(buffer), "%.15g", n == 1 ? a : a + (b - a) * i / (n - 1));
              values.push_back(std::stod(buffer));
            }
          return values;
        }
      std::istringstream items(text);
      for (std::string item; std::getline(items, item, ',');)
        {
          double x = 0;
          if (!read_number(item, x))
            {
              error = "expected numbers 'v1, v2, ...' or 'linspace a b n', got '" + item + "'";
              return {};
            }
          values.push_back(x);
        }
      if (values.empty())
        error = "no values";
      return values;
    }
  } // namespace

  std::string
  format_value(const double value)
  {
    return number_text(value);
  }

  void
  SweepParameters::declare_entries(dealii::ParameterHandler &prm)
  {
    prm.add_parameter("Parameter", parameter,
                      "The swept parameter: 'Section/.../Entry' (a numeric entry, e.g. "
                      "Model/Separations) or 'Section/.../Entry:k', field k (1-based) of the "
                      "first ';'-separated item of a list entry (e.g. Nodal forces/Harmonic:6, "
                      "the forcing frequency). Unit: -.");
    prm.add_parameter("Values", values_text,
                      "The values: 'v1, v2, ...' or 'linspace a b n' (n values from a to b). "
                      "Unit: that of Parameter.");
    prm.add_parameter("Label", label,
                      "The parameter's name on the plots' axes, e.g. 'forcing amplitude f (N)' "
                      "(empty: its path). Unit: -.");
  }

  void
  SweepParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Sweep");
    declare_entries(prm);
    add_choice(prm, "Command", command,
               "`poundfe sweep`: the command whose model runs at each value (its "
               "time history; run is the one so far). Unit: -.",
               {"run"});
    prm.leave_subsection();
  }

  void
  SweepParameters::check(const InputFile &input) const
  {
    if (values_text.find_first_not_of(" \t") == std::string::npos)
      return;
    std::string               error;
    const std::vector<double> values = parse_values(values_text, error);
    if (!error.empty())
      input.fail(section + "/Values", error);
    input.distinct(section + "/Values", values); // a value twice: the same run twice
  }

  void
  SweepParameters::require(const InputFile &input) const
  {
    if (parameter.find_first_not_of(" \t") == std::string::npos)
      input.fail(section + "/Parameter", "names no parameter to sweep");
    if (values().empty())
      input.fail(section + "/Values", "gives no values to sweep");
  }

  std::vector<double>
  SweepParameters::values() const
  {
    std::string error;
    return values_text.find_first_not_of(" \t") == std::string::npos ?
             std::vector<double>() :
             parse_values(values_text, error);
  }

  InputParameters
  SweepParameters::input_for(const std::string &file, const double value) const
  {
    return input_for(file, value, {});
  }

  InputParameters
  SweepParameters::input_for(const std::string &file, const double value,
                             const std::vector<ParameterOverride> &more) const
  {
    InputParameters input;
    input.file = file;
    return input_for(input, value, more);
  }

  InputParameters
  SweepParameters::input_for(const InputParameters &input, const double value,
                             const std::vector<ParameterOverride> &more) const
  {
    std::vector<ParameterOverride> overrides = input.overrides;
    overrides.push_back({parameter, format_value(value)});
    overrides.insert(overrides.end(), more.begin(), more.end());
    try
      {
        return read_parameters(input.file, overrides);
      }
    catch (const InputError &e) // say which value of the sweep it was
      {
        throw InputError(e.file(), e.line(), e.parameter(),
                         "at " + section + " value " + parameter + " = " + format_value(value) +
                           ": " + e.problem());
      }
  }

  std::string
  SweepParameters::axis_label() const
  {
    return label.empty() ? parameter : label;
  }

  std::string
  SweepParameters::column_name() const
  {
    std::string name;
    for (const char c : parameter)
      name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    return name;
  }

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
      row.push_back(*std::max_element(floors.peak_drift_ratio().begin(),
                                      floors.peak_drift_ratio().end()));
      if (!analysis.model.gaps.empty())
        {
          double peak_force = 0;
          for (const Impact &impact : state.impact_log().impacts())
            peak_force = std::max(peak_force, impact.peak_force);
          row.push_back(state.impact_log().impacts().size());
          row.push_back(peak_force);
          row.push_back(peaks.min_clearance());
        }
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
    };

    /// One run of the value's input with the peak observer; its row in `table`.
    /// Runs one value and adds its row; false (no row) when a signal
    /// stopped the run.
    bool
    run_value(const InputParameters &input, const double value, SweepTable &table)
    {
      const Analysis     analysis = prepare_analysis(input);
      const Excitation   excitation = make_excitation(analysis);
      TimeHistory        history(analysis);
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
        input.fail(input.sweep.section + "/Parameter",
                   "changes the model's floors or gaps at " + format_value(value) +
                     ": every value needs the same table columns");
      table.values.push_back(value);
      table.completed.push_back(status.completed());
      table.rows.push_back(scalars(analysis, peaks, history.state()));
      return true;
    }

    void
    write_sweep(const InputParameters &input, const SweepTable &table,
                const std::string &directory, const double wall_time, const bool interrupted)
    {
      const SweepParameters &sweep = input.sweep;
      prepare_output_directory(directory);
      std::vector<std::string> header{sweep.column_name(), "completed"};
      header.insert(header.end(), table.names.begin(), table.names.end());
      CsvWriter csv(directory + "/sweep.csv", header);
      for (std::size_t i = 0; i < table.rows.size(); ++i)
        {
          csv.begin_row(table.values[i]);
          csv.add(table.completed[i] ? 1 : 0);
          for (const double x : table.rows[i])
            csv.add(x);
          csv.end_row();
        }
      csv.commit();

      JsonWriter json;
      const bool all = std::all_of(table.completed.begin(), table.completed.end(),
                                   [](const bool c) { return c; });
      begin_summary(json, "sweep", input, interrupted ? "interrupted" : all ? "completed" : "failed");
      json.value("parameter", sweep.parameter).value("command_swept", sweep.command)
        .value("n_values", table.values.size()).value("wall_time_s", wall_time)
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
      json.end_object().end_object();
      write_file_atomically(directory + "/summary.json", json.str());

      if (!input.output.plots || table.rows.empty())
        return;
      Plot plot{"sweep.png", "peak inter-storey drift ratio against " + sweep.axis_label(),
                sweep.axis_label(), "peak drift ratio", {}};
      for (unsigned int s = 0; s < table.n_storeys; ++s)
        plot.series.push_back({"sweep.csv", "1:" + std::to_string(3 + s), table.names[s],
                               "linespoints"});
      draw_plots(directory, {plot});
    }
  } // namespace

  int
  sweep_command(const InputParameters &input, const std::string &directory)
  {
    const SweepParameters &sweep = input.sweep;
    sweep.require(input);
    const std::vector<double> values = sweep.values();
    std::vector<InputParameters> inputs; // all read first: bad input writes nothing
    for (const double value : values)
      inputs.push_back(sweep.input_for(input, value));

    const auto start = std::chrono::steady_clock::now();
    SweepTable table;
    bool       interrupted = false; // SIGINT/SIGTERM: the values finished are the result
    {
      Progress progress(std::cerr, "sweep: values", values.size());
      for (std::size_t i = 0; i < values.size() && !interrupted; ++i)
        {
          interrupted = interruption_requested() || !run_value(inputs[i], values[i], table);
          progress.update(i + 1);
        }
    }
    const double wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    write_sweep(input, table, directory, wall_time, interrupted);
    if (interrupted)
      {
        std::cerr << "poundfe: sweep interrupted (" << directory
                  << "/summary.json says interrupted): " << table.values.size() << " of "
                  << values.size() << " values kept in sweep.csv\n";
        return interrupted_exit_status();
      }
    const auto n_failed = std::count(table.completed.begin(), table.completed.end(), false);
    std::cout << "poundfe sweep: " << values.size() << " values of " << sweep.parameter << " in "
              << wall_time << " s\nresults in " << directory
              << "/ (sweep.csv, summary.json, sweep.png)\n";
    if (n_failed > 0)
      {
        std::cerr << "poundfe: numerical failure at " << n_failed
                  << " values (completed = 0 in sweep.csv)\n";
        return 2;
      }
    return 0;
  }
} // namespace poundfe
