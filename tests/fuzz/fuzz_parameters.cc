// libFuzzer target: the parameter-file reader (read_parameters: the line
// scan, deal.II's ParameterHandler, every section's declarations and checks,
// the limit-state expressions and random variables of Reliability included)
// on arbitrary bytes, as a .prm and as a .json file. A finding is a crash, a
// sanitizer report, a hang or an exception that is not poundfe's own
// InputError (reader_target.h). Built and run by tests/fuzz/run.sh.
#include <poundfe/input/input_parameters.h>

#include <deal.II/base/exceptions.h>

#include "reader_target.h"

extern "C" int
LLVMFuzzerInitialize(int *, char ***)
{
  dealii::deal_II_exceptions::disable_abort_on_exception();
  return 0;
}

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, const std::size_t size)
{
  // the first byte chooses the syntax, so both share one corpus
  const bool json = size > 0 && data[0] == '{';
  poundfe_fuzz::read_expecting_input_errors(data, size, json ? "input.json" : "input.prm",
                                            [](const std::string &file) {
                                              poundfe::read_parameters(file);
                                            });
  return 0;
}
