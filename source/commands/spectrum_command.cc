// `poundfe spectrum`: the response spectrum and intensity measures of the
// input's ground motion; with --realizations N, the ensemble mean spectrum
// (reliability/ensemble_spectrum.h) against the Spectrum section's target
// and the S0 that matches it.
#include <poundfe/commands/command.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/reliability/ensemble_spectrum.h>
#include <poundfe/excitation/excitation.h>
#include <poundfe/excitation/response_spectrum.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/csv_writer.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/plots.h>

#include <cmath>
#include <ostream>
#include <sstream>
#include <tuple>
#include <utility>

namespace poundfe
{
  namespace
  {
    std::string
    percent(const double zeta)
    {
      std::ostringstream text;
      text << 100 * zeta << " %";
      return text.str();
    }

    void
    write_intensity(JsonWriter &json, const GroundMotionIntensity &m)
    {
      json.begin_object("intensity")
        .value("pga_m_s2", m.pga)
        .value("pga_g", m.pga / standard_gravity)
        .value("pgv_m_s", m.pgv)
        .value("pgd_m", m.pgd)
        .value("baseline_correction", "none")
        .value("arias_intensity_m_s", m.arias_intensity)
        .value("cumulative_absolute_velocity_m_s", m.cumulative_absolute_velocity)
        .value("t5_s", m.t5)
        .value("t75_s", m.t75)
        .value("t95_s", m.t95)
        .value("significant_duration_5_75_s", m.significant_duration_5_75)
        .value("significant_duration_5_95_s", m.significant_duration)
        .value("duration_s", m.duration)
        .end_object();
    }

    void
    write_target(JsonWriter &json, const SpectrumParameters &s)
    {
      json.begin_object("target").value("type", design_spectrum_names().name(s.target));
      if (s.target != DesignSpectrum::none)
        {
          const Ec8GroundParameters p = ec8_ground_parameters(s.target, s.ground_type);
          json.value("ground_type", ground_type_names().name(s.ground_type))
            .value("ag_g", s.design_ground_acceleration)
            .value("S", p.S)
            .value("TB_s", p.TB)
            .value("TC_s", p.TC)
            .value("TD_s", p.TD)
            .value("eta", ec8_damping_correction(s.damping_ratios.front()));
        }
      json.end_object();
    }

    /// PSA (and the target) against the period, log period axis.
    Plot
    spectrum_plot(const std::string &file, const std::string &title,
                  std::vector<PlotSeries> series)
    {
      Plot plot{file, title, "period (s)", "pseudo-acceleration PSA (m/s^2)", std::move(series)};
      plot.log_x = true;
      plot.key   = "below"; // the curves fill the frame
      return plot;
    }

    /// "target ec8-type-1, ground C, 5 %": a target's legend.
    std::string
    target_title(const SpectrumParameters &s)
    {
      return "target " + design_spectrum_names().name(s.target) + ", ground " +
             ground_type_names().name(s.ground_type) + ", " + percent(s.damping_ratios.front());
    }

    /// spectrum.csv: per damping ratio Sd, Sv, PSV, PSA (m/s^2 and g), Sa
    /// and the target.
    void
    write_spectrum_csv(const CommandRun &run, const ResponseSpectrum &spectrum,
                       const SpectrumParameters &s)
    {
      const bool               target = s.target != DesignSpectrum::none;
      std::vector<std::string> header{"period_s"};
      for (const double zeta : s.damping_ratios)
        {
          const std::string z = damping_label(zeta);
          for (const char *name : {"sd_m_", "sv_m_s_", "psv_m_s_", "psa_m_s2_", "psa_g_",
                                   "sa_abs_m_s2_"})
            header.push_back(name + z);
          if (target)
            header.push_back("target_psa_m_s2_" + z);
        }
      const std::unique_ptr<TableWriter> csv =
        result_table_writer(run.memory, run.directory, "spectrum", header);
      std::vector<double> row;
      for (unsigned int i = 0; i < spectrum.n_periods(); ++i)
        {
          row.clear();
          for (unsigned int d = 0; d < s.damping_ratios.size(); ++d)
            {
              const unsigned int k = d * spectrum.n_periods() + i;
              row.push_back(spectrum.sd(d, i));
              row.push_back(spectrum.relative_velocity[k]);
              row.push_back(spectrum.psv(d, i));
              row.push_back(spectrum.psa(d, i));
              row.push_back(spectrum.psa(d, i) / standard_gravity);
              row.push_back(spectrum.absolute_acceleration[k]);
              if (target)
                row.push_back(s.target_psa(s.damping_ratios[d], spectrum.periods[i]));
            }
          csv->add_row(spectrum.periods[i], row);
        }
      csv->commit();
    }

    /// spectrum.png from spectrum.csv: PSA of every damping ratio, the target.
    std::vector<std::string>
    draw_spectrum(const std::string &directory, const std::string &description,
                  const SpectrumParameters &s)
    {
      const bool              target      = s.target != DesignSpectrum::none;
      const unsigned int      per_damping = 6 + target; // columns of spectrum.csv
      std::vector<PlotSeries> series;
      for (unsigned int d = 0; d < s.damping_ratios.size(); ++d)
        series.push_back({"spectrum.csv", "1:" + std::to_string(2 + d * per_damping + 3),
                          "PSA, " + percent(s.damping_ratios[d]), "lines lw 2"});
      if (target)
        series.push_back({"spectrum.csv", "1:" + std::to_string(1 + per_damping), target_title(s),
                          "lines dt 2 lw 2 lc rgb 'black'"});
      return draw_plots(directory, {spectrum_plot("spectrum.png",
                                                  "Elastic response spectrum: " + description,
                                                  series)});
    }

    /// One motion: spectrum.csv, spectrum.png, summary.json.
    int
    single_spectrum(const CommandRun &run)
    {
      const InputParameters &input     = *run.input;
      const std::string     &directory = run.directory;
      std::ostream          &out       = run.out;
      const GroundMotion motion =
        make_ground_motion(input.ground_motion, input, input.time_integration.newmark.time_step);
      if (motion.empty())
        input.fail("Ground motion/Type", "there is no ground motion (type none) to analyse");
      const SpectrumParameters   &s         = input.spectrum;
      const ResponseSpectrum      spectrum  = response_spectrum(motion, s.periods(), s.damping_ratios);
      const GroundMotionIntensity intensity = ground_motion_intensity(motion);
      unsigned int                peak      = 0; // the period of the largest PSA (first damping)
      for (unsigned int i = 1; i < spectrum.n_periods(); ++i)
        if (spectrum.psa(0, i) > spectrum.psa(0, peak))
          peak = i;

      if (!run.memory)
        create_directories(directory);
      write_spectrum_csv(run, spectrum, s);
      std::vector<std::string> files{"spectrum.csv"};
      if (input.output.plots && !run.memory)
        for (const std::string &png : draw_spectrum(directory, motion.description(), s))
          files.push_back(png);
      files.push_back("summary.json");

      JsonWriter json;
      begin_summary(json, "spectrum", input);
      json.begin_object("ground_motion")
        .value("description", motion.description())
        .value("time_step_s", motion.time_step())
        .value("samples", static_cast<unsigned long>(motion.samples().size()))
        .value("held", motion.is_held())
        .end_object();
      write_intensity(json, intensity);
      json.begin_object("spectrum")
        .value("method", "Nigam-Jennings exact recursion, piecewise-linear excitation")
        .value("damping_ratios", s.damping_ratios)
        .value("min_period_s", spectrum.periods.front())
        .value("max_period_s", spectrum.periods.back())
        .value("periods", spectrum.n_periods())
        .value("peak_psa_m_s2", spectrum.psa(0, peak))
        .value("period_of_peak_psa_s", spectrum.periods[peak])
        .end_object();
      write_target(json, s);
      json.value("files", files).end_object();
      write_result_text(run.memory, directory, "summary.json", json.str());

      out << motion.description() << ": PGA " << intensity.pga << " m/s^2 ("
          << intensity.pga / standard_gravity << " g), PGV " << intensity.pgv
          << " m/s, PGD " << intensity.pgd << " m (no baseline correction)\n"
          << "Arias intensity " << intensity.arias_intensity << " m/s, D5-95 "
          << intensity.significant_duration << " s (" << intensity.t5 << " to "
          << intensity.t95 << " s)\n"
          << "peak PSA (" << percent(s.damping_ratios.front()) << ") "
          << spectrum.psa(0, peak) << " m/s^2 at T = " << spectrum.periods[peak] << " s\n"
          << "results in " << run.results_place() << " (spectrum.csv, summary.json)\n";
      return 0;
    }

    /// The period at which the ensemble is matched, and where it came from.
    std::pair<double, std::string>
    matching_period(const InputParameters &input)
    {
      if (input.spectrum.matching_period > 0)
        return {input.spectrum.matching_period, "Spectrum/SpectrumMatching period"};
      const Analysis analysis = prepare_analysis(input);
      if (analysis.modes.n_modes() == 0)
        input.fail("Spectrum/SpectrumMatching period",
                   "is 0 (the model's first period) but the model has no modes "
                   "(Output/Number of modes = 0): give the period");
      return {analysis.modes.period(0), "first mode of the model"};
    }

    /// ensemble_spectrum.csv: per damping ratio the mean, std, mean -+ std
    /// and the target; the matched mean (first damping ratio).
    void
    write_ensemble_csv(const CommandRun &run, const EnsembleSpectrum &ensemble,
                       const SpectrumParameters &s, const SpectrumMatching *matching)
    {
      std::vector<std::string> header{"period_s"};
      for (const double z : s.damping_ratios)
        {
          const std::string label = damping_label(z);
          for (const char *name : {"mean_psa_m_s2_", "std_psa_m_s2_", "mean_minus_std_m_s2_",
                                   "mean_plus_std_m_s2_"})
            header.push_back(name + label);
          if (matching)
            header.push_back("target_psa_m_s2_" + label);
        }
      if (matching)
        header.push_back("matched_mean_psa_m_s2_" + damping_label(s.damping_ratios.front()));
      const std::unique_ptr<TableWriter> csv =
        result_table_writer(run.memory, run.directory, "ensemble_spectrum", header);
      std::vector<double> row;
      for (unsigned int i = 0; i < ensemble.n_grid; ++i)
        {
          row.clear();
          for (unsigned int d = 0; d < s.damping_ratios.size(); ++d)
            {
              const SampleStatistics &st = ensemble.at(d, i);
              row.push_back(st.mean);
              row.push_back(st.standard_deviation);
              row.push_back(st.mean - st.standard_deviation);
              row.push_back(st.mean + st.standard_deviation);
              if (matching)
                row.push_back(s.target_psa(s.damping_ratios[d], ensemble.periods[i]));
            }
          if (matching)
            row.push_back(std::sqrt(matching->s0_factor) * ensemble.at(0, i).mean);
          csv->add_row(ensemble.periods[i], row);
        }
      csv->commit();
    }

    /// ensemble_spectrum.png from ensemble_spectrum.csv (first damping ratio).
    std::vector<std::string>
    draw_ensemble(const std::string &directory, const std::string &title,
                  const SpectrumParameters &s, const SpectrumMatching *matching)
    {
      const std::string       file = "ensemble_spectrum.csv";
      const std::string       z    = percent(s.damping_ratios.front());
      std::vector<PlotSeries> series{{file, "1:2", "mean PSA, " + z, "lines lw 2 lc rgb 'blue'"},
                                     {file, "1:4", "mean - 1 std", "lines dt 3 lc rgb 'blue'"},
                                     {file, "1:5", "mean + 1 std", "lines dt 3 lc rgb 'blue'"}};
      if (matching)
        {
          const unsigned int last = 1 + 5 * s.damping_ratios.size() + 1; // matched mean
          std::ostringstream matched;
          matched << "mean with S0 x " << matching->s0_factor << " (matched at T = "
                  << matching->period << " s)";
          series.push_back({file, "1:6", target_title(s), "lines dt 2 lw 2 lc rgb 'black'"});
          series.push_back({file, "1:" + std::to_string(last), matched.str(),
                            "lines lw 2 lc rgb 'red'"});
        }
      return draw_plots(directory, {spectrum_plot("ensemble_spectrum.png", title, series)});
    }

    void
    write_matching(JsonWriter &json, const SpectrumMatching &m, const GroundMotionParameters &g,
                   const double s0)
    {
      json.begin_object("matching")
        .value("period_s", m.period)
        .value("period_source", m.source)
        .value("damping_ratio", m.damping_ratio)
        .value("target_psa_m_s2", m.target_psa)
        .value("mean_psa_m_s2", m.mean_psa)
        .value("std_psa_m_s2", m.std_psa)
        .value("s0_factor", m.s0_factor)
        .value("s0_m2_s3", s0)
        .value("matched_s0_m2_s3", m.s0_factor * s0);
      if (g.spectral_intensity == 0 && g.noise_intensity_d == 0) // S0 from the target PGA
        json.value("matched_target_pga_g", std::sqrt(m.s0_factor) * g.target_pga);
      json.end_object();
    }

    /// summary.json of `spectrum --realizations N`: the motion, the
    /// ensemble's intensity measures, the spectrum's grid, the target and
    /// its matching.
    void
    write_ensemble_summary(const CommandRun &run, const MotionGenerator &generator,
                           const EnsembleSpectrum &ensemble, const SpectrumMatching *const matched,
                           const std::vector<std::string> &files)
    {
      const InputParameters        &input          = *run.input;
      const GroundMotionParameters &g              = input.ground_motion;
      const SpectrumParameters     &s              = input.spectrum;
      const unsigned int            n_realizations = run.n_realizations;
      const double                  s0             = generator.motion().spectral_intensity;
      JsonWriter json;
      begin_summary(json, "spectrum", input);
      json.begin_object("ground_motion")
        .value("description", generator.description())
        .value("realizations", n_realizations)
        .value("time_step_s", generator.motion().sample_interval)
        .value("spectral_intensity_s0_m2_s3", s0)
        .value("scale_factor", g.scale_factor)
        .end_object();
      json.begin_object("intensity");
      const char *names[] = {"pga_m_s2", "pgv_m_s", "pgd_m", "arias_intensity_m_s",
                             "significant_duration_5_95_s"};
      for (unsigned int k = 0; k < 5; ++k)
        json.begin_object(names[k])
          .value("mean", ensemble.measures[k].mean)
          .value("standard_deviation", ensemble.measures[k].standard_deviation)
          .end_object();
      json.value("baseline_correction", "none").end_object();
      json.begin_object("spectrum")
        .value("method", "Nigam-Jennings exact recursion, piecewise-linear excitation")
        .value("damping_ratios", s.damping_ratios)
        .value("min_period_s", s.periods().front())
        .value("max_period_s", s.periods().back())
        .value("periods", ensemble.n_grid)
        .end_object();
      write_target(json, s);
      if (matched)
        write_matching(json, *matched, g, s0);
      json.value("files", files).end_object();
      write_result_text(run.memory, run.directory, "summary.json", json.str());
    }

    /// `spectrum --realizations N`: ensemble_spectrum.csv/png, summary.json.
    int
    ensemble_spectrum(const CommandRun &run)
    {
      const InputParameters &input          = *run.input;
      const std::string     &directory      = run.directory;
      const unsigned int     n_realizations = run.n_realizations;
      std::ostream          &out            = run.out;
      const GroundMotionParameters &g = input.ground_motion;
      if (!g.is_stochastic())
        input.fail("Ground motion/Type", "--realizations needs a stochastic ground motion, got '" +
                                           ground_motion_type_names().name(g.type) + "'");
      const SpectrumParameters &s      = input.spectrum;
      const bool                target = s.target != DesignSpectrum::none;
      std::pair<double, std::string> t1{0, ""};
      if (target) // may need the model's modes; before anything is written
        t1 = matching_period(input);

      const MotionGenerator generator =
        make_motion_generator(g, input.time_integration.newmark.time_step);
      std::vector<double> periods = s.periods();
      if (target)
        periods.push_back(t1.first);
      EnsembleSpectrum ensemble =
        compute_ensemble_spectrum(generator, g.scale_factor, periods, s.damping_ratios, n_realizations);
      ensemble.n_grid = s.periods().size();
      SpectrumMatching matching;
      if (target)
        matching = match_target(ensemble, s, t1.first, t1.second);
      const SpectrumMatching *matched = target ? &matching : nullptr;
      const double    s0      = generator.motion().spectral_intensity;

      if (!run.memory)
        create_directories(directory);
      write_ensemble_csv(run, ensemble, s, matched);
      std::vector<std::string> files{"ensemble_spectrum.csv"};
      if (input.output.plots && !run.memory)
        for (const std::string &png :
             draw_ensemble(directory,
                           "Mean spectrum of realizations 0.." + std::to_string(n_realizations - 1) +
                             ": " + generator.description(),
                           s, matched))
          files.push_back(png);
      files.push_back("summary.json");

      write_ensemble_summary(run, generator, ensemble, matched, files);

      out << n_realizations << " realizations of " << generator.description() << "\n";
      if (target)
        {
          out << "at T1 = " << matching.period << " s (" << matching.source
              << "): mean PSA " << matching.mean_psa << " m/s^2, target "
              << matching.target_psa << " m/s^2: multiply S0 by " << matching.s0_factor
              << " (Ground motion/Stochastic/S0 = " << matching.s0_factor * s0 << " m^2/s^3";
          if (g.spectral_intensity == 0 && g.noise_intensity_d == 0)
            out << ", or Target PGA = " << std::sqrt(matching.s0_factor) * g.target_pga
                << " g";
          out << ")\n";
        }
      out << "results in " << run.results_place() << " (ensemble_spectrum.csv, summary.json)\n";
      return 0;
    }
  } // namespace

} // namespace poundfe

namespace poundfe::commands
{
  int
  spectrum(const CommandRun &run)
  {
    if (run.n_realizations > 0)
      return ensemble_spectrum(run);
    return single_spectrum(run);
  }
} // namespace poundfe::commands
