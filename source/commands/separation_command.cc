// `poundfe separation`: the joint width of adjacent buildings by the ABS,
// SRSS, DDC, EC8 and ASCE 7 rules against the time history without contact
// (or the response-spectrum route), P(pounding) against the gap with random
// loading and, with a site hazard, P(pounding in T years) (the engines:
// separation/separation.h, separation/separation_spectrum.h,
// hazard/pounding_hazard.h; their tables: separation/separation_report.h).
// Rank 0 writes separation.csv,
// pounding_probability.csv, spectrum_modes.csv, pounding_hazard.csv,
// pounding_given_pga.csv, the plots and summary.json.
#include <poundfe/input/engine_parameters.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/base/numbers.h>
#include <poundfe/commands/command.h>
#include <poundfe/dynamics/realization.h>
#include <poundfe/hazard/pounding_hazard.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/output/append_file.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/finite_output.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/plots.h>
#include <poundfe/reliability/random_parameters.h>
#include <poundfe/reliability/statistics.h>
#include <poundfe/separation/separation.h>
#include <poundfe/separation/separation_report.h>
#include <poundfe/separation/separation_spectrum.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <iterator>
#include <limits>
#include <optional>
#include <regex>
#include <sstream>

namespace poundfe::commands
{
  namespace
  {
    std::string
    percent_of(const double value, const double reference)
    {
      if (!(reference > 0))
        return "n/a";
      const double percent = 100 * (value - reference) / reference;
      return (percent >= 0 ? "+" : "") + rounded(percent, 3) + " %";
    }

    void
    write_spectrum_modes(const CommandRun &run, const Model &model, const SpectrumPeaks &peaks)
    {
      write_result_text(run.memory, run.directory, "spectrum_modes.csv",
                        spectrum_modes_table(model, peaks));
    }

    /// separation.csv and its plot (one panel per pair).
    void
    write_separation_table(const CommandRun &run, const Model &model,
                           const std::vector<AdjacentPair> &pairs,
                           const std::vector<PairResult> &results, std::vector<Plot> &plots,
                           const SpectrumPeaks *spectrum, const bool monte_carlo)
    {
      write_result_text(run.memory, run.directory, "separation.csv",
                        separation_table(model, pairs, results, spectrum));
      plots.push_back(separation_plot(pairs, spectrum, monte_carlo));
    }

    /// pounding_probability.csv and its plot (one panel per pair).
    void
    write_probability_table(const CommandRun &run, const InputParameters &input,
                            const std::vector<AdjacentPair> &pairs,
                            const std::vector<PairResult> &results, std::vector<Plot> &plots)
    {
      write_result_text(run.memory, run.directory, "pounding_probability.csv",
                        pounding_probability_table(input.separation, pairs, results));
      plots.push_back(pounding_probability_plot(input.separation, pairs, results));
    }

    void
    write_spectrum_summary(JsonWriter &json, const InputParameters &input, const Model &model,
                           const SpectrumPeaks &peaks)
    {
      const SpectrumParameters &s = input.spectrum;
      json.begin_object("response_spectrum")
        .value("spectrum", design_spectrum_names().name(s.target))
        .value("ground_type", ground_type_names().name(s.ground_type))
        .value("design_ground_acceleration_g", s.design_ground_acceleration)
        .value("modal_combination", modal_combination_names().name(input.separation.modal_combination))
        .begin_array("buildings");
      for (unsigned int b = 0; b < peaks.buildings.size(); ++b)
        {
          const SpectrumModalResponse &r = peaks.buildings[b];
          std::vector<double>          periods;
          for (const double w : r.omega)
            periods.push_back(2 * M_PI / w);
          json.begin_object()
            .value("name", model.buildings[b].name)
            .value("n_modes", r.n_modes())
            .value("cumulative_mass_ratio", r.cumulative_mass_ratio())
            .value("periods_s", periods)
            .value("damping_ratios", r.damping_ratio)
            .value("Sd_m", r.spectral_displacement)
            .end_object();
        }
      json.end_array();
      json.begin_array("pairs");
      for (const auto &pair : peaks.levels)
        {
          json.begin_object().begin_array("levels");
          for (const auto &level : pair)
            json.begin_object()
              .value("u_left_srss_m", level[0].srss)
              .value("u_right_srss_m", level[1].srss)
              .value("u_left_cqc_m", level[0].cqc)
              .value("u_right_cqc_m", level[1].cqc)
              .end_object();
          json.end_array().end_object();
        }
      json.end_array().end_object();
    }

    /// The gaps of pounding_hazard.csv: past every realization, the existing
    /// gap and the gap for the target.
    std::vector<double>
    hazard_gaps(const InputParameters &input, const std::vector<AdjacentPair> &pairs,
                const PoundingHazard &result)
    {
      double top = 0;
      for (std::size_t i = 0; i < pairs.size(); ++i)
        {
          // P_T well below the target too
          top = std::max({top, pairs[i].existing_gap, 2.5 * result.gap_for_target[i]});
          for (const std::vector<double> &level : result.largest_approach[i])
            for (const double d : level)
              top = std::max(top, d);
        }
      return gap_grid(input.separation, top);
    }

    std::string
    years_text(const double years)
    {
      return rounded(years) + " years";
    }

    /// pounding_given_pga.csv and a panel per pair: the empirical P(D > g | a_k) and the model's.
    void
    write_conditional(const CommandRun &run, const InputParameters &input,
                      const std::vector<AdjacentPair> &pairs, const PoundingHazard &result,
                      const std::vector<double> &gaps, Plot &plot)
    {
      const double confidence = input.separation.confidence_level;
      std::string  csv        = "gap_m";
      std::vector<std::vector<std::vector<ExceedancePoint>>> curves(pairs.size());
      for (std::size_t i = 0; i < pairs.size(); ++i)
        for (std::size_t k = 0; k < result.pga_levels.size(); ++k)
          {
            curves[i].push_back(exceedance_curve(result.largest_approach[i][k], gaps, confidence));
            const std::string stem = pairs[i].name + "@" + rounded(result.pga_levels[k], 6) + "g_";
            for (const char *what : {"probability", "lower", "upper", "model"})
              csv += "," + stem + what;
          }
      csv += '\n';
      for (std::size_t j = 0; j < gaps.size(); ++j)
        {
          append_number(csv, gaps[j]);
          for (std::size_t i = 0; i < pairs.size(); ++i)
            for (std::size_t k = 0; k < result.pga_levels.size(); ++k)
              {
                const ExceedancePoint &e = curves[i][k][j];
                const LognormalCurve   f = pounding_fragility(result.demand[i], gaps[j]);
                const double model =
                  gaps[j] > 0 ? standard_normal_cdf(std::log(result.pga_levels[k] / f.theta) / f.beta) : 1.0;
                for (const double x : {e.probability, e.lower, e.upper, model})
                  csv += ',', append_number(csv, x);
              }
          csv += '\n';
        }
      write_result_text(run.memory, run.directory, "pounding_given_pga.csv", csv);

      const std::size_t n_levels = result.pga_levels.size();
      for (std::size_t i = 0; i < pairs.size(); ++i)
        {
          Plot panel{"", "P(pounding | PGA) of " + pairs[i].name + ", " +
                           std::to_string(result.largest_approach[i][0].size()) +
                           " realizations per level",
                     "gap width g (m)", "P(largest relative approach > g | PGA)", {}};
          for (std::size_t k = 0; k < n_levels; ++k)
            {
              const std::size_t column = 2 + 4 * (i * n_levels + k);
              const std::string colour = " lc " + std::to_string(k + 1);
              panel.series.push_back({"pounding_given_pga.csv", "1:" + std::to_string(column),
                                      "Monte Carlo, PGA " + rounded(result.pga_levels[k]) + " g",
                                      "lines lw 2" + colour});
              panel.series.push_back({"pounding_given_pga.csv", "1:" + std::to_string(column + 3),
                                      k == 0 ? "(dashed: lognormal demand model)" : "",
                                      "lines dt 2" + colour});
            }
          panel.settings = "set yrange [0:1]\n";
          if (i == 0 && plot.file.empty())
            plot = panel, plot.file = "pounding_hazard.png";
          else
            plot.below.push_back(panel);
        }
    }

    void
    write_pounding_hazard(const CommandRun &run, const InputParameters &input,
                          const std::vector<AdjacentPair> &pairs, const PoundingHazard &result,
                          std::vector<Plot> &plots)
    {
      const PoundingHazardParameters &p    = input.separation.hazard;
      const std::vector<double>       gaps = hazard_gaps(input, pairs, result);
      std::string                     csv  = "gap_m";
      for (const AdjacentPair &pair : pairs)
        csv += "," + pair.name + "_annual_rate_per_year," + pair.name + "_probability_in_exposure";
      csv += '\n';
      for (const double g : gaps)
        {
          append_number(csv, g);
          for (const PowerLawDemand &demand : result.demand)
            {
              const double rate = annual_pounding_rate(result.hazard, demand, g);
              for (const double x : {rate, probability_in_years(rate, p.exposure_years)})
                csv += ',', append_number(csv, x);
            }
          csv += '\n';
        }
      write_result_text(run.memory, run.directory, "pounding_hazard.csv", csv);

      Plot plot;
      write_conditional(run, input, pairs, result, gaps, plot);
      const std::string target = rounded(p.target_probability);
      for (std::size_t i = 0; i < pairs.size(); ++i)
        {
          Plot panel{"", "probability of pounding of " + pairs[i].name + " in " +
                           years_text(p.exposure_years) + " (" + result.hazard.source + ")",
                     "gap width g (m)", "P(pounding in " + years_text(p.exposure_years) + ")", {}};
          panel.log_y    = true;
          panel.settings = "set yrange [1e-4:1]\n";
          const std::string gap = rounded(result.gap_for_target[i]);
          panel.series   = {
            {"pounding_hazard.csv", "1:" + std::to_string(3 + 2 * i), "1 - exp(-T lambda(g))",
             "lines lw 2 lc rgb 'navy'"},
            {"pounding_hazard.csv", "1:(" + target + ")", "target " + target,
             "lines dt 2 lc rgb 'gray40'"},
            {"pounding_hazard.csv", "(" + gap + "):(10**(-4 + 4 * $0 / " +
                                      std::to_string(std::max<std::size_t>(1, gaps.size() - 1)) + ".0))",
             "gap for the target " + gap + " m", "lines dt 3 lw 2 lc rgb 'dark-green'"},
            {"pounding_hazard.csv", "(" + rounded(pairs[i].existing_gap) + "):(10**(-4 + 4 * $0 / " +
                                      std::to_string(std::max<std::size_t>(1, gaps.size() - 1)) + ".0))",
             "existing gap " + rounded(pairs[i].existing_gap) + " m", "lines dt 2 lc rgb 'red'"}};
          plot.below.push_back(panel);
        }
      plots.push_back(plot);
    }

    void
    write_pounding_hazard_json(JsonWriter &json, const InputParameters &input,
                               const std::vector<AdjacentPair> &pairs, const PoundingHazard &result)
    {
      const PoundingHazardParameters &p = input.separation.hazard;
      json.begin_object("site_hazard")
        .value("hazard", result.hazard.source)
        .value("minimum_pga_g", result.hazard.minimum_pga)
        .value("pga_levels_g", result.pga_levels)
        .value("input_motion_pga_g", result.reference_pga)
        .value("demand_model", "ln D | a normal: median c a^b, dispersion beta_D (least squares)")
        .value("exposure_years", p.exposure_years)
        .value("target_probability", p.target_probability)
        .value("status", result.interrupted ? "interrupted" : result.failure.empty() ? "completed" : "failed");
      if (!result.failure.empty())
        json.value("message", result.failure);
      json.begin_array("pairs");
      for (std::size_t i = 0; i < result.demand.size(); ++i)
        {
          const double rate = annual_pounding_rate(result.hazard, result.demand[i], pairs[i].existing_gap);
          json.begin_object()
            .value("pair", pairs[i].name)
            .value("realizations_per_level", result.largest_approach[i][0].size())
            .value("median_at_1g_m", result.demand[i].median_at_1g)
            .value("exponent_b", result.demand[i].exponent)
            .value("dispersion_beta_d", result.demand[i].dispersion)
            .value("annual_rate_at_existing_gap", rate)
            .value("probability_in_exposure_at_existing_gap",
                   probability_in_years(rate, p.exposure_years))
            .value("gap_for_target_probability_m", result.gap_for_target[i])
            .end_object();
        }
      json.end_array().end_object();
    }

    void
    report_pounding_hazard(const dealii::ConditionalOStream &out, const InputParameters &input,
                           const std::vector<AdjacentPair> &pairs, const PoundingHazard &result)
    {
      const PoundingHazardParameters &p = input.separation.hazard;
      if (result.interrupted)
        {
          out << "site hazard: interrupted during the PGA levels; the same command runs the rest\n";
          return;
        }
      if (!result.failure.empty())
        {
          out << "site hazard: failed: " << result.failure << "\n";
          return;
        }
      out << "site hazard (" << result.hazard.source << ", PGA > " << rounded(result.hazard.minimum_pga)
          << " g), Monte Carlo at PGA " ;
      for (std::size_t k = 0; k < result.pga_levels.size(); ++k)
        out << (k ? ", " : "") << rounded(result.pga_levels[k]);
      out << " g:\n";
      for (std::size_t i = 0; i < result.demand.size(); ++i)
        {
          const PowerLawDemand &d    = result.demand[i];
          const double          rate = annual_pounding_rate(result.hazard, d, pairs[i].existing_gap);
          out << "  " << pairs[i].name << ": median largest approach " << rounded(d.median_at_1g)
              << " m a^" << rounded(d.exponent) << " (a in g), beta_D " << rounded(d.dispersion)
              << "; at the existing gap " << rounded(rate) << " poundings/year, P = "
              << rounded(probability_in_years(rate, p.exposure_years)) << " in "
              << years_text(p.exposure_years) << "; gap for P = " << rounded(p.target_probability)
              << " in " << years_text(p.exposure_years) << ": " << rounded(result.gap_for_target[i])
              << " m\n";
        }
      for (const std::string &warning : result.warnings)
        out << "  warning: " << warning << "\n";
    }
    void
    write_summary(const CommandRun &run, const InputParameters &input,
                  const Model &model, const std::vector<AdjacentPair> &pairs,
                  const std::vector<PairResult> &results, const std::string &status,
                  const std::string &method, const unsigned long n_realizations,
                  const SpectrumPeaks *spectrum, const std::optional<PoundingHazard> &hazard)
    {
      const SeparationParameters &s = input.separation;
      JsonWriter                  json;
      begin_summary(json, "separation", input, status);
      if (hazard && !hazard->failure.empty())
        json.value("message", "site hazard: " + hazard->failure);
      if (hazard && !hazard->warnings.empty())
        json.value("warnings", hazard->warnings);
      json.value("method", method)
        .value("peak_displacements", peak_displacements_names().name(s.peak_displacements));
      if (spectrum)
        write_spectrum_summary(json, input, model, *spectrum);
      if (n_realizations > 0)
        json.value("completed_realizations", n_realizations);
      json.value("target_probability", s.target_probability)
        .value("confidence_level", s.confidence_level)
        .value("coinciding_levels_factor", s.coinciding_levels_factor);
      json.begin_array("pairs");
      for (std::size_t p = 0; p < pairs.size(); ++p)
        write_pair_json(json, s, model, pairs[p], results[p], spectrum == nullptr);
      json.end_array();
      if (hazard)
        write_pounding_hazard_json(json, input, pairs, *hazard);
      json.end_object();
      write_result_text(run.memory, run.directory, "summary.json", json.str());
    }

    /// The console report: per pair and level the rules against the time
    /// history, the governing rule and the probability of pounding.
    void
    report(const dealii::ConditionalOStream &out, const InputParameters &input, const std::vector<AdjacentPair> &pairs,
           const std::vector<PairResult> &results, const bool time_history)
    {
      const SeparationParameters &s = input.separation;
      for (std::size_t p = 0; p < pairs.size(); ++p)
        {
          const AdjacentPair &pair = pairs[p];
          const PairResult   &r    = results[p];
          out << pair.name << ": existing gap " << rounded(pair.existing_gap) << " m, T = "
              << rounded(2 * M_PI / r.left_mode.omega) << " s (zeta "
              << rounded(r.left_mode.damping_ratio) << ") and "
              << rounded(2 * M_PI / r.right_mode.omega) << " s (zeta "
              << rounded(r.right_mode.damping_ratio) << "), rho = " << rounded(r.rho) << "\n";
          for (std::size_t l = 0; l < r.levels.size(); ++l)
            {
              const auto values = rule_values(r.levels[l].rules);
              out << "  level " << rounded(pair.levels[l].level) << " m"
                  << (pair.levels[l].floors_coincide ? "" : " (floors differ)");
              if (time_history)
                out << ": time history " << rounded(r.levels[l].time_history) << " m";
              else
                out << ": u " << rounded(r.levels[l].u_left) << " and "
                    << rounded(r.levels[l].u_right) << " m";
              for (unsigned int c = 0; c < 5; ++c)
                {
                  out << ", " << rule_names[c] << " " << rounded(values[c]);
                  if (time_history)
                    out << " (" << percent_of(values[c], r.levels[l].time_history) << ")";
                }
              out << "\n";
            }
          const Joint        joint     = joint_of(r);
          const unsigned int governing = joint.governing_code_rule();
          out << "  joint (largest over the levels): ";
          if (time_history)
            out << "time history " << rounded(joint.time_history) << " m; ";
          out << "governing code rule " << (governing == 3 ? "EC8 " : "ASCE 7 ")
              << rounded(joint.required[governing]) << " m";
          if (time_history)
            out << "; EC8 " << percent_of(joint.required[3], joint.time_history) << ", ASCE 7 "
                << percent_of(joint.required[4], joint.time_history) << " of the time history";
          out << "\n";
          if (!r.largest_approach.empty())
            {
              const auto at_gap = exceedance_curve(r.largest_approach, {pair.existing_gap},
                                                   s.confidence_level)[0];
              const double upper =
                gap_for_probability_upper(r.largest_approach, s.target_probability,
                                          s.confidence_level);
              out << "  P(pounding at the existing gap) = " << rounded(at_gap.probability) << " ["
                  << rounded(at_gap.lower) << ", " << rounded(at_gap.upper) << "]; gap for P = "
                  << s.target_probability << ": "
                  << rounded(gap_for_probability(r.largest_approach, s.target_probability))
                  << " m (" << rounded(100 * s.confidence_level) << " % upper band: "
                  << (std::isnan(upper) ? "needs more realizations" : rounded(upper) + " m")
                  << ")\n";
            }
          if (!r.random_separation.empty())
            out << "  P(pounding at the random separation) = "
                << rounded(pounding_at_random_separation(r).probability) << "\n";
        }
    }

    /// The file's input for the free responses: no gap element between the
    /// buildings, no barrier. Throws InputError for fewer than two buildings.
    InputParameters
    free_input(const InputParameters &file_input)
    {
      InputParameters input = file_input;
      input.contact.law     = "none";
      // no gap, no contact model: Contact/Model = nonsmooth steps its gaps
      // only, and the free responses are the same Newmark runs either way
      input.time_integration.contact_model = ContactModel::penalty;
      // none of the file's Contact entries acts on the free responses: not
      // one is reported as without effect
      for (auto line = input.lines.begin(); line != input.lines.end();)
        line = line->first.rfind("Contact/", 0) == 0 ? input.lines.erase(line) : std::next(line);
      if (input.model.buildings.size() < 2)
        input.fail("Model/Number of buildings",
                   "separation needs two or more adjacent buildings, got " +
                     std::to_string(input.model.buildings.size()));
      return input;
    }

    /// How the peaks come: from the design spectrum, from Monte Carlo of a
    /// random loading, or from one time history.
    struct Route
    {
      bool by_spectrum = false, random = false;
    };

    /// The route of the input, checked with the pairs before anything runs.
    Route
    check_route(const InputParameters &input, const std::vector<AdjacentPair> &pairs)
    {
      for (const AdjacentPair &pair : pairs)
        if (pair.levels.empty())
          input.fail("Model/Number of buildings",
                     "buildings " + pair.name + " have no level in common (a floor of either "
                     "above both bases and up to the lower roof)");
      Route route;
      route.by_spectrum =
        input.separation.peak_displacements == PeakDisplacements::response_spectrum;
      if (route.by_spectrum && input.spectrum.target == DesignSpectrum::none)
        input.fail("Separation/Peak displacements",
                   "response spectrum needs a design spectrum: set Spectrum/Target "
                   "(ec8-type-1 or ec8-type-2)");
      route.random = !route.by_spectrum && (input.ground_motion.is_stochastic() ||
                                            !input.nodal_forces.white_noise.empty());
      if (route.by_spectrum && input.separation.hazard.given())
        input.fail(input.separation.hazard.hazard_file.empty() ?
                     "Separation/Site hazard/Annual rate at 1 g" :
                     "Separation/Site hazard/File",
                   "a site hazard needs the time-history route (Monte Carlo of a random "
                   "ground motion at its PGA levels), not Peak displacements = response spectrum");
      return route;
    }

    /// What the runs leave for the output.
    struct Outcome
    {
      std::vector<PairResult> results;
      std::string             status = "completed", method;
      unsigned long           n_completed = 0;
      int                     exit_status = 0;
    };

    /// The Random parameters of a Monte Carlo without contact: the pairs'
    /// separations (Model/Separations[i], sampled per realization: they
    /// change no free response) apart from the structure's (made random in
    /// the runner), each with its block of the correlation matrix; with a
    /// correlation, the separations' Nataf transformation is over the
    /// structure's variables then the separations (RandomSeparations).
    /// Limit states are not used here.
    void
    split_random_parameters(const InputParameters &input, const std::vector<AdjacentPair> &pairs,
                            RandomParameterParameters &structure, RandomSeparations &separations)
    {
      const RandomParameterParameters &p = input.random_parameters;
      static const std::regex separation(R"(^\s*Model/Separations\s*(\[\s*([0-9]+)\s*\])?\s*$)");
      structure = p;
      structure.names.clear(), structure.paths.clear(), structure.distributions.clear();
      structure.limit_state_names.clear(), structure.expressions.clear();
      std::vector<std::size_t> of_structure, of_separations; // indices in p's variables
      for (std::size_t i = 0; i < p.names.size(); ++i)
        {
          std::smatch match;
          if (!std::regex_match(p.paths[i], match, separation))
            {
              structure.names.push_back(p.names[i]);
              structure.paths.push_back(p.paths[i]);
              structure.distributions.push_back(p.distributions[i]);
              of_structure.push_back(i);
              continue;
            }
          const unsigned long b  = match[2].matched ? std::stoul(match[2]) : 1;
          const auto          at = std::find_if(pairs.begin(), pairs.end(), [b](const AdjacentPair &a) {
            return a.left + 1 == b && a.right == b;
          });
          if (at == pairs.end())
            input.fail("Random parameters/Variables",
                       "variable '" + p.names[i] + "': no adjacent pair of buildings " +
                         std::to_string(b) + " and " + std::to_string(b + 1));
          separations.pairs.push_back(at - pairs.begin());
          separations.distributions.push_back(p.distributions[i]);
          of_separations.push_back(i);
        }
      if (p.correlation.empty())
        return;
      // the correlation in the order (structure, separations); the
      // structure's block is the runner's
      std::vector<std::size_t> order = of_structure;
      order.insert(order.end(), of_separations.begin(), of_separations.end());
      DenseMatrix reordered(order.size(), std::vector<double>(order.size()));
      std::vector<Distribution> marginals;
      for (std::size_t i = 0; i < order.size(); ++i)
        {
          marginals.push_back(p.distributions[order[i]]);
          for (std::size_t j = 0; j < order.size(); ++j)
            reordered[i][j] = p.correlation[order[i]][order[j]];
        }
      structure.correlation.assign(of_structure.size(), {});
      for (std::size_t i = 0; i < of_structure.size(); ++i)
        structure.correlation[i].assign(reordered[i].begin(),
                                        reordered[i].begin() + of_structure.size());
      if (!of_separations.empty()) // R was checked on reading: T exists
        separations.joint = std::make_shared<const NatafTransformation>(marginals, reordered);
    }

    /// Monte Carlo without contact and, with a site hazard, at its PGA levels.
    void
    run_random(const InputParameters &input, const Analysis &analysis,
               const std::vector<AdjacentPair> &pairs, const RandomParameterParameters &structure,
               const RandomSeparations &separations, const CommandRun &run,
               std::optional<PoundingHazard> &hazard, Outcome &outcome)
    {
      const MPI_Comm        comm      = run.communicator;
      const std::string     directory = run.memory ? "" : run.directory; // "": no journal
      const unsigned int    rank      = dealii::Utilities::MPI::this_mpi_process(comm);
      const MonteCarloTable table     = run_realizations_without_contact(
        analysis, time_history_parameters(input), pairs, input.monte_carlo.realizations, directory,
        comm, outcome.results,
        [&](RealizationRunner &runner) {
          attach_random_parameters(runner, structure, input, input.model, input.contact, input.modal.eigensolver);
        },
        separations);
      if (run.memory && rank == 0) // the journal's rows a run into files appended
        write_result_text(run.memory, run.directory, "realizations.csv", realizations_text(table));
      if (hazard && table.interrupted) // the levels not begun: the same command runs them
        hazard->interrupted = true;
      else if (hazard)
        {
          // the levels' structure is as random as the file's PGA's (the same
          // normals of realization r: the same sampled structure at every level)
          RealizationRunner runner(analysis, time_history_parameters(input));
          attach_random_parameters(runner, structure, input, input.model, input.contact, input.modal.eigensolver);
          SeparationObserver observer(analysis.model, pairs);
          run_pounding_hazard(largest_approach_job(runner, observer, pairs),
                              input.monte_carlo.realizations, input.separation.hazard, directory,
                              comm, *hazard);
        }
      if (table.interrupted || (hazard && hazard->interrupted))
        outcome.status = "interrupted", outcome.exit_status = interrupted_exit_status();
      else if (hazard && !hazard->failure.empty()) // the per-event results stand
        {
          outcome.status = "failed", outcome.exit_status = 2;
          if (rank == 0)
            std::cerr << "poundfe: numerical failure: site hazard: " << hazard->failure
                      << " (the per-event results and the levels' realizations are written)\n";
        }
      if (rank != 0)
        return;
      outcome.n_completed = outcome.results[0].largest_approach.size();
      outcome.method      = "Monte Carlo without contact: means of " +
                       std::to_string(outcome.n_completed) + " realizations";
      if (outcome.n_completed == 0)
        {
          if (outcome.status == "interrupted") // the guard's summary says so
            throw Interrupted();
          throw NumericalError("no realization completed (see realizations.csv)");
        }
    }

    /// One time history without contact (rank 0).
    void
    run_deterministic(const InputParameters &input, const Analysis &analysis,
                      const std::vector<AdjacentPair> &pairs, Outcome &outcome)
    {
      const RunStatus run =
        run_without_contact(analysis, time_history_parameters(input), pairs, outcome.results);
      outcome.status      = run.name();
      outcome.method      = "time history without contact";
      if (run.kind == RunStatus::Kind::failed)
        {
          std::cerr << "poundfe: numerical failure: " << run.message
                    << " (results up to t = " << run.end_time << " s are written)\n";
          outcome.exit_status = 2;
        }
      else if (run.kind == RunStatus::Kind::interrupted)
        outcome.exit_status = interrupted_exit_status();
    }

    /// separation.csv, spectrum_modes.csv, pounding_probability.csv, the
    /// pounding hazard's tables, the plots and summary.json (rank 0).
    void
    write_results(const CommandRun &run, const InputParameters &input,
                  const Analysis &analysis, const std::vector<AdjacentPair> &pairs,
                  const Route &route, const Outcome &outcome, const SpectrumPeaks *by_modes,
                  const std::optional<PoundingHazard> &hazard)
    {
      std::vector<Plot> plots;
      write_separation_table(run, analysis.model, pairs, outcome.results, plots, by_modes,
                             route.random);
      if (by_modes)
        write_spectrum_modes(run, analysis.model, *by_modes);
      if (route.random)
        write_probability_table(run, input, pairs, outcome.results, plots);
      if (hazard && !hazard->interrupted && hazard->failure.empty())
        write_pounding_hazard(run, input, pairs, *hazard, plots);
      if (input.output.plots && outcome.status == "completed" && !run.memory)
        draw_plots(run.directory, plots);
      write_summary(run, input, analysis.model, pairs, outcome.results, outcome.status,
                    outcome.method, outcome.n_completed, by_modes, hazard);
    }

    /// The Random parameters split into the structure's and the pairs'
    /// separations; the structure's paths and distributions checked on a
    /// runner before any output.
    void
    split_checked_random_parameters(const InputParameters &input, const Analysis &analysis,
                                    const std::vector<AdjacentPair> &pairs,
                                    RandomParameterParameters       &structure,
                                    RandomSeparations               &separations)
    {
      split_random_parameters(input, pairs, structure, separations);
      if (!structure.has_variables())
        return;
      RealizationRunner check(analysis, time_history_parameters(input));
      attach_random_parameters(check, structure, input, input.model, input.contact,
                               input.modal.eigensolver);
    }

    /// The run's outcome on the terminal: how it ended, the method, the
    /// pairs' peaks and what files it wrote (rank 0; pcout is silent elsewhere).
    void
    print_outcome(dealii::ConditionalOStream &pcout, const CommandRun &run,
                  const InputParameters &input, const std::vector<AdjacentPair> &pairs,
                  const Route &route, const Outcome &outcome,
                  const std::optional<PoundingHazard> &hazard)
    {
      if (outcome.status == "interrupted")
        pcout << "separation interrupted: the results are over what was completed before the "
                 "signal (summary.json says interrupted)"
              << (route.random ? "; the same command runs the rest" : "") << "\n";
      pcout << "poundfe separation: " << outcome.method << "\n";
      report(pcout, input, pairs, outcome.results, !route.by_spectrum);
      if (hazard)
        report_pounding_hazard(pcout, input, pairs, *hazard);
      pcout << "results in " << run.results_place() << " (summary.json, separation.csv"
            << (route.random ? ", pounding_probability.csv, realizations.csv" : "")
            << (route.by_spectrum ? ", spectrum_modes.csv" : "")
            << (hazard && hazard->failure.empty() ?
                  ", pounding_hazard.csv, pounding_given_pga.csv" :
                  "")
            << (hazard && !run.memory ? ", pga_*g/" : "")
            << (input.output.plots && outcome.status == "completed" ? ", *.png" : "") << ")\n";
    }
  } // namespace

  int
  separation(const CommandRun &run)
  {
    const std::string         &directory = run.directory;
    const MPI_Comm             comm      = run.communicator;
    const unsigned int         rank      = dealii::Utilities::MPI::this_mpi_process(comm);
    dealii::ConditionalOStream pcout(run.out, rank == 0);

    // Set-up: everything read and checked before any output.
    const InputParameters           input    = free_input(*run.input);
    const Analysis                  analysis = prepare_analysis(input);
    const std::vector<AdjacentPair> pairs    = adjacent_pairs(analysis.model);
    const Route                     route    = check_route(input, pairs);
    std::optional<PoundingHazard>   hazard;
    if (input.separation.hazard.given())
      hazard = prepare_pounding_hazard(
        input.separation.hazard, input,
        RealizationRunner(analysis, time_history_parameters(input)).reference_pga("the PGA levels of a site hazard"));
    RandomParameterParameters structure; // Random parameters: the structure's
    RandomSeparations         separations; // and the pairs' separations
    if (route.random)
      split_checked_random_parameters(input, analysis, pairs, structure, separations);
    std::optional<SpectrumPeaks> spectrum; // it may find bad input
    if (route.by_spectrum && rank == 0)
      spectrum = spectrum_peaks(analysis, pairs, input.spectrum, input.separation,
                                input.modal.eigensolver, input);
    if (rank == 0 && !run.memory) // the earlier run's files go, but the realizations it resumes
      prepare_output_directory(directory, route.random ? std::vector<std::string>{"realizations.csv"} :
                                                         std::vector<std::string>{});

    // The peaks: by the spectrum, by Monte Carlo or by one time history.
    Outcome outcome;
    outcome.results = pair_results_before_run(analysis, pairs, input.modal.eigensolver);
    if (route.by_spectrum)
      {
        if (rank != 0)
          return 0;
        outcome.method = spectrum->method;
        fill_from_spectrum(*spectrum, input.separation.modal_combination, outcome.results);
      }
    else if (route.random)
      {
        run_random(input, analysis, pairs, structure, separations, run, hazard, outcome);
        if (rank != 0)
          return outcome.exit_status;
      }
    else
      {
        if (rank != 0)
          return 0;
        run_deterministic(input, analysis, pairs, outcome);
      }
    for (std::size_t p = 0; p < pairs.size(); ++p)
      apply_rules(input.separation, pairs[p], outcome.results[p]);

    // The output (rank 0).
    write_results(run, input, analysis, pairs, route, outcome,
                  spectrum ? &*spectrum : nullptr, hazard);
    print_outcome(pcout, run, input, pairs, route, outcome, hazard);
    return outcome.exit_status;
  }
} // namespace poundfe::commands
