// libFuzzer target: the fragility summary.json that `site-hazard` reads
// (read_fragility_summary, curve "pounding") on arbitrary bytes. A curve it
// returns must have a positive, finite median and dispersion; crashes,
// sanitizer reports, hangs and exceptions other than InputError are
// findings (reader_target.h). Built and run by tests/fuzz/run.sh.
#include <poundfe/hazard/catalogue.h>

#include "reader_target.h"

#include <cmath>
#include <cstdlib>

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, const std::size_t size)
{
  poundfe_fuzz::read_expecting_input_errors(data, size, "summary.json", [](const std::string &file) {
    const poundfe::LognormalCurve curve = poundfe::read_fragility_summary(file, "pounding");
    if (!(curve.theta > 0 && curve.beta > 0 && std::isfinite(curve.theta) && std::isfinite(curve.beta)))
      std::abort();
  });
  return 0;
}
