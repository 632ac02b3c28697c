// The readers of `poundfe site-hazard FILE` (source/commands/site_hazard.cc): the site intensity and PGA of each event of a
// catalogue (hazard/site_hazard.h has the formulas and their sources), the
// annual rate of exceeding each intensity, a Gumbel or Poisson fit, the
// intensity and PGA of chosen return periods and, with a fragility, the
// annual probability of failure. Writes hazard.csv, hazard_curve.csv,
// return_periods.csv, hazard.png and summary.json.
#ifndef poundfe_commands_site_hazard_h
#define poundfe_commands_site_hazard_h

#include <poundfe/hazard/site_hazard.h>

#include <string>
#include <vector>

namespace poundfe
{
  struct InputParameters;

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
} // namespace poundfe

#endif
