// `poundfe site-hazard FILE`: the site intensity and PGA of each event of a
// catalogue (hazard/catalogue.h reads and fits it; hazard/site_hazard.h has
// the formulas and their sources), the annual rate of exceeding each
// intensity, a Gumbel or Poisson fit, the intensity and PGA of chosen return
// periods and, with a fragility, the annual probability of failure. Writes
// hazard.csv, hazard_curve.csv, return_periods.csv, hazard.png and summary.json.
#include <poundfe/base/input_file.h>
#include <poundfe/base/numbers.h>
#include <poundfe/commands/command.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/excitation/ground_motion.h>
#include <poundfe/hazard/catalogue.h>
#include <poundfe/hazard/site_study.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/output/append_file.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/plots.h>

#include <deal.II/base/conditional_ostream.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>

namespace poundfe::commands
{
  namespace
  {
    void
    write_events(const CommandRun &run, const std::vector<SiteEvent> &events)
    {
      std::string csv = "date,year,latitude_deg,longitude_deg,magnitude,distance_km,intensity,"
                        "pga_cm_s2,pga_g,annual_rate_of_exceeding_per_year\n";
      for (const SiteEvent &s : events)
        {
          csv += s.event.date + "," + std::to_string(s.event.year);
          for (const double x : {s.event.epicentre.latitude, s.event.epicentre.longitude,
                                 s.event.magnitude, s.distance_km, s.intensity,
                                 trifunac_brady_acceleration(s.intensity), trifunac_brady_pga_g(s.intensity)})
            {
              csv += ",";
              append_number(csv, x);
            }
          csv += ",";
          if (s.annual_rate >= 0) // empty: below the minimum intensity
            append_number(csv, s.annual_rate);
          csv += "\n";
        }
      write_result_text(run.memory, run.directory, "hazard.csv", csv);
    }

    void
    write_curve(const CommandRun &run, const IntensityHazard &hazard, const double low,
                const double high)
    {
      std::string csv = "intensity,pga_cm_s2,pga_g,annual_rate_per_year,"
                        "annual_exceedance_probability,return_period_years\n";
      const unsigned int n = 200;
      for (unsigned int k = 0; k <= n; ++k)
        {
          const double x = low + (high - low) * k / n;
          for (const double v :
               {x, trifunac_brady_acceleration(x), trifunac_brady_pga_g(x), hazard.annual_rate(x),
                hazard.annual_exceedance_probability(x), hazard.return_period(x)})
            {
              append_number(csv, v);
              csv += ",";
            }
          csv.back() = '\n';
        }
      write_result_text(run.memory, run.directory, "hazard_curve.csv", csv);
    }

    void
    write_return_periods(const CommandRun &run, const std::vector<double> &periods,
                         const IntensityHazard &hazard)
    {
      std::string csv = "return_period_years,intensity,pga_cm_s2,pga_g,pga_m_s2,"
                        "annual_rate_per_year\n";
      for (const double T : periods)
        {
          const double x = hazard.intensity_for_return_period(T);
          for (const double v : {T, x, trifunac_brady_acceleration(x), trifunac_brady_pga_g(x),
                                 trifunac_brady_acceleration(x) / 100, hazard.annual_rate(x)})
            {
              append_number(csv, v);
              csv += ",";
            }
          csv.back() = '\n';
        }
      write_result_text(run.memory, run.directory, "return_periods.csv", csv);
    }

    Plot
    hazard_plot(const IntensityHazard &hazard, const SiteHazardParameters &p)
    {
      // the site the rates belong to, in the title
      const std::string site = rounded(std::abs(p.site.latitude), 5) +
                               (p.site.latitude < 0 ? " S, " : " N, ") +
                               rounded(std::abs(p.site.longitude), 5) +
                               (p.site.longitude < 0 ? " W" : " E");
      const std::string fit = hazard.model == IntensityHazard::Model::gumbel ?
                                "Gumbel fit of the annual maxima" :
                                "Poisson fit (exponential in intensity)";
      Plot by_intensity{"hazard.png", "Site hazard at " + site + ": annual rate of exceedance",
                        "site intensity I (Cornell)", "annual rate of exceedance (1/year)",
                        {{"hazard.csv", "7:10", "catalogue (events with I >= x per year)",
                          "points pt 7 ps 1.2"},
                         {"hazard_curve.csv", "1:4", fit, "lines lw 2"},
                         {"return_periods.csv", "2:6", "chosen return periods",
                          "points pt 4 ps 1.6"}}};
      by_intensity.log_y = true;
      Plot by_pga{"", "", "PGA (g, Trifunac-Brady)", "annual rate of exceedance (1/year)",
                  {{"hazard.csv", "9:10", "catalogue", "points pt 7 ps 1.2"},
                   {"hazard_curve.csv", "3:4", fit, "lines lw 2"},
                   {"return_periods.csv", "4:6", "chosen return periods", "points pt 4 ps 1.6"}}};
      by_pga.log_y       = true;
      by_intensity.below = {by_pga};
      return by_intensity;
    }

    void
    write_summary(JsonWriter &json, const InputParameters &input, const ObservationPeriod &period,
                  const std::vector<CatalogueEvent> &catalogue,
                  const std::vector<SiteEvent> &events, const IntensityHazard &hazard)
    {
      const SiteHazardParameters &p = input.site_hazard;
      unsigned int                n_counted = 0;
      for (const SiteEvent &s : events)
        n_counted += s.annual_rate >= 0;
      json.begin_object("site")
        .value("latitude_deg", p.site.latitude)
        .value("longitude_deg", p.site.longitude)
        .end_object();
      json.begin_object("catalogue")
        .value("file", p.catalogue_file)
        .value("events", static_cast<unsigned int>(catalogue.size()))
        .value("events_within_maximum_distance", static_cast<unsigned int>(events.size()))
        .value("events_counted", n_counted)
        .value("first_year", period.first)
        .value("last_year", period.last)
        .value("years", period.years())
        .end_object();
      json.begin_object("attenuation")
        .value("distance", "great circle, haversine on a sphere of R = 6371.0 km")
        .value("intensity", "Cornell (1968): I = 8.0 + 1.5 M - 2.5 ln r, r in km")
        .value("acceleration", "Trifunac-Brady (1975): log10 A_h = 0.014 + 0.30 I, cm/s^2")
        .value("focal_depth_km", p.focal_depth)
        .value("minimum_intensity", p.minimum_intensity)
        .end_object();
      json.begin_object("fit").value("model", hazard_model_names().name(hazard.model));
      if (hazard.model == IntensityHazard::Model::gumbel)
        json.value("estimator", "maximum likelihood, years without a counted event censored")
          .value("location", hazard.gumbel.location)
          .value("scale", hazard.gumbel.scale)
          .value("location_standard_error", hazard.gumbel.location_standard_error)
          .value("scale_standard_error", hazard.gumbel.scale_standard_error)
          .value("log_likelihood", hazard.gumbel.log_likelihood)
          .value("years_with_a_maximum", hazard.gumbel.n_observed)
          .value("censored_years", hazard.gumbel.n_censored);
      else
        json.value("estimator", "Aki (1965) maximum likelihood")
          .value("rate_above_minimum_per_year", hazard.poisson.rate_above_threshold)
          .value("b_per_intensity_unit", hazard.poisson.b)
          .value("b_standard_error", hazard.poisson.b_standard_error)
          .value("events", hazard.poisson.n_events);
      json.end_object();
      json.begin_array("return_periods");
      for (const double T : p.return_periods)
        {
          const double x = hazard.intensity_for_return_period(T);
          const double a = trifunac_brady_acceleration(x);
          json.begin_object()
            .value("return_period_years", T)
            .value("intensity", x)
            .value("pga_cm_s2", a)
            .value("pga_m_s2", a / 100)
            .value("pga_g", a / 100 / standard_gravity)
            .value("annual_exceedance_probability", hazard.annual_exceedance_probability(x))
            .end_object();
        }
      json.end_array();
    }
    void
    write_convolution(JsonWriter &json, const InputParameters &input, const Convolution &c)
    {
      const SiteHazardParameters &p = input.site_hazard;
      json.begin_object("fragility")
        .value("source", p.fragility_file.empty() ? std::string("Median PGA and Beta") :
                                                    p.fragility_file + " (" + p.fragility_curve + ")")
        .value("theta_g", c.fragility.theta)
        .value("beta", c.fragility.beta)
        .value("minimum_pga_g", c.minimum_pga)
        .value("annual_failure_rate", c.annual_failure_rate)
        .value("exposure_years", p.exposure_years)
        .value("probability_over_exposure", c.probability)
        .end_object();
    }

    void
    print_report(const dealii::ConditionalOStream &out, const InputParameters &input, const ObservationPeriod &period,
                 const std::vector<CatalogueEvent> &catalogue,
                 const std::vector<SiteEvent> &events, const IntensityHazard &hazard,
                 const std::optional<Convolution> &failure)
    {
      const SiteHazardParameters &p = input.site_hazard;
      std::ostringstream          text;
      text.precision(3);
      text << events.size() << " of " << catalogue.size() << " events within the distance, "
           << period.years() << " years (" << period.first << "-" << period.last << "); "
           << hazard_model_names().name(hazard.model) << " fit: ";
      if (hazard.model == IntensityHazard::Model::gumbel)
        text << "u = " << hazard.gumbel.location << " +- " << hazard.gumbel.location_standard_error
             << ", s = " << hazard.gumbel.scale << " +- " << hazard.gumbel.scale_standard_error
             << "\n";
      else
        text << "nu0 = " << hazard.poisson.rate_above_threshold << "/year above I = "
             << p.minimum_intensity << ", b = " << hazard.poisson.b << " +- "
             << hazard.poisson.b_standard_error << "\n";
      for (const double T : p.return_periods)
        {
          const double x = hazard.intensity_for_return_period(T);
          text << "  T = " << T << " years: I = " << x << ", PGA = " << trifunac_brady_pga_g(x) << " g ("
               << trifunac_brady_acceleration(x) / 100 << " m/s^2)\n";
        }
      if (failure)
        text << "fragility theta = " << failure->fragility.theta
             << " g, beta = " << failure->fragility.beta << ": annual rate of failure "
             << failure->annual_failure_rate << ", probability in " << p.exposure_years
             << " years " << failure->probability << "\n";
      out << text.str();
    }

    /// hazard.csv, hazard_curve.csv, return_periods.csv and hazard.png of a
    /// catalogue; returns the names written.
    std::vector<std::string>
    write_catalogue_outputs(const CommandRun &run, const SiteHazardOfCatalogue &site)
    {
      const InputParameters      &input     = *run.input;
      const std::string          &directory = run.directory;
      const SiteHazardParameters &p = input.site_hazard;
      double top = p.minimum_intensity + 1;
      for (const SiteEvent &s : site.events)
        top = std::max(top, s.intensity);
      for (const double T : p.return_periods)
        top = std::max(top, site.hazard.intensity_for_return_period(T));
      write_events(run, site.events);
      write_curve(run, site.hazard, p.minimum_intensity, top + 0.5);
      write_return_periods(run, p.return_periods, site.hazard);
      std::vector<std::string> files{"hazard.csv", "hazard_curve.csv", "return_periods.csv"};
      if (run.memory) // no figure
        return files;
      if (input.output.plots)
        for (const std::string &png : draw_plots(directory, {hazard_plot(site.hazard, p)}))
          files.push_back(png);
      else
        std::remove((directory + "/hazard.png").c_str()); // not an earlier run's
      return files;
    }

    const char *
    scale_name(const IntensityScale scale)
    {
      return scale == IntensityScale::isc ? "isc" : "jma";
    }

    void
    write_study(const CommandRun &run, const SiteStudyResult &study)
    {
      std::string csv = "method,scale,return_period_years,intensity,acceleration_gal,"
                        "coefficient_k\n";
      for (const SiteStudyRow &row : study.rows)
        {
          csv += row.entry.method + "," + scale_name(row.entry.scale);
          for (const double x : {row.entry.return_period, row.entry.intensity,
                                 row.acceleration_gal, row.coefficient})
            {
              csv += ",";
              append_number(csv, x);
            }
          csv += "\n";
        }
      write_result_text(run.memory, run.directory, "site_study.csv", csv);
    }

    void
    write_study_summary(JsonWriter &json, const SiteStudyResult &study)
    {
      json.begin_object("site_study");
      json.begin_array("rows");
      for (const SiteStudyRow &row : study.rows)
        json.begin_object()
          .value("method", row.entry.method)
          .value("scale", std::string(scale_name(row.entry.scale)))
          .value("return_period_years", row.entry.return_period)
          .value("intensity", row.entry.intensity)
          .value("acceleration_gal", row.acceleration_gal)
          .value("coefficient_k", row.coefficient)
          .end_object();
      json.end_array();
      json.begin_array("design_coefficients");
      for (const DesignCoefficient &c : study.coefficients)
        json.begin_object()
          .value("return_period_years", c.return_period)
          .value("largest_k", c.coefficient)
          .value("k", c.rounded)
          .end_object();
      json.end_array();
      json.begin_object("design_earthquakes")
        .value("service_life_return_period_years", study.design.service_life_return_period)
        .value("obe_return_period_years", study.design.obe_return_period)
        .value("obe_g", study.design.obe_g)
        .value("mce_g", study.design.mce_g)
        .end_object();
      json.end_object();
    }

    void
    print_study(const dealii::ConditionalOStream &out, const SiteStudyResult &study)
    {
      std::ostringstream text;
      text.precision(3);
      text << "site study (earthquake coefficient k = A/g):\n";
      for (const SiteStudyRow &row : study.rows)
        text << "  " << row.entry.method << " (" << scale_name(row.entry.scale) << ") T = "
             << row.entry.return_period << " years: I = " << row.entry.intensity
             << ", A = " << row.acceleration_gal << " gal, k = " << row.coefficient << "\n";
      for (const DesignCoefficient &c : study.coefficients)
        text << "  T = " << c.return_period << " years: k = " << c.rounded << " (largest "
             << c.coefficient << ")\n";
      text << "  OBE (T = " << study.design.obe_return_period << " years; the service life's "
           << study.design.service_life_return_period << "): " << study.design.obe_g
           << " g; MCE " << study.design.mce_g << " g\n";
      out << text.str();
    }
  } // namespace

  int
  site_hazard(const CommandRun &run)
  {
    const InputParameters     &input     = *run.input;
    const std::string         &directory = run.directory;
    const SiteHazardParameters &p        = input.site_hazard;
    p.require(input);
    // Everything read and checked before any file is written.
    std::optional<SiteHazardOfCatalogue> site;
    if (!p.catalogue_file.empty())
      site = site_hazard_of_catalogue(p, input);
    std::optional<SiteStudyResult> study;
    if (p.study.given())
      study = site_study(p.study.entries(input, site ? &site->hazard : nullptr),
                         p.study.settings);

    if (!run.memory)
      create_directories(directory);
    std::vector<std::string> files;
    if (site)
      files = write_catalogue_outputs(run, *site);
    if (study)
      {
        write_study(run, *study);
        files.push_back("site_study.csv");
      }
    files.push_back("summary.json");
    JsonWriter json;
    begin_summary(json, "site-hazard", input);
    if (site)
      {
        write_summary(json, input, site->period, site->catalogue, site->events, site->hazard);
        if (site->failure)
          write_convolution(json, input, *site->failure);
      }
    if (study)
      write_study_summary(json, *study);
    json.begin_object("output").value("files", files).end_object();
    json.end_object();
    write_result_text(run.memory, directory, "summary.json", json.str());
    const dealii::ConditionalOStream pcout(run.out, writes_outputs());
    if (site)
      print_report(pcout, input, site->period, site->catalogue, site->events, site->hazard,
                   site->failure);
    if (study)
      print_study(pcout, *study);
    pcout << "results in " << run.results_place() << " (summary.json lists the files)\n";
    return 0;
  }
} // namespace poundfe::commands
