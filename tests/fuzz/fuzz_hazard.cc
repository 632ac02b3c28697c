// libFuzzer target: the hazard file of `separation`'s Site hazard
// (read_pga_hazard): a hazard_curve.csv when the first byte is not '{',
// a site-hazard summary.json when it is. The hazard read is evaluated at
// its minimum PGA and at 1 g: a rate that is NaN or negative is a finding,
// as are crashes, sanitizer reports, hangs and exceptions other than
// InputError (reader_target.h). Built and run by tests/fuzz/run.sh.
#include <poundfe/hazard/pounding_hazard.h>

#include "reader_target.h"

#include <cmath>
#include <cstdlib>

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, const std::size_t size)
{
  const bool json = size > 0 && data[0] == '{';
  poundfe_fuzz::read_expecting_input_errors(
    data, size, json ? "hazard.json" : "hazard_curve.csv", [](const std::string &file) {
      const poundfe::PgaHazard hazard = poundfe::read_pga_hazard(file, "Separation/Site hazard/File");
      for (const double pga : {hazard.minimum_pga, 1.0})
        if (!(hazard.annual_rate(pga) >= 0))
          std::abort();
    });
  return 0;
}
