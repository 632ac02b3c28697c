// What a time history with the standard outputs reads from the input: the
// time history's own parts, and what its recorders, VTU series and
// summary.json need. Each part is its module's own section; the commands
// take them from the whole input (input/engine_parameters.h).
#ifndef poundfe_report_run_parameters_h
#define poundfe_report_run_parameters_h

#include <poundfe/dynamics/time_history.h>
#include <poundfe/excitation/spectrum_parameters.h>
#include <poundfe/model/contact_parameters.h>
#include <poundfe/output/drift_limits.h>
#include <poundfe/output/output_parameters.h>
#include <poundfe/output/section_limits.h>

namespace poundfe
{
  struct RunParameters
  {
    TimeHistoryParameters time_history;
    OutputParameters      output;
    SpectrumParameters    spectrum;     // the floor spectra's periods and damping ratios
    DriftLimitParameters  drift_limits; // checked against the peak drifts in summary.json
    ContactParameters     contact;      // summary.json: how the contact damping was set
    SectionLimitParameters section_limits; // the fibre members' limit states in summary.json
  };
} // namespace poundfe

#endif
