// libFuzzer target: the record readers (PEER AT2 header and values; the
// one- and two-column text reader when the first byte is '#') on arbitrary
// bytes. A finding is a crash, a sanitizer report, a hang or an exception
// that is not an InputError. Built and run by tests/fuzz/run.sh.
#include <poundfe/base/exceptions.h>
#include <poundfe/excitation/records.h>

#include "scratch_file.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, const std::size_t size)
{
  const bool        text = size > 0 && data[0] == '#';
  const std::string file =
    poundfe_fuzz::write_scratch_file(data, size, text ? "record.txt" : "record.at2");
  poundfe::RecordFormat format;
  format.time_step = 0.01; // for one-column text
  try
    {
      poundfe::read_record(file, format);
    }
  catch (const poundfe::InputError &)
    {
    }
  catch (const std::exception &e)
    {
      std::fprintf(stderr, "not an InputError: %s\n", e.what());
      std::abort();
    }
  return 0;
}
