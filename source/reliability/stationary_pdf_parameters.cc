#include <poundfe/reliability/stationary_pdf_parameters.h>
#include <poundfe/base/numbers.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>

namespace poundfe
{
  const NameTable<BandwidthRule> &
  bandwidth_rule_names()
  {
    static const NameTable<BandwidthRule> table({{BandwidthRule::silverman, "silverman"},
                                                 {BandwidthRule::sheather_jones, "sheather-jones"},
                                                 {BandwidthRule::automatic, "auto"}});
    return table;
  }

  namespace Patterns = dealii::Patterns;

  namespace
  {
    /// The most time steps between samples: exact in a double and far within
    /// an unsigned long (interval_steps). Any interval longer than the
    /// sampled time takes one sample per realization; this bound only keeps
    /// absurd values (1e200 s) from overflowing the count.
    constexpr double max_interval_steps = 1e15;
  } // namespace

  void
  StationaryPdfParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Stationary PDF");
    prm.add_parameter("Response", response,
                      "'building floor node' whose horizontal displacement x (ux) and "
                      "velocity are sampled (building: its number, 1-based, or its Name; "
                      "floor 1-based, node 0-based). Unit: -.");
    prm.add_parameter("Burn-in time", burn_in, "Time from rest before sampling starts. Unit: s.",
                      Patterns::Double(0));
    prm.add_parameter("Sampling time", sampling_time,
                      "Time sampled after the burn-in; the runs then end at burn-in + "
                      "sampling time (0: sample to the end of the run, Time integration/End "
                      "time or the ground motion's length). Unit: s.",
                      Patterns::Double(0));
    prm.add_parameter("Sample interval", sample_interval,
                      "Time between samples (a whole number of time steps, at most 1e15 of "
                      "them; 0: every step). Longer than the sampled time: one sample per "
                      "realization, at the end of the burn-in. Unit: s.",
                      Patterns::Double(0));
    prm.add_parameter("Number of realizations", realizations,
                      "Independent runs (noise of seed and realization 0..N-1). Unit: count.",
                      Patterns::Integer(1, 100000));
    prm.add_parameter("Bins", bins,
                      "Bins of each histogram (x, velocity, amplitude) and of each axis of the "
                      "joint histogram of (x, velocity). Unit: count.",
                      Patterns::Integer(4, 400));
    prm.add_parameter("Range", range,
                      "'x_low, x_high, v_low, v_high' (m, m/s) of the histograms (the amplitude "
                      "from 0 to its largest value on that box); empty: from a pilot run "
                      "(realization 0): -m..m with m = 1.25 times its largest |x| (|v|), the "
                      "amplitude 0..1.25 times its largest. Unit: per field.",
                      Patterns::List(Patterns::Double(), 0, 4, ","));
    prm.add_parameter("Omega", omega,
                      "omega of the amplitude a = sqrt(x^2 + v^2/omega^2) (0: the "
                      "model's first natural frequency). Unit: rad/s.",
                      Patterns::Double(0));
    prm.add_parameter("Kernel bandwidth", bandwidths,
                      "Gaussian kernel bandwidths of x (m), v (m/s) and a (m), or one for all; "
                      "0: chosen by Bandwidth rule. Unit: per field.",
                      Patterns::List(Patterns::Double(0), 1, 3, ","));
    add_choice(prm, "Bandwidth rule", bandwidth_rule,
               "A Kernel bandwidth of 0: silverman (0.9 min(sigma, IQR/1.34) N^(-1/5); "
               "oversmooths a multimodal density), sheather-jones (Sheather and Jones's "
               "plug-in rule, solve-the-equation; Silverman's where it has no root) or auto "
               "(Silverman's, then Sheather-Jones's when that density has 2 or more peaks). "
               "Unit: -.",
               bandwidth_rule_names());
    prm.add_parameter("Peak threshold", peak_threshold,
                      "A peak of a kernel density is a local maximum whose height and "
                      "prominence are at least this fraction of the global maximum. "
                      "Unit: dimensionless.",
                      Patterns::Double(0, 1));
    prm.add_parameter("Support threshold", support_threshold,
                      "The support of a kernel density is where it is at least this "
                      "fraction of its maximum (summary.json's support intervals; a "
                      "P-bifurcation reports the values between which their number "
                      "changes: a change of support, the hard bifurcation). "
                      "Unit: dimensionless.",
                      Patterns::Double(0, 1));
    sweep.declare_entries(prm);
    prm.leave_subsection();
  }

  void
  StationaryPdfParameters::check(const InputFile &input, const double time_step) const
  {
    const std::string s = "Stationary PDF/";
    if (range.size() != 0 && range.size() != 4)
      input.fail(s + "Range", "needs 4 values 'x_low, x_high, v_low, v_high' or none (from a "
                              "pilot run), got " + std::to_string(range.size()));
    if (range.size() == 4 && !(range[0] < range[1] && range[2] < range[3]))
      input.fail(s + "Range", "each low value must lie below its high value");
    if (bandwidths.size() != 1 && bandwidths.size() != 3)
      input.fail(s + "Kernel bandwidth", "needs 1 value or 3 (x, v, a), got " +
                                           std::to_string(bandwidths.size()));
    if (!(peak_threshold > 0 && peak_threshold < 1))
      input.fail(s + "Peak threshold", "must lie in (0, 1)");
    if (!(support_threshold > 0 && support_threshold < 1))
      input.fail(s + "Support threshold", "must lie in (0, 1)");
    sweep.check(input);
    input.distinct(s + "Values", sweep.values()); // a value twice: the same density twice
    if (sweep.values().size() == 1)
      input.fail(s + "Values", "a P-bifurcation needs at least 2 values");
    if (!sweep.values().empty())
      sweep.require(input);
    const double steps = sample_interval / time_step;
    if (sample_interval > 0 && (steps < 0.5 || std::abs(steps - std::round(steps)) > 1e-6 * steps))
      input.fail(s + "Sample interval", "must be a whole number of time steps (" +
                                          number_text(time_step) + " s)");
    if (steps > max_interval_steps) // its step count would overflow interval_steps
      input.fail(s + "Sample interval", "must be at most 1e15 time steps (" +
                                          number_text(time_step) + " s each)");
  }

  unsigned long
  StationaryPdfParameters::interval_steps(const double time_step) const
  {
    return sample_interval > 0 ? std::lround(sample_interval / time_step) : 1;
  }
} // namespace poundfe
