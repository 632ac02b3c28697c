// What `poundfe ida` and `poundfe msa` give a loss model and `ida` a FEMA
// P-695 evaluation: the pelicun demand tables at IDA/Demand intensities and
// at msa's stripes and cloud (assessment/ida_demands.h,
// output/demand_table.h) and the collapse margin (assessment/collapse_margin.h);
// and what both say of the Ground motion entries they ignore; private to
// the commands.
#ifndef poundfe_commands_ida_loss_h
#define poundfe_commands_ida_loss_h

#include <poundfe/assessment/ida.h>
#include <poundfe/assessment/ida_demands.h>

#include <ostream>
#include <string>
#include <vector>

namespace poundfe
{
  class JsonWriter;
  class Model;
  struct CommandRun;
} // namespace poundfe

namespace poundfe::commands
{
  /// demands_<building><label>.csv for each sample and its label ("_im1",
  /// "_stripe2", "_cloud": the rows of its records at its intensity, or
  /// each at its own for a sample whose intensity is NaN, a cloud's:
  /// assessment/ida_demands.h), into run.directory or run.memory;
  /// summary.json's "demand_tables" and the report's lines. The names of
  /// the files written are appended to `files`.
  void write_demand_samples(const CommandRun &run, const Model &model,
                            const IdaRunner &runner, const IdaParameters &ida,
                            const std::vector<IdaDemandSample> &samples,
                            const std::vector<std::string> &labels, JsonWriter &json,
                            std::ostream &out, std::vector<std::string> &files);

  /// demands_<building>_im<k>.csv for each intensity of IDA/Demand
  /// intensities (into run.directory or run.memory); summary.json's
  /// "demand_tables" and the report's lines.
  /// The names of the files written are appended to `files`.
  void write_ida_demand_tables(const CommandRun &run, const Model &model,
                               const IdaRunner &runner, const IdaResult &result,
                               const IdaParameters &ida, JsonWriter &json, std::ostream &out,
                               std::vector<std::string> &files);

  /// summary.json's "collapse_margin" and the report's lines, when
  /// IDA/Collapse margin/MCE spectral acceleration is given.
  void write_collapse_margin(const IdaRunner &runner, const IdaResult &result,
                             const IdaParameters &ida, JsonWriter &json, std::ostream &out);
} // namespace poundfe::commands

#endif
