// The entries of a Sweep-like section and their values (base/sweep_parameters.h).
#include <poundfe/base/sweep_parameters.h>
#include <poundfe/base/choices.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>

#include <deal.II/base/parameter_handler.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

namespace poundfe
{
  namespace
  {
    /// A finite number, the whole of `text` (blanks around allowed).
    bool
    read_number(const std::string &text, double &x)
    {
      const std::optional<double> value = parse_number(text);
      if (value)
        x = *value;
      return value.has_value();
    }

    /// The values of `text`; on a syntax error an empty list and `error` says why.
    std::vector<double>
    parse_values(const std::string &text, std::string &error)
    {
      std::istringstream words(text);
      std::string        first;
      words >> first;
      std::vector<double> values;
      if (first == "linspace")
        {
          std::string a_text, b_text, n_text, extra;
          double      a = 0, b = 0, n = 0;
          if (!(words >> a_text >> b_text >> n_text) || (words >> extra) ||
              !read_number(a_text, a) || !read_number(b_text, b) || !read_number(n_text, n) ||
              n < 1 || n > 100000 || n != std::floor(n) || (n == 1 && a != b))
            {
              error = "expected 'linspace a b n' with n a whole number in 1..100000 "
                      "(n = 1 needs a = b), got '" + text + "'";
              return {};
            }
          for (unsigned int i = 0; i < n; ++i) // to 15 digits: 0.775, not 0.7749999999999999
            {
              char buffer[32];
              std::snprintf(buffer, sizeof(buffer), "%.15g", n == 1 ? a : a + (b - a) * i / (n - 1));
              values.push_back(std::stod(buffer));
            }
          return values;
        }
      std::istringstream items(text);
      for (std::string item; std::getline(items, item, ',');)
        {
          double x = 0;
          if (!read_number(item, x))
            {
              error = "expected numbers 'v1, v2, ...' or 'linspace a b n', got '" + item + "'";
              return {};
            }
          values.push_back(x);
        }
      if (values.empty())
        error = "no values";
      return values;
    }
  } // namespace

  std::string
  format_value(const double value)
  {
    return number_text(value);
  }

  void
  SweepParameters::declare_entries(dealii::ParameterHandler &prm)
  {
    prm.add_parameter("Parameter", parameter,
                      "The swept parameter: 'Section/.../Entry' (a numeric entry, e.g. "
                      "Model/Separations) or 'Section/.../Entry:k', field k (1-based) of the "
                      "first ';'-separated item of a list entry (e.g. Nodal forces/Harmonic:6, "
                      "the forcing frequency). Unit: -.");
    prm.add_parameter("Values", values_text,
                      "The values: 'v1, v2, ...' or 'linspace a b n' (n values from a to b). "
                      "Unit: that of Parameter.");
    prm.add_parameter("Label", label,
                      "The parameter's name on the plots' axes, e.g. 'forcing amplitude f (N)' "
                      "(empty: its path). Unit: -.");
  }

  void
  SweepParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Sweep");
    declare_entries(prm);
    add_choice(prm, "Command", command,
               "`poundfe sweep`: the command whose model runs at each value (its "
               "time history; run is the one so far). Unit: -.",
               {"run"});
    prm.leave_subsection();
  }

  void
  SweepParameters::check(const InputFile &input) const
  {
    if (values_text.find_first_not_of(" \t") == std::string::npos)
      return;
    std::string error;
    parse_values(values_text, error);
    if (!error.empty())
      input.fail(section + "/Values", error);
  }

  void
  SweepParameters::require(const InputFile &input) const
  {
    if (parameter.find_first_not_of(" \t") == std::string::npos)
      input.fail(section + "/Parameter", "names no parameter to sweep");
    if (values().empty())
      input.fail(section + "/Values", "gives no values to sweep");
  }

  std::vector<double>
  SweepParameters::values() const
  {
    std::string error;
    return values_text.find_first_not_of(" \t") == std::string::npos ?
             std::vector<double>() :
             parse_values(values_text, error);
  }

  std::string
  SweepParameters::axis_label() const
  {
    return label.empty() ? parameter : label;
  }

  std::string
  SweepParameters::column_name() const
  {
    std::string name;
    for (const char c : parameter)
      name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    return name;
  }

} // namespace poundfe
