// A parameter sweep: one parameter (an override path, see ParameterOverride)
// takes each of a list of values, and each value gives one InputParameters
// read from the file with that override, so every value goes through the
// checks the file does. The `Sweep` section drives `poundfe sweep`; other
// sweeping commands (bifurcation, stationary-pdf) declare the same
// `Parameter` and `Values` entries in their own section and reuse this.
//   Values = v1, v2, ...        an explicit list
//   Values = linspace a b n     n values a + i (b - a)/(n - 1), i = 0..n-1
#ifndef poundfe_input_sweep_h
#define poundfe_input_sweep_h

#include <poundfe/base/input_file.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  struct InputParameters;
  struct ParameterOverride;

  struct SweepParameters
  {
    /// The section whose entries these are ("Sweep", "Bifurcation", ...),
    /// for messages.
    std::string section = "Sweep";
    std::string parameter{};   // an override path, e.g. "Model/Separations"
    std::string values_text{}; // as written
    std::string label{};       // the parameter's name on plot axes ("": its path)
    std::string command = "run"; // Sweep only: whose model runs

    /// Parameter and Values in the subsection `prm` is in.
    void declare_entries(dealii::ParameterHandler &prm);
    /// The Sweep section: the entries and Command (entered and left here).
    void declare(dealii::ParameterHandler &prm);
    /// The syntax of Values, when given. Throws InputError.
    void check(const InputFile &input) const;
    /// For the command that sweeps: Parameter and Values are given.
    void require(const InputFile &input) const;

    /// The swept values, in order (after check()).
    std::vector<double> values() const;
    /// The input of `file` with the parameter set to `value` (and then the
    /// `more` overrides), checked. Throws InputError naming the path.
    InputParameters input_for(const std::string &file, double value) const;
    InputParameters input_for(const std::string &file, double value,
                              const std::vector<ParameterOverride> &more) const;
    /// The same for the file `input` was read from, with the overrides it
    /// was read with first.
    InputParameters input_for(const InputParameters &input, double value,
                              const std::vector<ParameterOverride> &more = {}) const;
    /// The parameter's name on plot axes: Label, or the path when none is given.
    std::string axis_label() const;
    /// The parameter as a CSV column name: "Model/Separations" -> "Model_Separations".
    std::string column_name() const;
  };

  /// The shortest text that reads back as `value`.
  std::string format_value(double value);

  /// The `sweep` command: for each value, the time history of the input
  /// with the override; the summary scalars against the value in
  /// sweep.csv, sweep.png and summary.json. Returns the exit status.
  int sweep_command(const InputParameters &input, const std::string &output_directory);
} // namespace poundfe

#endif
