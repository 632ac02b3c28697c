// A catalogue's site hazard (formulas and sources in site_hazard.h): the
// catalogue and fragility-summary readers, the events' site intensities,
// their annual exceedance rates and the Gumbel or Poisson fit.
#include <poundfe/hazard/catalogue.h>
#include <poundfe/hazard/site_study.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/input_text.h>
#include <poundfe/base/numbers.h>
#include <poundfe/excitation/ground_motion.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>

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

    ObservationPeriod
    observation_period(const SiteHazardParameters &p, const InputFile &input,
                       const std::vector<CatalogueEvent> &events, const std::string &file)
    {
      ObservationPeriod           period{p.first_year, p.last_year};
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
    site_events(const SiteHazardParameters &p, const std::vector<CatalogueEvent> &events,
                const std::string &file, const ObservationPeriod &period)
    {
      std::vector<SiteEvent>      site;
      for (const CatalogueEvent &e : events)
        {
          const double delta = great_circle_distance_km(p.site, e.epicentre);
          if (p.maximum_distance > 0 && delta > p.maximum_distance)
            continue;
          const double r = std::hypot(delta, p.focal_depth);
          if (r < 1.0)
            throw InputError(file, e.line, catalogue_parameter,
                             "the event of " + e.date + " is " + number_text(r) +
                               " km from the site: Cornell's ln r needs r >= 1 km (give a "
                               "Focal depth)");
          // rounded as a printed table is (Intensity decimals) before A_h
          site.push_back({e, delta,
                          rounded_to_decimals(cornell_intensity(e.magnitude, r),
                                              p.intensity_decimals)});
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
    fit_hazard(const SiteHazardParameters &p, const InputFile &input,
               const std::vector<SiteEvent> &events, const ObservationPeriod &period)
    {
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

    std::optional<Convolution>
    convolve(const SiteHazardParameters &p, const InputFile &input, const IntensityHazard &hazard)
    {
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

  } // namespace

  namespace
  {
    /// The columns of date, latitude, longitude and magnitude in a
    /// catalogue's header row `fields` (line `number` of `file`).
    std::vector<int>
    catalogue_columns(const std::string &file, const int number,
                      const std::vector<std::string> &fields)
    {
      const std::vector<std::string> required{"date", "latitude", "longitude", "magnitude"};
      std::vector<int>               column(required.size(), -1);
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
      return column;
    }

    /// The event of a catalogue's row `fields` (line `number` of `file`),
    /// its date, epicentre and magnitude checked.
    CatalogueEvent
    catalogue_event(const std::string &file, const int number,
                    const std::vector<std::string> &fields, const std::vector<int> &column)
    {
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
      // A negative magnitude is a micro-earthquake, never felt at a site:
      // in a hazard catalogue it is a typing error; none on
      // Earth has reached 10.
      if (!(e.magnitude >= 0 && e.magnitude < 10))
        throw InputError(file, number, catalogue_parameter,
                         "magnitude '" + fields[column[3]] + "' is not a number in [0, 10)");
      return e;
    }
  } // namespace

  std::vector<CatalogueEvent>
  read_catalogue(const std::string &file)
  {
    std::istringstream in(read_input_text(file, "catalogue", catalogue_parameter));
    std::vector<int>            column;
    std::size_t                 n_fields = 0;
    std::vector<CatalogueEvent> events;
    std::string                 line;
    for (int number = 1; std::getline(in, line); ++number)
      {
        line = trimmed(line);
        if (line.empty() || line[0] == '#')
          continue;
        const std::vector<std::string> fields = split_fields(line);
        if (n_fields == 0) // the header
          {
            n_fields = fields.size();
            column   = catalogue_columns(file, number, fields);
            continue;
          }
        if (fields.size() != n_fields)
          throw InputError(file, number, catalogue_parameter,
                           "a row of " + std::to_string(fields.size()) + " fields; the header has " +
                             std::to_string(n_fields));
        events.push_back(catalogue_event(file, number, fields, column));
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
        std::istringstream in(read_json_text(file, "fragility file", parameter));
        boost::property_tree::read_json(in, tree);
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


  SiteHazardOfCatalogue
  site_hazard_of_catalogue(const SiteHazardParameters &parameters, const InputFile &input)
  {
    SiteHazardOfCatalogue result;
    result.file      = input.resolve(parameters.catalogue_file);
    result.catalogue = read_catalogue(result.file);
    result.period    = observation_period(parameters, input, result.catalogue, result.file);
    result.events    = site_events(parameters, result.catalogue, result.file, result.period);
    result.hazard    = fit_hazard(parameters, input, result.events, result.period);
    result.failure   = convolve(parameters, input, result.hazard);
    return result;
  }
} // namespace poundfe
