#include <poundfe/analysis/analysis.h>
#include <poundfe/analysis/spectrum.h>
#include <poundfe/analysis/statistics.h>
#include <poundfe/excitation/excitation.h>
#include <poundfe/excitation/response_spectrum.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/csv_writer.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/plots.h>

#include <cmath>
#include <iostream>
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
        .value("t5_s", m.t5)
        .value("t95_s", m.t95)
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

    /// One motion: spectrum.csv, spectrum.png, summary.json.
    int
    single_spectrum(const InputParameters &input, const std::string &directory)
    {
      const GroundMotion motion =
        make_ground_motion(input.ground_motion, input, input.time_integration.newmark.time_step);
      if (motion.empty())
        input.fail("Ground motion/Type", "there is no ground motion (type none) to analyse");
      const SpectrumParameters   &s        = input.spectrum;
      const std::vector<double>   periods  = s.periods();
      const ResponseSpectrum      spectrum = response_spectrum(motion, periods, s.damping_ratios);
      const GroundMotionIntensity intensity = ground_motion_intensity(motion);
      const bool                  target    = s.target != DesignSpectrum::none;

      create_directories(directory);
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
      CsvWriter csv(directory + "/spectrum.csv", header);
      double    peak_psa = 0, peak_period = 0;
      for (unsigned int i = 0; i < periods.size(); ++i)
        {
          csv.begin_row(periods[i]);
          for (unsigned int d = 0; d < s.damping_ratios.size(); ++d)
            {
              const unsigned int k = d * periods.size() + i;
              csv.add(spectrum.sd(d, i));
              csv.add(spectrum.relative_velocity[k]);
              csv.add(spectrum.psv(d, i));
              csv.add(spectrum.psa(d, i));
              csv.add(spectrum.psa(d, i) / standard_gravity);
              csv.add(spectrum.absolute_acceleration[k]);
              if (target)
                csv.add(s.target_psa(s.damping_ratios[d], periods[i]));
            }
          csv.end_row();
          if (spectrum.psa(0, i) > peak_psa)
            peak_psa = spectrum.psa(0, i), peak_period = periods[i];
        }
      csv.commit();

      std::vector<std::string> files{"spectrum.csv"};
      if (input.output.plots)
        {
          const unsigned int      per_damping = 6 + target;
          std::vector<PlotSeries> series;
          for (unsigned int d = 0; d < s.damping_ratios.size(); ++d)
            series.push_back({"spectrum.csv", "1:" + std::to_string(2 + d * per_damping + 3),
                              "PSA, " + percent(s.damping_ratios[d]), "lines lw 2"});
          if (target)
            series.push_back({"spectrum.csv", "1:" + std::to_string(1 + per_damping),
                              "target " + design_spectrum_names().name(s.target) + ", ground " +
                                ground_type_names().name(s.ground_type) + ", " +
                                percent(s.damping_ratios.front()),
                              "lines dt 2 lw 2 lc rgb 'black'"});
          for (const std::string &png :
               draw_plots(directory, {spectrum_plot("spectrum.png",
                                                    "Elastic response spectrum: " +
                                                      motion.description(),
                                                    series)}))
            files.push_back(png);
        }
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
        .value("min_period_s", periods.front())
        .value("max_period_s", periods.back())
        .value("periods", static_cast<unsigned long>(periods.size()))
        .value("peak_psa_m_s2", peak_psa)
        .value("period_of_peak_psa_s", peak_period)
        .end_object();
      write_target(json, s);
      json.value("files", files).end_object();
      write_file_atomically(directory + "/summary.json", json.str());

      std::cout << motion.description() << ": PGA " << intensity.pga << " m/s^2 ("
                << intensity.pga / standard_gravity << " g), PGV " << intensity.pgv
                << " m/s, PGD " << intensity.pgd << " m (no baseline correction)\n"
                << "Arias intensity " << intensity.arias_intensity << " m/s, D5-95 "
                << intensity.significant_duration << " s (" << intensity.t5 << " to "
                << intensity.t95 << " s)\n"
                << "peak PSA (" << percent(s.damping_ratios.front()) << ") " << peak_psa
                << " m/s^2 at T = " << peak_period << " s\n"
                << "results in " << directory << "/ (spectrum.csv, summary.json)\n";
      return 0;
    }

    /// The period at which the ensemble is matched, and where it came from.
    std::pair<double, std::string>
    matching_period(const InputParameters &input)
    {
      if (input.spectrum.matching_period > 0)
        return {input.spectrum.matching_period, "Spectrum/Matching period"};
      const Analysis analysis = prepare_analysis(input);
      if (analysis.modes.n_modes() == 0)
        input.fail("Spectrum/Matching period",
                   "is 0 (the model's first period) but the model has no modes "
                   "(Output/Number of modes = 0): give the period");
      return {analysis.modes.period(0), "first mode of the model"};
    }

    int
    ensemble_spectrum(const InputParameters &input, const std::string &directory,
                      const unsigned int n_realizations)
    {
      const GroundMotionParameters &g = input.ground_motion;
      if (!g.is_stochastic())
        input.fail("Ground motion/Type", "--realizations needs a stochastic ground motion, got '" +
                                           ground_motion_type_names().name(g.type) + "'");
      const SpectrumParameters &s      = input.spectrum;
      const bool                target = s.target != DesignSpectrum::none;
      double                    t1     = 0;
      std::string               t1_source;
      if (target)
        std::tie(t1, t1_source) = matching_period(input);

      const MotionGenerator generator =
        make_motion_generator(g, input.time_integration.newmark.time_step);
      std::vector<double> periods = s.periods();
      const unsigned int  n       = periods.size();
      if (target)
        periods.push_back(t1); // the last column: the matching period
      const unsigned int n_damping = s.damping_ratios.size();
      std::vector<std::vector<double>> psa(n_damping * periods.size());
      std::vector<std::vector<double>> measures(5);
      std::vector<double> xi(generator.n_variables()), samples;
      for (unsigned int r = 0; r < n_realizations; ++r)
        {
          standard_normals(generator.motion().seed, r, xi);
          generator.generate(xi.data(), samples);
          GroundMotion motion(generator.motion().sample_interval, samples,
                              generator.description(), generator.held());
          motion.scale(g.scale_factor);
          const ResponseSpectrum spectrum = response_spectrum(motion, periods, s.damping_ratios);
          for (unsigned int d = 0; d < n_damping; ++d)
            for (unsigned int i = 0; i < periods.size(); ++i)
              psa[d * periods.size() + i].push_back(spectrum.psa(d, i));
          const GroundMotionIntensity m = ground_motion_intensity(motion);
          const double values[] = {m.pga, m.pgv, m.pgd, m.arias_intensity,
                                   m.significant_duration};
          for (unsigned int k = 0; k < 5; ++k)
            measures[k].push_back(values[k]);
        }
      std::vector<SampleStatistics> stats;
      for (const std::vector<double> &values : psa)
        stats.push_back(describe(values));

      // the factor on S0 that brings the mean PSA (first damping) to the target at T1
      const double zeta       = s.damping_ratios.front();
      const double target_t1  = target ? s.target_psa(zeta, t1) : 0;
      const double mean_t1    = target ? stats[n].mean : 0;
      const double s0_factor  = target && mean_t1 > 0 ? std::pow(target_t1 / mean_t1, 2) : 0;
      const double amplitude  = std::sqrt(s0_factor);

      create_directories(directory);
      std::vector<std::string> header{"period_s"};
      for (const double z : s.damping_ratios)
        {
          const std::string label = damping_label(z);
          for (const char *name : {"mean_psa_m_s2_", "std_psa_m_s2_", "mean_minus_std_m_s2_",
                                   "mean_plus_std_m_s2_"})
            header.push_back(name + label);
          if (target)
            header.push_back("target_psa_m_s2_" + label);
        }
      if (target)
        header.push_back("matched_mean_psa_m_s2_" + damping_label(zeta));
      CsvWriter csv(directory + "/ensemble_spectrum.csv", header);
      for (unsigned int i = 0; i < n; ++i)
        {
          csv.begin_row(periods[i]);
          for (unsigned int d = 0; d < n_damping; ++d)
            {
              const SampleStatistics &st = stats[d * periods.size() + i];
              csv.add(st.mean);
              csv.add(st.standard_deviation);
              csv.add(st.mean - st.standard_deviation);
              csv.add(st.mean + st.standard_deviation);
              if (target)
                csv.add(s.target_psa(s.damping_ratios[d], periods[i]));
            }
          if (target)
            csv.add(amplitude * stats[i].mean);
          csv.end_row();
        }
      csv.commit();

      std::vector<std::string> files{"ensemble_spectrum.csv"};
      if (input.output.plots)
        {
          const std::string       z = percent(zeta);
          std::vector<PlotSeries> series{
            {"ensemble_spectrum.csv", "1:2", "mean PSA, " + z, "lines lw 2 lc rgb 'blue'"},
            {"ensemble_spectrum.csv", "1:4", "mean - 1 std", "lines dt 3 lc rgb 'blue'"},
            {"ensemble_spectrum.csv", "1:5", "mean + 1 std", "lines dt 3 lc rgb 'blue'"}};
          if (target)
            {
              std::ostringstream matched;
              matched << "mean with S0 x " << s0_factor << " (matched at T = " << t1 << " s)";
              series.push_back({"ensemble_spectrum.csv", "1:6",
                                "target " + design_spectrum_names().name(s.target) +
                                  ", ground " + ground_type_names().name(s.ground_type) + ", " + z,
                                "lines dt 2 lw 2 lc rgb 'black'"});
              series.push_back({"ensemble_spectrum.csv", "1:" + std::to_string(header.size()),
                                matched.str(), "lines lw 2 lc rgb 'red'"});
            }
          const std::string title = "Mean spectrum of " + std::to_string(n_realizations) +
                                    " realizations: " + generator.description();
          for (const std::string &png :
               draw_plots(directory, {spectrum_plot("ensemble_spectrum.png", title, series)}))
            files.push_back(png);
        }
      files.push_back("summary.json");

      JsonWriter json;
      begin_summary(json, "spectrum", input);
      json.begin_object("ground_motion")
        .value("description", generator.description())
        .value("realizations", n_realizations)
        .value("time_step_s", generator.motion().sample_interval)
        .value("spectral_intensity_s0_m2_s3", generator.motion().spectral_intensity)
        .value("scale_factor", g.scale_factor)
        .end_object();
      json.begin_object("intensity");
      const char *names[] = {"pga_m_s2", "pgv_m_s", "pgd_m", "arias_intensity_m_s",
                             "significant_duration_5_95_s"};
      for (unsigned int k = 0; k < 5; ++k)
        {
          const SampleStatistics st = describe(measures[k]);
          json.begin_object(names[k])
            .value("mean", st.mean)
            .value("standard_deviation", st.standard_deviation)
            .end_object();
        }
      json.value("baseline_correction", "none").end_object();
      json.begin_object("spectrum")
        .value("method", "Nigam-Jennings exact recursion, piecewise-linear excitation")
        .value("damping_ratios", s.damping_ratios)
        .value("min_period_s", periods.front())
        .value("max_period_s", periods[n - 1])
        .value("periods", n)
        .end_object();
      write_target(json, s);
      if (target)
        {
          json.begin_object("matching")
            .value("period_s", t1)
            .value("period_source", t1_source)
            .value("damping_ratio", zeta)
            .value("target_psa_m_s2", target_t1)
            .value("mean_psa_m_s2", mean_t1)
            .value("std_psa_m_s2", stats[n].standard_deviation)
            .value("s0_factor", s0_factor)
            .value("s0_m2_s3", generator.motion().spectral_intensity)
            .value("matched_s0_m2_s3", s0_factor * generator.motion().spectral_intensity);
          if (g.spectral_intensity == 0 && g.noise_intensity_d == 0)
            json.value("matched_target_pga_g", amplitude * g.target_pga);
          json.end_object();
        }
      json.value("files", files).end_object();
      write_file_atomically(directory + "/summary.json", json.str());

      std::cout << n_realizations << " realizations of " << generator.description() << "\n";
      if (target)
        {
          std::cout << "at T1 = " << t1 << " s (" << t1_source << "): mean PSA " << mean_t1
                    << " m/s^2, target " << target_t1 << " m/s^2: multiply S0 by " << s0_factor
                    << " (Ground motion/Stochastic/S0 = " << s0_factor * generator.motion().spectral_intensity
                    << " m^2/s^3";
          if (g.spectral_intensity == 0 && g.noise_intensity_d == 0)
            std::cout << ", or Target PGA = " << amplitude * g.target_pga << " g";
          std::cout << ")\n";
        }
      std::cout << "results in " << directory << "/ (ensemble_spectrum.csv, summary.json)\n";
      return 0;
    }
  } // namespace

  int
  spectrum_command(const InputParameters &input, const std::string &output_directory,
                   const unsigned int n_realizations)
  {
    if (n_realizations > 0)
      return ensemble_spectrum(input, output_directory, n_realizations);
    return single_spectrum(input, output_directory);
  }
} // namespace poundfe
