#include <poundfe/output/drift_limits.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace poundfe
{
  namespace
  {
    std::string
    shortest(const double x)
    {
      std::ostringstream s;
      s.precision(6);
      s << x;
      return s.str();
    }
  } // namespace

  const NameTable<DriftCode> &
  drift_code_names()
  {
    static const NameTable<DriftCode> table({{DriftCode::none, "none"},
                                             {DriftCode::asce7, "asce-7"},
                                             {DriftCode::eurocode8, "eurocode-8"}});
    return table;
  }

  void
  DriftLimitParameters::declare(dealii::ParameterHandler &prm)
  {
    namespace Patterns = dealii::Patterns;
    prm.enter_subsection("Drift limits");
    prm.add_parameter("Limits", limits_text,
                      "Peak inter-storey drift ratios to check every storey of every building "
                      "against, as ratios (0.005, 0.01) or percentages (0.5 %, 1 %); empty: "
                      "none. Pass/fail per building and limit in summary.json, lines on "
                      "drift_profile.png. Unit: dimensionless.");
    add_choice(prm, "Code", code,
               "A code's limit checked as well: asce-7 (Table 12.12-1, all other "
               "structures: 0.020/0.015/0.010 for risk categories I-II/III/IV), eurocode-8 "
               "(4.4.3.2 damage limitation: d_r nu <= 0.005/0.0075/0.010 h for brittle/"
               "ductile/no interfering non-structural elements). Unit: -.",
               drift_code_names());
    prm.add_parameter("Risk category", risk_category, "ASCE 7 risk category. Unit: -.",
                      Patterns::Selection("I|II|III|IV"));
    prm.add_parameter("Non-structural elements", non_structural,
                      "Eurocode 8: brittle, ductile, or none (none, or fixed so as not to "
                      "interfere with the structural deformations). Unit: -.",
                      Patterns::Selection("brittle|ductile|none"));
    prm.add_parameter("nu", nu,
                      "Eurocode 8 reduction factor for the damage-limitation action (0.5 for "
                      "importance classes I-II, 0.4 for III-IV; 1 if the run is at the "
                      "damage-limitation action itself). Unit: dimensionless.",
                      Patterns::Double(0, 1));
    prm.leave_subsection();
  }

  DriftLimit
  code_drift_limit(const DriftCode code, const std::string &risk_category,
                   const std::string &non_structural, const double nu)
  {
    if (code == DriftCode::asce7)
      {
        const double ratio = risk_category == "IV" ? 0.010 : risk_category == "III" ? 0.015 : 0.020;
        return {"ASCE 7 Table 12.12-1, risk category " + risk_category, ratio};
      }
    const double alpha = non_structural == "brittle" ? 0.005 :
                         non_structural == "ductile" ? 0.0075 :
                                                       0.010;
    return {"Eurocode 8 4.4.3.2, " + non_structural + " non-structural elements, nu = " +
              shortest(nu),
            alpha / nu};
  }

  void
  DriftLimitParameters::finalize(const InputFile &input)
  {
    all_limits.clear();
    std::stringstream items(limits_text);
    std::string       item;
    while (std::getline(items, item, ','))
      {
        item = trimmed(item);
        if (item.empty())
          input.fail("Drift limits/Limits", "an empty item in '" + limits_text + "'");
        const bool   percent = item.back() == '%';
        std::string  number  = trimmed(percent ? item.substr(0, item.size() - 1) : item);
        char        *end     = nullptr;
        const double value   = std::strtod(number.c_str(), &end);
        if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(value))
          input.fail("Drift limits/Limits", "'" + item + "' is not a number or a percentage");
        const double ratio = percent ? value / 100 : value;
        if (!(ratio > 0 && ratio < 1))
          input.fail("Drift limits/Limits",
                     "'" + item + "' is not a drift ratio in (0, 1) (percentages end in %)");
        all_limits.push_back({"limit " + shortest(ratio * 100) + " %", ratio});
      }
    if (code == DriftCode::eurocode8 && !(nu > 0))
      input.fail("Drift limits/nu", "must be positive");
    if (code != DriftCode::none)
      all_limits.push_back(code_drift_limit(code, risk_category, non_structural, nu));
  }

  std::vector<DriftCheck>
  check_drift_limits(const std::vector<DriftLimit> &limits,
                     const std::vector<double>     &peak_drift_ratios)
  {
    std::vector<DriftCheck> checks;
    for (const DriftLimit &limit : limits)
      {
        DriftCheck check;
        check.limit = limit;
        for (unsigned int s = 0; s < peak_drift_ratios.size(); ++s)
          {
            if (s == 0 || peak_drift_ratios[s] > check.peak_drift_ratio)
              {
                check.peak_drift_ratio = peak_drift_ratios[s];
                check.storey_of_peak   = s + 1;
              }
            if (!(peak_drift_ratios[s] <= limit.drift_ratio)) // NaN fails
              check.storeys_exceeding.push_back(s + 1);
          }
        check.passes = check.storeys_exceeding.empty();
        checks.push_back(check);
      }
    return checks;
  }
} // namespace poundfe
