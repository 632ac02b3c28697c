// The `IDA` section (ida_parameters.h).
#include <poundfe/assessment/ida_parameters.h>
#include <poundfe/base/numbers.h>
#include <poundfe/excitation/response_spectrum.h>

#include <deal.II/base/parameter_handler.h>

namespace poundfe
{
  void
  IdaParameters::declare(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    prm.enter_subsection("IDA");
    prm.add_parameter("Suite", suite,
                      "The records: a CSV file with a header row (file, file2, name, scale, "
                      "event, station, magnitude, distance_km, vs30_m_s), a JSON file "
                      "({\"records\": [{\"files\": [...], ...}]}) or a folder of PEER .AT2 "
                      "files; record paths relative to the suite. Two files a record: a "
                      "horizontal pair (Model/Dimension = 3). Unit: -.");
    add_choice(prm, "Intensity measure", measure,
               "What records are scaled to: Sa (pseudo-spectral acceleration at Period), "
               "Sa_avg (geometric mean of Sa over the Sa_avg range), PGA, PGV. Unit: -.",
               intensity_measure_names());
    add_choice(prm, "Pair measure", pair,
               "A horizontal pair's measure: RotD50, RotD100 (Boore 2010) or the geometric "
               "mean of the two components. Unit: -.",
               pair_measure_names());
    prm.add_parameter("Period", period,
                      "Period of Sa, and the period Sa_avg's range is in multiples of; 0: the "
                      "model's first period. Unit: s.", Double(0));
    prm.add_parameter("Damping ratio", damping_ratio, "Of Sa. Unit: -.", Double(0, 0.99));
    prm.add_parameter("Sa_avg range", sa_avg_range,
                      "Shortest and longest period of Sa_avg as multiples of Period. Unit: -.",
                      dealii::Patterns::List(Double(0), 2, 2, ","));
    prm.add_parameter("Sa_avg periods", sa_avg_periods,
                      "Periods of Sa_avg, log-spaced over the range. Unit: count.", Integer(2, 100));
    prm.add_parameter("Initial step", initial_step,
                      "First intensity of the hunt and its first step. Unit: that of the measure "
                      "(g, or m/s for PGV).", Double(0));
    prm.add_parameter("Step increment", step_increment,
                      "Added to the step after each hunting run (Vamvatsikos & Cornell 2004). "
                      "Unit: that of the measure.", Double(0));
    prm.add_parameter("Upper intensity", upper_intensity,
                      "The hunt stops here: a record that does not collapse below it is "
                      "reported as such. Unit: that of the measure.", Double(0));
    prm.add_parameter("Tolerance", tolerance,
                      "Bracketing stops when the collapse intensity lies in an interval this "
                      "wide. Unit: that of the measure.", Double(0));
    prm.add_parameter("Runs per record", runs_per_record,
                      "Runs of hunting, bracketing and filling a record (bracketing continues "
                      "to Tolerance). Unit: count.", Integer(2, 1000));
    prm.add_parameter("Collapse drift ratio", collapse_drift_ratio,
                      "Collapse: a peak inter-storey drift ratio above it, or a run that fails "
                      "to converge. Unit: -.", Double(0));
    prm.add_parameter("Free vibration", free_vibration,
                      "Rest after each record (the residual drift is that at the end). Unit: s.",
                      Double(0));
    prm.add_parameter("Demand intensities", demand_intensities,
                      "Intensities at which ida writes each building's demands in pelicun's "
                      "demand-sample convention, demands_<building>_im<k>.csv (k = 1, 2, ... "
                      "in this order): a row per record that has not collapsed there, its "
                      "demands interpolated along its IDA curve. Unit: that of the measure.",
                      dealii::Patterns::List(Double(0), 0, 100, ","));
    collapse_margin.declare(prm);
    prm.leave_subsection();
  }

  std::vector<NamedInputFile>
  IdaParameters::input_files() const
  {
    if (suite.empty())
      return {};
    return {{"IDA/Suite", "record suite", suite, ""}};
  }

  void
  IdaParameters::check(const InputFile &input) const
  {
    for (const auto &[path, value] : {std::pair{"IDA/Initial step", initial_step},
                                      std::pair{"IDA/Upper intensity", upper_intensity},
                                      std::pair{"IDA/Tolerance", tolerance},
                                      std::pair{"IDA/Collapse drift ratio", collapse_drift_ratio}})
      input.positive(path, value);
    // a drift of the storey's height has brought down any building long
    // before (collapse limits lie near 0.02 to 0.1); 1e200 ran as a
    // building that never collapses
    input.at_most("IDA/Collapse drift ratio", collapse_drift_ratio, 1, "",
                  "a drift of the whole storey height");
    if (!(upper_intensity > initial_step))
      input.fail("IDA/Upper intensity", "must exceed IDA/Initial step");
    for (const double x : demand_intensities)
      if (!(x > 0 && x <= upper_intensity))
        input.fail("IDA/Demand intensities",
                   "each must lie in (0, IDA/Upper intensity], got " + rounded(x));
    collapse_margin.check(input, measure);
    if (!(sa_avg_range[0] > 0 && sa_avg_range[1] > sa_avg_range[0]))
      input.fail("IDA/Sa_avg range", "expected 0 < shortest < longest");
  }

  std::vector<double>
  IdaParameters::measure_periods(const double first_period) const
  {
    const double centre = period > 0 ? period : first_period;
    if (measure == IntensityMeasure::sa)
      return {centre};
    if (measure == IntensityMeasure::sa_avg)
      return period_grid(sa_avg_range[0] * centre, sa_avg_range[1] * centre, sa_avg_periods, true);
    return {};
  }
} // namespace poundfe
