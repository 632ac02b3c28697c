// libFuzzer target: the earthquake catalogue reader of `site-hazard`
// (read_catalogue: header, dates, coordinates, magnitudes) on arbitrary
// bytes. A finding: a crash, a sanitizer report, a hang, or an exception
// other than InputError (reader_target.h). Built and run by tests/fuzz/run.sh.
#include <poundfe/hazard/catalogue.h>

#include "reader_target.h"

#include <cmath>
#include <cstdlib>

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, const std::size_t size)
{
  poundfe_fuzz::read_expecting_input_errors(data, size, "catalogue.csv", [](const std::string &file) {
    for (const poundfe::CatalogueEvent &e : poundfe::read_catalogue(file))
      if (!std::isfinite(e.magnitude) || !std::isfinite(e.epicentre.latitude) ||
          !std::isfinite(e.epicentre.longitude) || e.year == 0)
        std::abort(); // an event the reader should have refused
  });
  return 0;
}
