// `poundfe mitigation`: the bare pair against viscous dampers of each size
// and against bumpers, on the same realizations of the ground motion
// (separation/mitigation.h), over the MPI ranks.
//   read:   the file; the cases' inputs (Links/Viscous dampers and Bumpers
//           replaced by the Mitigation section's), each model built and
//           checked before any run
//   runs:   run_realizations of the study's job (realizations.csv, resumed)
//   output: mitigation.csv (one row per case), summary.json, mitigation.png
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/base/numbers.h>
#include <poundfe/base/progress.h>
#include <poundfe/commands/command.h>
#include <poundfe/excitation/ground_motion.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/output/append_file.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/plots.h>
#include <poundfe/separation/mitigation.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <iostream>
#include <iterator>
#include <list>

namespace poundfe::commands
{
  namespace
  {
    /// The input of one model of the study: the file's, with the study's
    /// dampers (`dampers`, possibly none) in place of its viscous dampers,
    /// `bumper` in its gaps and, when not `contact`, no contact at all.
    InputParameters
    case_input(const InputParameters &file, const std::vector<std::string> &dampers,
               const BumperParameters &bumper, const bool contact)
    {
      InputParameters input         = file;
      input.contact.links.viscous   = dampers;
      input.contact.bumpers.bumper  = bumper;
      if (!contact) // the bare pair: the file's Contact entries do not act (no warning)
        {
          input.contact.law = "none", input.contact.bumpers.bumper = {};
          for (auto line = input.lines.begin(); line != input.lines.end();)
            line = line->first.rfind("Contact/", 0) == 0 ? input.lines.erase(line) : std::next(line);
        }
      return input;
    }

    /// prepare_analysis of a case's input; its bad input is the Mitigation
    /// entry `path`'s (the file does not say Links or Bumpers for it).
    Analysis
    prepare_case(const InputParameters &input, const std::string &path, const std::string &what)
    {
      try
        {
          return prepare_analysis(input);
        }
      catch (const InputError &e)
        {
          throw InputError(input.file, input.line_of(path), path, what + ": " + e.problem());
        }
    }

    /// Every model of the study, built (and so checked) before any run.
    struct StudyAnalyses
    {
      std::list<Analysis> analyses; // stable addresses
      MitigationModels    models;

      explicit StudyAnalyses(const InputParameters &file)
      {
        const MitigationParameters &m = file.mitigation;
        const auto add = [this](const InputParameters &input, const std::string &path,
                                const std::string &what) {
          analyses.push_back(prepare_case(input, path, what));
          return &analyses.back();
        };
        models.bare      = add(case_input(file, {}, {}, true), "Model/Separations", "the bare pair");
        models.bare_free = add(case_input(file, {}, {}, false), "Model/Separations", "the bare pair");
        if (!m.damper_coefficients.empty())
          {
            // any c > 0 builds the dampers' places: each case writes its own c
            const std::vector<std::string> dampers = m.damper_entries(1.0);
            const std::string path = "Mitigation/Damper locations";
            const std::string what = "the dampers (each entry with a c and alpha appended)";
            models.damped      = add(case_input(file, dampers, {}, true), path, what);
            models.damped_free = add(case_input(file, dampers, {}, false), path, what);
          }
        for (unsigned int k = 0; k < m.bumper_thicknesses.size(); ++k)
          models.bumpered.push_back(add(case_input(file, {}, m.bumper(k), true),
                                        "Mitigation/Bumper thicknesses",
                                        "bumper " + std::to_string(k + 1)));
      }
    };

    /// mitigation.csv: one row per case.
    void
    write_table(const CommandRun &run, const std::vector<std::string> &buildings,
                const std::vector<MitigationRow> &rows, const double exponent)
    {
      std::string text = "case,label,number,kind,damper_coefficient,damper_exponent,"
                         "bumper_thickness_m,bumper_stiffness,realizations";
      for (const std::string &b : buildings)
        text += ",peak_drift_ratio_" + b;
      text += ",max_drift_ratio,peak_floor_acc_m_s2,n_impacts,peak_impact_force_N,"
              "max_impact_force_N,p_pounding,required_gap_m,required_gap_target_m\n";
      const char *kinds[] = {"bare", "damper", "bumper"};
      for (std::size_t i = 0; i < rows.size(); ++i)
        {
          const MitigationRow  &r = rows[i];
          const MitigationCase &c = r.study_case;
          const bool damper = c.kind == MitigationCase::Kind::damper;
          const std::string label =
            damper ? "c=" + number_text(c.damper_coefficient) :
            c.kind == MitigationCase::Kind::bumper ? "t=" + number_text(c.bumper.thickness) + " m" :
                                                    "bare";
          text += c.name + "," + label + "," + std::to_string(i + 1) + "," + kinds[int(c.kind)];
          std::vector<double> x{damper ? c.damper_coefficient : 0, damper ? exponent : 0,
                                c.bumper.thickness, c.bumper.stiffness,
                                double(r.n_realizations)};
          x.insert(x.end(), r.peak_drift_ratio.begin(), r.peak_drift_ratio.end());
          for (const double v : {r.max_drift_ratio, r.peak_floor_acceleration, r.n_impacts,
                                 r.peak_impact_force, r.max_impact_force, r.pounding_probability,
                                 r.required_gap, r.required_gap_at_target})
            x.push_back(v);
          for (const double v : x)
            text += ',', append_number(text, v);
          text += '\n';
        }
      write_result_text(run.memory, run.directory, "mitigation.csv", text);
    }

    void
    write_summary(const CommandRun &run, const InputParameters &input,
                  const std::vector<std::string> &buildings, const std::vector<MitigationRow> &rows,
                  const MonteCarloTable &table, const bool random)
    {
      JsonWriter json;
      begin_summary(json, "mitigation", input, table.interrupted ? "interrupted" : "completed");
      json.value("ground_motion", random ? "random" : "deterministic")
        .value("realizations", table.realizations.size())
        .value("wall_time_s", table.wall_time)
        .value("target_probability", input.separation.target_probability)
        .value("damper_exponent", input.mitigation.damper_exponent)
        .value("buildings", buildings)
        .begin_array("mitigation");
      for (const MitigationRow &r : rows)
        {
          const MitigationCase &c = r.study_case;
          json.begin_object().value("case", c.name);
          if (c.kind == MitigationCase::Kind::damper)
            json.value("kind", "damper").value("damper_coefficient", c.damper_coefficient);
          else if (c.kind == MitigationCase::Kind::bumper)
            json.value("kind", "bumper")
              .value("bumper_thickness_m", c.bumper.thickness)
              .value("bumper_stiffness", c.bumper.stiffness);
          else
            json.value("kind", "bare");
          json.value("realizations", r.n_realizations)
            .value("peak_drift_ratio", r.peak_drift_ratio)
            .value("max_drift_ratio", r.max_drift_ratio)
            .value("peak_floor_acc_m_s2", r.peak_floor_acceleration)
            .value("n_impacts", r.n_impacts)
            .value("peak_impact_force_N", r.peak_impact_force)
            .value("max_impact_force_N", r.max_impact_force)
            .value("p_pounding", r.pounding_probability)
            .value("required_gap_m", r.required_gap)
            .value("required_gap_target_m", r.required_gap_at_target)
            .end_object();
        }
      json.end_array().end_object();
      write_result_text(run.memory, run.directory, "summary.json", json.str());
    }

    /// mitigation.png: drifts, pounding and the required gap against the case.
    Plot
    mitigation_plot(const std::vector<std::string> &buildings)
    {
      const std::string csv = "mitigation.csv", xtics = "set xtics rotate by -30\n";
      std::string pair; // "A and B"
      for (std::size_t b = 0; b < buildings.size(); ++b)
        pair += (b == 0 ? "" : b + 1 == buildings.size() ? " and " : ", ") + buildings[b];
      Plot drift{"mitigation.png",
                 "Mitigation of the pounding of " + pair + ": the bare pair, dampers and bumpers",
                 "", "mean peak drift ratio", {}};
      for (std::size_t b = 0; b < buildings.size(); ++b)
        drift.series.push_back({csv, "3:" + std::to_string(10 + b) + ":xtic(2)", buildings[b],
                                "linespoints pt 7"});
      drift.settings = xtics + "set offsets 0.3, 0.3, 0, 0\n";
      // mitigation.csv's columns (1-based) after the drifts: max drift, floor
      // acceleration, impacts, peak and max impact force, P(pounding), gaps;
      // in SI, drawn in kN, mm and g
      const std::size_t after = 10 + buildings.size();
      const auto column = [&](const std::size_t k, const std::string &in_unit = "") {
        const std::string c = std::to_string(after + k);
        return "3:" + (in_unit.empty() ? c : "($" + c + in_unit + ")") + ":xtic(2)";
      };
      Plot pounding{"", "", "", "P(pounding)",
                    {{csv, column(5), "P(pounding)", "linespoints pt 7"},
                     {csv, column(3, "/1000"), "mean peak impact force (kN)", "linespoints pt 5",
                      "x1y2"}}};
      pounding.y2_label = "impact force (kN)";
      pounding.settings = drift.settings + "set yrange [-0.02:1.05]\n";
      Plot gap{"", "", "case", "required gap (mm)",
               {{csv, column(6, "*1000"), "mean largest approach without contact (+ bumper)",
                 "linespoints pt 7"},
                {csv, column(1, "/" + number_text(standard_gravity)),
                 "mean peak floor acceleration (g)", "linespoints pt 5", "x1y2"}}};
      gap.y2_label = "floor acceleration (g)";
      gap.settings = drift.settings;
      drift.below  = {pounding, gap};
      return drift;
    }

    void
    report(const dealii::ConditionalOStream &out, const std::vector<MitigationRow> &rows,
           const MonteCarloTable &table, const unsigned long n, const std::string &place,
           const bool plots)
    {
      if (table.interrupted)
        out << "mitigation interrupted after " << table.realizations.size() << " of " << n
            << " realizations: the results are over these; the same command runs the rest\n";
      out << "poundfe mitigation: " << rows.size() << " cases on " << table.realizations.size()
          << " realization" << (table.realizations.size() == 1 ? "" : "s") << "\n"
          << "case       max drift   P(pounding)  impacts  peak force (N)  required gap (m)\n";
      for (const MitigationRow &r : rows)
        out << r.study_case.name << std::string(11 - std::min<std::size_t>(10, r.study_case.name.size()), ' ')
            << rounded(r.max_drift_ratio) << "    " << rounded(r.pounding_probability) << "    "
            << rounded(r.n_impacts) << "    " << rounded(r.peak_impact_force) << "    "
            << rounded(r.required_gap) << "\n";
      out << "results in " << place << " (mitigation.csv, summary.json, realizations.csv"
          << (plots ? ", mitigation.png" : "") << ")\n";
    }
  } // namespace

  int
  mitigation(const CommandRun &run)
  {
    const InputParameters     &input = *run.input;
    const MPI_Comm             comm  = run.communicator;
    const unsigned int         rank  = dealii::Utilities::MPI::this_mpi_process(comm);
    dealii::ConditionalOStream pcout(run.out, rank == 0);
    dealii::TimerOutput timer(pcout, dealii::TimerOutput::never, dealii::TimerOutput::wall_times);

    timer.enter_subsection("set-up");
    input.mitigation.require(input);
    const bool random =
      input.ground_motion.is_stochastic() || !input.nodal_forces.white_noise.empty();
    const StudyAnalyses study_analyses(input);
    MitigationStudy     study(study_analyses.models, time_history_parameters(input),
                              input.mitigation, input.modal.eigensolver, random);
    if (rank == 0 && !run.memory) // an earlier run's realizations stay: it resumes from them
      prepare_output_directory(run.directory, {"realizations.csv"});
    timer.leave_subsection();

    timer.enter_subsection("realizations");
    const unsigned long   n = random ? input.monte_carlo.realizations : 1;
    Progress              progress(std::cerr, "mitigation: realizations", n);
    const MonteCarloTable table = run_realizations(
      study.job(), n, run.memory ? "" : run.directory + "/realizations.csv", comm, "", &progress);
    progress.finish();
    timer.leave_subsection();
    const int status = table.interrupted ? interrupted_exit_status() : 0;
    if (rank != 0)
      return status;
    if (table.completed_values(0).empty())
      {
        if (table.interrupted) // stopped before the first: the guard's summary says so
          throw Interrupted();
        throw NumericalError("no realization completed (see realizations.csv)");
      }

    timer.enter_subsection("output");
    const std::vector<MitigationRow> rows =
      study.rows(table, input.separation.target_probability);
    write_table(run, study.building_names(), rows, input.mitigation.damper_exponent);
    const bool plots = input.output.plots && !table.interrupted && !run.memory;
    if (plots)
      draw_plots(run.directory, {mitigation_plot(study.building_names())});
    if (run.memory) // the journal's rows, which a run into files appended as they came
      write_result_text(run.memory, run.directory, "realizations.csv", realizations_text(table));
    write_summary(run, input, study.building_names(), rows, table, random);
    timer.leave_subsection();

    report(pcout, rows, table, n, run.results_place(), plots);
    print_timing(timer);
    return status;
  }
} // namespace poundfe::commands
