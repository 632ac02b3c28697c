// The `IDA` section: the record suite, the intensity measure records are
// scaled to, the hunt-and-fill search (assessment/ida.h) and what counts as
// collapse.
#ifndef poundfe_assessment_ida_parameters_h
#define poundfe_assessment_ida_parameters_h

#include <poundfe/assessment/collapse_margin.h>
#include <poundfe/base/input_file.h>
#include <poundfe/excitation/intensity_measures.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  struct IdaParameters
  {
    std::string         suite; // a .csv, a .json or a folder of .AT2, relative to the input
    IntensityMeasure    measure = IntensityMeasure::sa;
    PairMeasure         pair    = PairMeasure::rotd50;
    double              period  = 0; // s; 0: the model's first period
    double              damping_ratio = 0.05;
    std::vector<double> sa_avg_range{0.2, 3.0}; // times Period
    unsigned int        sa_avg_periods = 10;
    double              initial_step   = 0.1;  // in the measure's unit
    double              step_increment = 0.05; // added to each hunting step
    double              upper_intensity = 5;   // no collapse below it: reported as such
    double              tolerance       = 0.02; // of the collapse intensity
    unsigned int        runs_per_record = 12;   // hunt, bracket and fill (bracketing may exceed it)
    double              collapse_drift_ratio = 0.1;
    double              free_vibration       = 0; // s of rest after each record
    /// Intensities at which ida writes pelicun demand tables (output/demand_table.h).
    std::vector<double>      demand_intensities;
    CollapseMarginParameters collapse_margin; // FEMA P-695

    void declare(dealii::ParameterHandler &prm);
    /// The suite it names (when given).
    std::vector<NamedInputFile> input_files() const;
    void check(const InputFile &input) const;
    /// The periods the measure is taken at, given the model's first period:
    /// {Period} for Sa, sa_avg_periods log-spaced over the range for Sa_avg.
    std::vector<double> measure_periods(double first_period) const;
  };
} // namespace poundfe

#endif
