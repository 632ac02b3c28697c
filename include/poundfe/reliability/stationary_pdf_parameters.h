// The `Stationary PDF` section: long runs of a noisy system, burn-in then
// sampling of one DOF, over several independent realizations.
#ifndef poundfe_reliability_stationary_pdf_parameters_h
#define poundfe_reliability_stationary_pdf_parameters_h

#include <poundfe/base/choices.h>
#include <poundfe/base/sweep_parameters.h>
#include <poundfe/base/input_file.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  /// How a kernel bandwidth of 0 is chosen (reliability/density.h).
  enum class BandwidthRule
  {
    silverman,      // 0.9 min(sigma, IQR/1.34) N^(-1/5)
    sheather_jones, // the plug-in rule, solve-the-equation
    automatic       // Silverman's, then Sheather-Jones's if that density has 2+ peaks
  };
  const NameTable<BandwidthRule> &bandwidth_rule_names();

  struct StationaryPdfParameters
  {
    std::string         response        = "1 1 0"; // 'building floor node' (its ux)
    double              burn_in         = 0;       // s
    double              sampling_time   = 0;       // s; 0: to the end of the run
    double              sample_interval = 0;       // s; 0: every time step
    unsigned int        realizations    = 4;
    unsigned int        bins            = 50;
    std::vector<double> range;            // x_low, x_high, v_low, v_high; empty: from a pilot
    double              omega          = 0; // rad/s; 0: the first natural frequency
    std::vector<double> bandwidths{0.0};  // x, v, a (one for all); 0: by `bandwidth_rule`
    BandwidthRule       bandwidth_rule = BandwidthRule::silverman;
    double              peak_threshold = 0.05;
    /// The support of a kernel density: where it is at least this fraction
    /// of its maximum (reliability/density.h).
    double              support_threshold = 1e-3;
    /// P-bifurcation: `Parameter` and `Values` of this section; empty: one run.
    SweepParameters sweep{"Stationary PDF"};

    /// Declare the section (entered and left here).
    void declare(dealii::ParameterHandler &prm);
    /// `time_step`: the analysis time step. Throws InputError.
    void check(const InputFile &input, double time_step) const;

    /// Steps of the analysis time step between samples.
    unsigned long interval_steps(double time_step) const;
  };
} // namespace poundfe

#endif
