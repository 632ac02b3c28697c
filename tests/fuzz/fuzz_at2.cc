// libFuzzer target: the record readers (PEER AT2 header and values; the
// one- and two-column text reader when the first byte is '#') on arbitrary
// bytes. A finding is a crash, a sanitizer report, a hang or an exception
// that is not an InputError (reader_target.h). Built and run by
// tests/fuzz/run.sh.
#include <poundfe/excitation/records.h>

#include "reader_target.h"

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, const std::size_t size)
{
  const bool text = size > 0 && data[0] == '#';
  poundfe_fuzz::read_expecting_input_errors(data, size, text ? "record.txt" : "record.at2",
                                            [](const std::string &file) {
                                              poundfe::RecordFormat format;
                                              format.time_step = 0.01; // for one-column text
                                              poundfe::read_record(file, format);
                                            });
  return 0;
}
