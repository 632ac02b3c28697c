// A catalogue's site hazard: the catalogue (a CSV of dated epicentres and
// magnitudes) and the fragility summary.json of `poundfe fragility`, read
// and checked; each event's distance and site intensity, the empirical
// annual rate of exceeding each counted intensity, the Gumbel or Poisson
// fit and, with a fragility, its convolution with the hazard
// (hazard/site_hazard.h has the formulas and their sources).
#ifndef poundfe_hazard_catalogue_h
#define poundfe_hazard_catalogue_h

#include <poundfe/base/input_file.h>
#include <poundfe/hazard/site_hazard.h>
#include <poundfe/hazard/site_hazard_parameters.h>

#include <optional>
#include <string>
#include <vector>

namespace poundfe
{
  /// One row of a catalogue.
  struct CatalogueEvent
  {
    std::string     date;  // as written
    int             year = 0;
    GeographicPoint epicentre{};
    double          magnitude = 0;
    int             line = 0; // in the catalogue file, for messages
  };

  /// Read a catalogue CSV (format: SiteHazardParameters' Catalogue file).
  /// Throws InputError naming `file`, the line and what is wrong.
  std::vector<CatalogueEvent> read_catalogue(const std::string &file);

  /// theta (g) and beta of the curve named `curve` in a summary.json written
  /// by `poundfe fragility`. Throws InputError.
  LognormalCurve read_fragility_summary(const std::string &file, const std::string &curve);

  /// An event with its site values.
  struct SiteEvent
  {
    CatalogueEvent event;
    double         distance_km = 0, intensity = 0;
    double         annual_rate = -1; // of exceeding its intensity; < 0: not counted
  };

  /// The observation period, in whole years.
  struct ObservationPeriod
  {
    int first = 0, last = 0;
    int years() const { return last - first + 1; }
  };

  /// A fragility convolved with the hazard.
  struct Convolution
  {
    LognormalCurve fragility;
    double         minimum_pga = 0;          // g
    double         annual_failure_rate = 0;  // lambda_F, 1/year
    double         probability = 0;          // over the exposure
  };

  /// The site hazard of Site hazard/Catalogue file.
  struct SiteHazardOfCatalogue
  {
    std::string                 file; // the catalogue's path
    std::vector<CatalogueEvent> catalogue;
    ObservationPeriod           period;
    std::vector<SiteEvent>      events; // within the maximum distance
    IntensityHazard             hazard;
    std::optional<Convolution>  failure; // with a fragility
  };

  /// Reads the catalogue (and the fragility file) that `parameters` name
  /// (paths relative to `input`), and computes the site hazard. Throws
  /// InputError naming the file, line and parameter of what is wrong.
  SiteHazardOfCatalogue site_hazard_of_catalogue(const SiteHazardParameters &parameters,
                                                 const InputFile            &input);
} // namespace poundfe

#endif
