#include <poundfe/hazard/site_study_parameters.h>
#include <poundfe/base/numbers.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <sstream>

namespace poundfe
{
  namespace Patterns = dealii::Patterns;

  namespace
  {
    const std::string section = "Site hazard/Site study/";

    IntensityScale
    scale_of(const std::string &name, const InputFile &input, const std::string &entry)
    {
      if (name == "isc")
        return IntensityScale::isc;
      if (name == "jma")
        return IntensityScale::jma;
      input.fail(section + "Intensities",
                 "entry '" + entry + "': scale '" + name + "' is neither isc nor jma");
    }

    /// An intensity inside its scale: a value outside is a typing error.
    void
    check_on_scale(const SiteStudyEntry &e, const InputFile &input, const std::string &path,
                   const std::string &what)
    {
      const double low = intensity_scale_minimum(e.scale), high = intensity_scale_maximum(e.scale);
      if (!(e.intensity >= low && e.intensity <= high))
        input.fail(path, what + ": intensity " + number_text(e.intensity) + " is outside the " +
                           (e.scale == IntensityScale::isc ? "ISC" : "JMA") + " scale [" +
                           number_text(low) + ", " + number_text(high) + "]");
    }
  } // namespace

  void
  SiteStudyParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Site study");
    prm.add_parameter("Intensities", intensities,
                      "Site intensities of return periods 'method scale T I', separated by "
                      "';', e.g. 'ISC isc 100 2.5; JMA jma 250 3'. method: a label without "
                      "blanks; scale: isc (I to XII, A = 10^(0.014 + 0.30 I) gal) or jma (0 "
                      "to 7, a = 0.45 10^(S/2) gal); T in years. Unit: per field.",
                      Patterns::List(Patterns::Anything(), 0, 1000, ";"));
    prm.add_parameter("Return periods", return_periods,
                      "Years (each > 1) at which the intensity-frequency relation and the "
                      "catalogue's fit give an ISC intensity. Unit: years.",
                      Patterns::List(Patterns::Double(0), 1, 100, ","));
    prm.add_parameter("Relation a", relation_a,
                      "a of log10 N_c(I) = a - b I, N_c the annual number of site events of "
                      "ISC intensity >= I. Unit: dimensionless.");
    prm.add_parameter("Relation b", relation_b,
                      "b of the intensity-frequency relation (0: none). Unit: dimensionless "
                      "(per intensity unit).",
                      Patterns::Double(0));
    prm.add_parameter("From catalogue", from_catalogue,
                      "Also the ISC intensities of the Return periods from the catalogue's "
                      "Gumbel or Poisson fit (needs a Catalogue file). Unit: -.");
    prm.add_parameter("Gravity", settings.gravity,
                      "g of the earthquake coefficient k = A/g (the thesis's k = A/980 gal: "
                      "9.80). Unit: m/s^2.",
                      Patterns::Double(0));
    prm.add_parameter("Coefficient decimals", settings.coefficient_decimals,
                      "The design k (the largest of a return period's methods) is rounded to "
                      "this many decimals (-1: not rounded). Unit: count.",
                      Patterns::Integer(-1, 6));
    prm.add_parameter("Service life", settings.service_life,
                      "L of the OBE's probability of exceedance. Unit: years.",
                      Patterns::Double(0));
    prm.add_parameter("Exceedance probability", settings.exceedance_probability,
                      "p of the OBE in the service life: T = -L/ln(1 - p) (Poisson; 144.3 "
                      "years for 50 % in 100). Unit: dimensionless.",
                      Patterns::Double(0, 1));
    prm.add_parameter("OBE return period", settings.obe_return_period,
                      "The return period whose design k is the OBE (0: the service life's "
                      "T; a conservative study takes a longer one, the thesis 250). Unit: "
                      "years.",
                      Patterns::Double(0));
    prm.add_parameter("MCE factor", settings.mce_factor,
                      "MCE = factor x OBE (the thesis: 2). Unit: dimensionless.",
                      Patterns::Double(0));
    prm.leave_subsection();
  }

  std::vector<SiteStudyEntry>
  SiteStudyParameters::typed_entries(const InputFile &input) const
  {
    std::vector<SiteStudyEntry> entries;
    const std::string           path = section + "Intensities";
    for (const std::string &text : intensities)
      {
        std::istringstream       in(text);
        std::vector<std::string> fields;
        for (std::string field; in >> field;)
          fields.push_back(field);
        if (fields.size() != 4)
          input.fail(path, "entry '" + text + "' has " + std::to_string(fields.size()) +
                             " fields; it needs 'method scale T I'");
        SiteStudyEntry e;
        e.method = fields[0];
        e.scale  = scale_of(fields[1], input, text);
        const std::optional<double> T = parse_number(fields[2]), I = parse_number(fields[3]);
        if (!T || !(*T > 1) || !std::isfinite(*T))
          input.fail(path, "entry '" + text + "': return period '" + fields[2] +
                             "' is not a number of years > 1");
        if (!I)
          input.fail(path, "entry '" + text + "': intensity '" + fields[3] + "' is not a number");
        e.return_period = *T;
        e.intensity     = *I;
        check_on_scale(e, input, path, "entry '" + text + "'");
        entries.push_back(e);
      }
    return entries;
  }

  void
  SiteStudyParameters::check(const InputFile &input) const
  {
    typed_entries(input);
    for (const double T : return_periods)
      if (!(T > 1) || !std::isfinite(T))
        input.fail(section + "Return periods", "every return period must exceed 1 year");
    input.distinct(section + "Return periods", return_periods);
    if (!std::isfinite(relation_a))
      input.fail(section + "Relation a", "must be finite");
    if (!given())
      return;
    input.positive(section + "Gravity", settings.gravity);
    input.positive(section + "Service life", settings.service_life);
    if (!(settings.exceedance_probability > 0 && settings.exceedance_probability < 1))
      input.fail(section + "Exceedance probability", "must lie strictly between 0 and 1");
    if (settings.obe_return_period != 0 && !(settings.obe_return_period > 1))
      input.fail(section + "OBE return period", "must exceed 1 year (or be 0)");
    input.positive(section + "MCE factor", settings.mce_factor);
  }

  std::vector<SiteStudyEntry>
  SiteStudyParameters::entries(const InputFile &input, const IntensityHazard *catalogue) const
  {
    if (from_catalogue && catalogue == nullptr)
      input.fail(section + "From catalogue", "needs a Site hazard/Catalogue file");
    std::vector<SiteStudyEntry> result  = typed_entries(input);
    std::vector<double>         periods = return_periods;
    const double                obe_period =
      settings.obe_return_period > 0 ?
        settings.obe_return_period :
        return_period_of_exceedance(settings.service_life, settings.exceedance_probability);
    const auto same_period = [](const double T, const double U) {
      return std::abs(T - U) <= 1e-9 * U;
    };
    bool listed = false;
    for (const double T : return_periods)
      listed = listed || same_period(T, obe_period);
    if (!listed)
      periods.push_back(obe_period);
    const auto add = [&](const std::string &method, const double T, const double I,
                         const std::string &path) {
      const SiteStudyEntry e{method, IntensityScale::isc, T, I};
      check_on_scale(e, input, path, method + " at " + number_text(T) + " years");
      result.push_back(e);
    };
    for (const double T : periods)
      {
        if (relation_b > 0)
          add("N_c", T, IntensityFrequencyRelation{relation_a, relation_b}
                          .intensity_for_return_period(T), section + "Relation b");
        if (from_catalogue && catalogue != nullptr)
          add("catalogue", T, catalogue->intensity_for_return_period(T),
              section + "From catalogue");
      }
    bool obe_found = false;
    for (const SiteStudyEntry &e : result)
      obe_found = obe_found || same_period(e.return_period, obe_period);
    if (!obe_found)
      input.fail(section + "OBE return period",
                 "no method gives an intensity at the OBE's return period of " +
                   number_text(obe_period) + " years (type one in Intensities, or give a "
                   "Relation b or From catalogue)");
    return result;
  }
} // namespace poundfe
