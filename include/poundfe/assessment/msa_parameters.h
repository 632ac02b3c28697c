// The `MSA` section: the stripes of a multiple-stripe analysis (given
// intensities and/or the return periods of a hazard curve), the limit
// states whose fragilities are fitted, and the cloud (assessment/msa.h).
// The record suite, its intensity measure and collapse are the IDA
// section's.
#ifndef poundfe_assessment_msa_parameters_h
#define poundfe_assessment_msa_parameters_h

#include <poundfe/base/input_file.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  struct LimitState;

  struct MsaParameters
  {
    std::vector<double> intensities;    // in the IDA measure's unit
    std::string         hazard_curve;   // a CSV, relative to the input
    std::string         hazard_column = "pga_g";
    std::vector<double> return_periods; // years
    std::string         limit_states;   // "column > threshold; ..."
    bool                cloud        = false;
    std::string         cloud_demand = "max_drift_ratio";

    void declare(dealii::ParameterHandler &prm);
    std::vector<NamedInputFile> input_files() const;
    void check(const InputFile &input) const;
    /// Collapse, then the limit states of `limit_states` on the demands
    /// `names` (IdaRunner::demand_names()). InputError for a term that is
    /// not "column > number" or names no demand.
    std::vector<LimitState> parse_limit_states(const InputFile &input,
                                               const std::vector<std::string> &names) const;
  };
} // namespace poundfe

#endif
