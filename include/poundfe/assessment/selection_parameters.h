// The `Selection` section: the candidate records, the target spectrum
// (EC8 from the Spectrum section, ASCE 7-16, a user's table or the
// conditional mean spectrum of BSSA14), the period range, the number of
// records and the limits of their scale factors (record_selection.h,
// excitation/target_spectrum.h). The spectra are of IDA/Pair measure at
// IDA/Damping ratio.
#ifndef poundfe_assessment_selection_parameters_h
#define poundfe_assessment_selection_parameters_h

#include <poundfe/base/input_file.h>
#include <poundfe/excitation/target_spectrum.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  enum class SelectionTarget
  {
    ec8_type_1,
    ec8_type_2,
    asce7,
    table,
    cms
  };
  const NameTable<SelectionTarget> &selection_target_names();

  struct SelectionParameters
  {
    std::string         candidates; // a suite; empty: IDA/Suite
    unsigned int        n_records = 7;
    SelectionTarget     target    = SelectionTarget::ec8_type_1;
    double              min_period = 0.1, max_period = 2; // s
    unsigned int        n_periods  = 20;
    std::vector<double> scale_limits{0.25, 4};
    bool                scale_to_intensity = false; // else least squares
    double              target_intensity   = 0;     // IDA measure's unit
    std::string         table;                      // period_s, sa_g
    double              sds = 1, sd1 = 0.6, tl = 8; // ASCE 7-16: g, g, s
    Scenario            scenario;
    double              conditioning_period = 1, epsilon = 1;

    void declare(dealii::ParameterHandler &prm);
    std::vector<NamedInputFile> input_files() const;
    void check(const InputFile &input) const;
  };
} // namespace poundfe

#endif
