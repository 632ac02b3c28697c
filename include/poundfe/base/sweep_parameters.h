// The entries of a parameter sweep: one parameter (an override path, see
// ParameterOverride in input/input_parameters.h) and a list of values. The
// `Sweep` section drives `poundfe sweep`; other sweeping sections
// (Bifurcation, Stationary PDF) declare the same `Parameter` and `Values`
// entries and reuse this. Each value's input is read in input/sweep.h.
//   Values = v1, v2, ...        an explicit list
//   Values = linspace a b n     n values a + i (b - a)/(n - 1), i = 0..n-1
#ifndef poundfe_base_sweep_parameters_h
#define poundfe_base_sweep_parameters_h

#include <poundfe/base/input_file.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
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
    /// The parameter's name on plot axes: Label, or the path when none is given.
    std::string axis_label() const;
    /// The parameter as a CSV column name: "Model/Separations" -> "Model_Separations".
    std::string column_name() const;
  };

  /// The shortest text that reads back as `value`.
  std::string format_value(double value);
} // namespace poundfe

#endif
