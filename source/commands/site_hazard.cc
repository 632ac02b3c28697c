#include <poundfe/dynamics/analysis.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/commands/command.h>
#include <poundfe/commands/site_hazard.h>
#include <poundfe/input/sweep.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/excitation/ground_motion.h>
#include <poundfe/output/append_file.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/plots.h>

// property_tree includes boost/bind.hpp, which asks for this (a note at every build)
#define BOOST_BIND_GLOBAL_PLACEHOLDERS
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <regex>
#include <sstream>

namespace poundfe
{
  namespace
  {
    const char *catalogue_parameter = "Site hazard/Catalogue file";

    std::vector<std::string>
    split_fields(const std::string &line)
    {
      std::vector<std::string> fields;
      std::stringstream        in(line);
      std::string              field;
      while (std::getline(in, field, ','))
        fields.push_back(trimmed(field));
      if (!line.empty() && line.back() == ',')
        fields.push_back("");
      return fields;
    }

    /// The year of YYYY, YYYY-MM or YYYY-MM-DD; 0 when the text is none of these.
    int
    year_of(const std::string &date)
    {
      static const std::regex format("^([0-9]{4})(-([0-9]{2})(-([0-9]{2}))?)?$");
      std::smatch             m;
      if (!std::regex_match(date, m, format))
        return 0;
      const int month = m[3].matched ? std::stoi(m[3]) : 1;
      const int day   = m[5].matched ? std::stoi(m[5]) : 1;
      if (month < 1 || month > 12 || day < 1 || day > 31)
        return 0;
      return std::stoi(m[1]);
    }

    /// The number in `text`, or NaN when it is not one.
    double
    number_in(const std::string &text)
    {
      char        *end   = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value))
        return std::nan("");
      return value;
    }

    /// An event with its site values.
    struct SiteEvent
    {
      CatalogueEvent event;
      double         distance_km = 0, intensity = 0;
      double         annual_rate = -1; // of exceeding its intensity; < 0: not counted
    };

    /// The observation period, in whole years.
    struct Period
    {
      int first = 0, last = 0;
      int years() const { return last - first + 1; }
    };

    Period
    observation_period(const InputParameters &input, const std::vector<CatalogueEvent> &events,
                       const std::string &file)
    {
      const SiteHazardParameters &p = input.site_hazard;
      Period                      period{p.first_year, p.last_year};
      for (const CatalogueEvent &e : events)
        {
          if (p.first_year == 0)
            period.first = period.first == 0 ? e.year : std::min(period.first, e.year);
          if (p.last_year == 0)
            period.last = std::max(period.last, e.year);
        }
      if (period.last < period.first)
        input.fail("Site hazard/Last year", "is before the first year of the catalogue, " +
                                              std::to_string(period.first));
      for (const CatalogueEvent &e : events)
        if (e.year < period.first || e.year > period.last)
          throw InputError(file, e.line, catalogue_parameter,
                           "the event of " + e.date + " is outside the observation period " +
                             std::to_string(period.first) + "-" + std::to_string(period.last) +
                             " (First year, Last year)");
      return period;
    }

    /// Distances and intensities of the events within the maximum distance,
    /// and the empirical annual rate of exceeding each counted intensity.
    std::vector<SiteEvent>
    site_events(const InputParameters &input, const std::vector<CatalogueEvent> &events,
                const std::string &file, const Period &period)
    {
      const SiteHazardParameters &p = input.site_hazard;
      std::vector<SiteEvent>      site;
      for (const CatalogueEvent &e : events)
        {
          const double delta = great_circle_distance_km(p.site, e.epicentre);
          if (p.maximum_distance > 0 && delta > p.maximum_distance)
            continue;
          const double r = std::hypot(delta, p.focal_depth);
          if (r < 1.0)
            throw InputError(file, e.line, catalogue_parameter,
                             "the event of " + e.date + " is " + format_value(r) +
                               " km from the site: Cornell's ln r needs r >= 1 km (give a "
                               "Focal depth)");
          site.push_back({e, delta, cornell_intensity(e.magnitude, r)});
        }
      // rate of exceeding x: the number of counted events with I >= x per year
      std::vector<double> counted;
      for (const SiteEvent &s : site)
        if (s.intensity >= p.minimum_intensity)
          counted.push_back(s.intensity);
      std::sort(counted.begin(), counted.end());
      for (SiteEvent &s : site)
        if (s.intensity >= p.minimum_intensity)
          s.annual_rate =
            double(counted.end() - std::lower_bound(counted.begin(), counted.end(), s.intensity)) /
            period.years();
      return site;
    }

    IntensityHazard
    fit_hazard(const InputParameters &input, const std::vector<SiteEvent> &events,
               const Period &period)
    {
      const SiteHazardParameters &p = input.site_hazard;
      IntensityHazard             hazard;
      hazard.model = p.fit;
      try
        {
          if (p.fit == IntensityHazard::Model::gumbel)
            {
              std::map<int, double> maxima; // year -> largest counted intensity
              for (const SiteEvent &s : events)
                if (s.intensity >= p.minimum_intensity)
                  {
                    auto it = maxima.emplace(s.event.year, s.intensity).first;
                    it->second = std::max(it->second, s.intensity);
                  }
              std::vector<double> values;
              for (const auto &[year, x] : maxima)
                values.push_back(x);
              hazard.gumbel =
                fit_gumbel(values, period.years() - values.size(), p.minimum_intensity);
            }
          else
            {
              std::vector<double> values;
              for (const SiteEvent &s : events)
                values.push_back(s.intensity);
              hazard.poisson =
                fit_exponential_recurrence(values, p.minimum_intensity, period.years());
            }
        }
      catch (const std::invalid_argument &e)
        {
          input.fail("Site hazard/Fit", std::string(e.what()) + " (events within the maximum "
                                        "distance with intensity >= the Minimum intensity)");
        }
      return hazard;
    }

    void
    write_events(const std::string &path, const std::vector<SiteEvent> &events)
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
      write_file_atomically(path, csv);
    }

    void
    write_curve(const std::string &path, const IntensityHazard &hazard, const double low,
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
      write_file_atomically(path, csv);
    }

    void
    write_return_periods(const std::string &path, const std::vector<double> &periods,
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
      write_file_atomically(path, csv);
    }

    Plot
    hazard_plot(const IntensityHazard &hazard)
    {
      const std::string fit = hazard.model == IntensityHazard::Model::gumbel ?
                                "Gumbel fit of the annual maxima" :
                                "Poisson fit (exponential in intensity)";
      Plot by_intensity{"hazard.png", "Site hazard: annual rate of exceedance",
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
    write_summary(JsonWriter &json, const InputParameters &input, const Period &period,
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
    /// A fragility convolved with the hazard.
    struct Convolution
    {
      LognormalCurve fragility;
      double         minimum_pga = 0;          // g
      double         annual_failure_rate = 0;  // lambda_F, 1/year
      double         probability = 0;          // over the exposure
    };

    std::optional<Convolution>
    convolve(const InputParameters &input, const IntensityHazard &hazard)
    {
      const SiteHazardParameters &p = input.site_hazard;
      if (!p.has_fragility())
        return std::nullopt;
      Convolution c;
      c.fragility = p.fragility_median > 0 ?
                      LognormalCurve{p.fragility_median, p.fragility_beta} :
                      read_fragility_summary(input.resolve(p.fragility_file), p.fragility_curve);
      const auto rate_of_pga = [&hazard](const double a_g) { return annual_rate_of_pga(hazard, a_g); };
      c.minimum_pga         = trifunac_brady_pga_g(p.minimum_intensity);
      c.annual_failure_rate = annual_failure_rate(rate_of_pga, c.minimum_pga, c.fragility);
      c.probability         = probability_in_years(c.annual_failure_rate, p.exposure_years);
      return c;
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
    print_report(std::ostream &out, const InputParameters &input, const Period &period,
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
  } // namespace

  std::vector<CatalogueEvent>
  read_catalogue(const std::string &file)
  {
    std::ifstream in(file);
    if (!in)
      throw InputError(file, 0, catalogue_parameter, "cannot open the catalogue");
    const std::vector<std::string> required{"date", "latitude", "longitude", "magnitude"};
    std::vector<int>               column(required.size(), -1);
    std::size_t                    n_fields = 0;
    std::vector<CatalogueEvent>    events;
    std::string                    line;
    for (int number = 1; std::getline(in, line); ++number)
      {
        line = trimmed(line);
        if (line.empty() || line[0] == '#')
          continue;
        std::vector<std::string> fields = split_fields(line);
        if (n_fields == 0) // the header
          {
            n_fields = fields.size();
            for (std::size_t i = 0; i < fields.size(); ++i)
              {
                std::string name = fields[i];
                std::transform(name.begin(), name.end(), name.begin(), ::tolower);
                for (std::size_t c = 0; c < required.size(); ++c)
                  if (name == required[c])
                    column[c] = i;
              }
            for (std::size_t c = 0; c < required.size(); ++c)
              if (column[c] < 0)
                throw InputError(file, number, catalogue_parameter,
                                 "the header has no column '" + required[c] +
                                   "' (it needs date, latitude, longitude, magnitude)");
            continue;
          }
        if (fields.size() != n_fields)
          throw InputError(file, number, catalogue_parameter,
                           "a row of " + std::to_string(fields.size()) + " fields; the header has " +
                             std::to_string(n_fields));
        CatalogueEvent e;
        e.line = number;
        e.date = fields[column[0]];
        e.year = year_of(e.date);
        if (e.year == 0)
          throw InputError(file, number, catalogue_parameter,
                           "date '" + e.date + "' is not YYYY, YYYY-MM or YYYY-MM-DD");
        e.epicentre.latitude  = number_in(fields[column[1]]);
        e.epicentre.longitude = number_in(fields[column[2]]);
        e.magnitude           = number_in(fields[column[3]]);
        if (!(std::abs(e.epicentre.latitude) <= 90))
          throw InputError(file, number, catalogue_parameter,
                           "latitude '" + fields[column[1]] + "' is not a number in [-90, 90]");
        if (!(e.epicentre.longitude >= -180 && e.epicentre.longitude <= 360))
          throw InputError(file, number, catalogue_parameter,
                           "longitude '" + fields[column[2]] + "' is not a number in [-180, 360]");
        if (!(e.magnitude > -3 && e.magnitude < 10))
          throw InputError(file, number, catalogue_parameter,
                           "magnitude '" + fields[column[3]] + "' is not a number in (-3, 10)");
        events.push_back(e);
      }
    if (n_fields == 0)
      throw InputError(file, 0, catalogue_parameter, "the catalogue has no header row");
    if (events.empty())
      throw InputError(file, 0, catalogue_parameter, "the catalogue has no events");
    return events;
  }

  LognormalCurve
  read_fragility_summary(const std::string &file, const std::string &curve)
  {
    const std::string parameter = "Site hazard/Fragility/File";
    boost::property_tree::ptree tree;
    try
      {
        boost::property_tree::read_json(file, tree);
      }
    catch (const boost::property_tree::json_parser_error &e)
      {
        throw InputError(file, e.line(), parameter,
                         "cannot read it as a fragility summary.json: " + e.message());
      }
    if (tree.get<std::string>("command", "") != "fragility")
      throw InputError(file, 0, parameter, "not a summary.json of `poundfe fragility`");
    std::string                       names;
    const boost::property_tree::ptree none;
    for (const auto &[key, c] : tree.get_child("curves", none))
      {
        const std::string name = c.get<std::string>("name", "");
        names += (names.empty() ? "" : ", ") + name;
        if (name != curve)
          continue;
        if (!c.get<bool>("fitted", false))
          throw InputError(file, 0, parameter,
                           "its curve '" + curve + "' was not fitted: " + c.get<std::string>("note", ""));
        const LognormalCurve fragility{c.get<double>("theta_g", 0), c.get<double>("beta", 0)};
        if (!(fragility.theta > 0 && fragility.beta > 0))
          throw InputError(file, 0, parameter, "its curve '" + curve + "' has no theta_g and beta");
        return fragility;
      }
    throw InputError(file, 0, "Site hazard/Fragility/Curve",
                     "no curve '" + curve + "' in the file; it has: " + names);
  }

} // namespace poundfe

namespace poundfe::commands
{
  int
  site_hazard(const CommandRun &run)
  {
    const InputParameters &input     = *run.input;
    const std::string     &directory = run.directory;
    const SiteHazardParameters &p = input.site_hazard;
    p.require(input);
    // Everything read and checked before any file is written.
    const std::string                 file      = input.resolve(p.catalogue_file);
    const std::vector<CatalogueEvent> catalogue = read_catalogue(file);
    const Period                      period    = observation_period(input, catalogue, file);
    const std::vector<SiteEvent>      events    = site_events(input, catalogue, file, period);
    const IntensityHazard             hazard    = fit_hazard(input, events, period);
    const std::optional<Convolution>  failure   = convolve(input, hazard);

    create_directories(directory);
    double top = p.minimum_intensity + 1;
    for (const SiteEvent &s : events)
      top = std::max(top, s.intensity);
    for (const double T : p.return_periods)
      top = std::max(top, hazard.intensity_for_return_period(T));
    write_events(directory + "/hazard.csv", events);
    write_curve(directory + "/hazard_curve.csv", hazard, p.minimum_intensity, top + 0.5);
    write_return_periods(directory + "/return_periods.csv", p.return_periods, hazard);
    std::vector<std::string> files{"hazard.csv", "hazard_curve.csv", "return_periods.csv"};
    if (input.output.plots)
      for (const std::string &png : draw_plots(directory, {hazard_plot(hazard)}))
        files.push_back(png);
    else
      std::remove((directory + "/hazard.png").c_str()); // not an earlier run's
    files.push_back("summary.json");
    JsonWriter json;
    begin_summary(json, "site-hazard", input);
    write_summary(json, input, period, catalogue, events, hazard);
    if (failure)
      write_convolution(json, input, *failure);
    json.begin_object("output").value("files", files).end_object();
    json.end_object();
    write_file_atomically(directory + "/summary.json", json.str());
    print_report(std::cout, input, period, catalogue, events, hazard, failure);
    std::cout << "results in " << directory << "/ (summary.json lists the files)\n";
    return 0;
  }
} // namespace poundfe::commands
