// libFuzzer target: the record-suite reader (read_record_suite: a CSV suite,
// or a JSON one when the first byte is '{') on arbitrary bytes, beside two
// small AT2 records it may name (r.AT2 and s.AT2, whose lengths differ, so
// that a pair of them is refused). A finding is a crash, a sanitizer report,
// a hang or an exception that is not an InputError (reader_target.h). Built
// and run by tests/fuzz/run.sh.
#include <poundfe/excitation/record_suite.h>

#include "reader_target.h"

#include <cstring>

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, const std::size_t size)
{
  // the records beside the suite, written once into the scratch directory
  static const bool records = [] {
    const char *r = "PEER\nfuzz record\nACCELERATION IN G\nNPTS= 4, DT= 0.01 SEC\n"
                    "0.1 -0.2 0.3 -0.1\n";
    const char *s = "PEER\nfuzz record\nACCELERATION IN G\nNPTS= 3, DT= 0.02 SEC\n0.1 0.2 0.1\n";
    poundfe_fuzz::write_scratch_file(reinterpret_cast<const std::uint8_t *>(r), std::strlen(r),
                                     "r.AT2");
    poundfe_fuzz::write_scratch_file(reinterpret_cast<const std::uint8_t *>(s), std::strlen(s),
                                     "s.AT2");
    return true;
  }();
  (void)records;
  const bool json = size > 0 && data[0] == '{';
  poundfe_fuzz::read_expecting_input_errors(data, size, json ? "suite.json" : "suite.csv",
                                            [](const std::string &file) {
                                              poundfe::read_record_suite(file, "IDA/Suite");
                                            });
  return 0;
}
