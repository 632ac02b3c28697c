// libFuzzer target: the parameter-file reader (read_parameters: the line
// scan, deal.II's ParameterHandler, every section's checks) on arbitrary
// bytes, as a .prm and as a .json file. A finding is a crash, a sanitizer
// report, a hang or an exception that is not poundfe's own InputError
// (main.cc would print it, but it means a check is missing). Built and run
// by tests/fuzz/run.sh.
#include <poundfe/input/input_parameters.h>
#include <poundfe/base/exceptions.h>

#include <deal.II/base/exceptions.h>

#include "scratch_file.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
  void
  read_as(const std::uint8_t *data, const std::size_t size, const char *extension)
  {
    const std::string file =
      poundfe_fuzz::write_scratch_file(data, size, std::string("input") + extension);
    try
      {
        poundfe::read_parameters(file);
      }
    catch (const poundfe::InputError &)
      {
      }
    catch (const std::exception &e)
      {
        std::fprintf(stderr, "not an InputError: %s\n", e.what());
        std::abort();
      }
  }
} // namespace

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
  if (size > 0 && data[0] == '{')
    read_as(data, size, ".json");
  else
    read_as(data, size, ".prm");
  return 0;
}
