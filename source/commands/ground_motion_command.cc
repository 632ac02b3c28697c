// `poundfe ground-motion`: the ground acceleration a run would use
// (ground_motion.csv, .png); with --realizations N, the samples of
// realizations 0..N-1 and their ensemble PSD against the target.
#include <poundfe/base/exceptions.h>
#include <poundfe/commands/command.h>
#include <poundfe/excitation/excitation.h>
#include <poundfe/excitation/stochastic.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/output/csv_writer.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/plots.h>

#include <algorithm>
#include <cmath>
#include <ostream>

namespace poundfe
{
  namespace
  {
    /// ground_motion_samples.csv: time, then one column per realization.
    void
    write_samples(const std::string &file, const MotionGenerator &generator,
                  const MotionSamples &samples)
    {
      std::vector<std::string> header{"time"};
      for (unsigned int r = 0; r < samples.realizations.size(); ++r)
        header.push_back("realization_" + std::to_string(r));
      CsvWriter csv(file, header);
      for (unsigned int k = 0; k < generator.n_samples(); ++k)
        {
          csv.begin_row(k * generator.motion().sample_interval);
          for (const std::vector<double> &realization : samples.realizations)
            csv.add(realization[k]);
          csv.end_row();
        }
      csv.commit();
    }

    /// The ensemble PSD of `n_realizations` at about 200 frequencies up to
    /// 10 omega_g (filtered motions) or the cutoff (white noise).
    EnsemblePsd
    psd_of(const MotionGenerator &generator, const GroundMotionType type,
           const unsigned int n_realizations)
    {
      const double top =
        type == GroundMotionType::white_noise ?
          generator.cutoff_frequency() :
          std::min(generator.cutoff_frequency(), 10 * generator.motion().filter.omega_g);
      const double dw = 2 * M_PI / (generator.n_samples() * generator.motion().sample_interval);
      const unsigned int band = std::max(1u, static_cast<unsigned int>(top / dw / 200));
      return ensemble_psd(generator, n_realizations, band, top);
    }

    /// ensemble_psd.csv: omega, the estimate and the target (times the
    /// scale factor squared), their ratio.
    void
    write_psd(const std::string &file, const EnsemblePsd &psd, const double scale)
    {
      CsvWriter out(file, {"omega", "estimated_psd", "target_psd", "ratio"});
      for (std::size_t i = 0; i < psd.omega.size(); ++i)
        {
          out.begin_row(psd.omega[i]);
          out.add(psd.estimate[i] * scale * scale);
          out.add(psd.target[i] * scale * scale);
          out.add(psd.estimate[i] / psd.target[i]);
          out.end_row();
        }
      out.commit();
    }

    /// `ground-motion --realizations N`: the samples of realizations 0..N-1
    /// and their ensemble PSD against the target.
    int
    ensemble(const InputParameters &input, const std::string &directory,
             const unsigned int n_realizations, std::ostream &out)
    {
      const GroundMotionType type = input.ground_motion.type;
      if (!input.ground_motion.is_stochastic())
        input.fail("Ground motion/Type", "--realizations needs a stochastic ground motion, got '" +
                                           ground_motion_type_names().name(type) + "'");
      const MotionGenerator generator =
        make_motion_generator(input.ground_motion, input.time_integration.newmark.time_step);
      const double scale = input.ground_motion.scale_factor;
      // all samples are held, then written: the guard before either
      require_free_space(directory, csv_table_bytes(generator.n_samples(), n_realizations + 1.0),
                         "ground-motion samples (" + std::to_string(generator.n_samples()) +
                           " rows of " + std::to_string(n_realizations) + " realizations)");
      prepare_output_directory(directory);
      const MotionSamples samples = sample_realizations(generator, n_realizations, scale);
      write_samples(directory + "/ground_motion_samples.csv", generator, samples);
      write_psd(directory + "/ensemble_psd.csv", psd_of(generator, type, n_realizations), scale);
      if (input.output.plots)
        draw_plots(directory,
                   {Plot{"ensemble_psd.png",
                         "ensemble PSD of " + std::to_string(n_realizations) + " realizations",
                         "omega (rad/s)", "two-sided PSD (m^2/s^3)",
                         {{"ensemble_psd.csv", "1:2", "estimate", "lines"},
                          {"ensemble_psd.csv", "1:3", "target", "lines"}}, true},
                    Plot{"ground_motion_samples.png", generator.description(), "time (s)",
                         "ground acceleration (m/s^2)",
                         {{"ground_motion_samples.csv", "1:2", "realization 0", "lines"}}}});
      out << n_realizations << " realizations of " << generator.description() << ": "
          << generator.n_samples() << " samples each, " << generator.n_variables()
          << " random variables; ensemble mean square " << samples.mean_square << " m^2/s^4\n"
          << "written to " << directory << "/ground_motion_samples.csv and ensemble_psd.csv\n";
      return 0;
    }

    /// The input's ground motion: ground_motion.csv and .png.
    int
    single(const InputParameters &input, const std::string &directory, std::ostream &out)
    {
      const GroundMotion motion =
        make_ground_motion(input.ground_motion, input, input.time_integration.newmark.time_step);
      if (motion.empty())
        throw InputError(input.file, input.line_of("Ground motion/Type"), "Ground motion/Type",
                         "there is no ground motion to write (type none)");
      prepare_output_directory(directory);
      {
        CsvWriter csv(directory + "/ground_motion.csv", {"time", "ground_acceleration"});
        for (std::size_t i = 0; i < motion.samples().size(); ++i)
          {
            csv.begin_row(i * motion.time_step());
            csv.add(motion.samples()[i]);
            csv.end_row();
          }
        csv.commit();
      }
      if (input.output.plots)
        draw_plots(directory, {Plot{"ground_motion.png", motion.description(), "time (s)",
                                    "ground acceleration (m/s^2)",
                                    {{"ground_motion.csv", "1:2", "a_g", "lines"}}}});
      out << motion.description() << ": " << motion.samples().size() << " samples, dt = "
          << motion.time_step() << " s, PGA = " << motion.peak() << " m/s^2 ("
          << motion.peak() / standard_gravity << " g)\n"
          << "written to " << directory << "/ground_motion.csv\n";
      return 0;
    }
  } // namespace
} // namespace poundfe

namespace poundfe::commands
{
  int
  ground_motion(const CommandRun &run)
  {
    if (run.n_realizations > 0)
      return ensemble(*run.input, run.directory, run.n_realizations, run.out);
    return single(*run.input, run.directory, run.out);
  }
} // namespace poundfe::commands
