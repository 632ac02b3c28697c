// libFuzzer target: a force table of Nodal forces/Tabulated, as the time
// history reads it (make_nodal_forces: the entry's 'building floor node dof'
// against the model, then the table through read_columns: two columns,
// increasing times). An input is
//   line 1   the entry before its file name ('1 2 0 ux')
//   the rest the table file
// read against a 2D and a 3D pair of shear buildings built once
// (base_model.h). A table it accepts must have finite, increasing times and
// finite forces; crashes, sanitizer reports, hangs and exceptions other
// than InputError are findings (reader_target.h). Built and run by
// tests/fuzz/run.sh.
#include <poundfe/excitation/excitation.h>

#include <deal.II/base/exceptions.h>

#include "base_model.h"
#include "reader_target.h"

#include <cmath>
#include <cstdlib>
#include <string>

namespace
{
  using poundfe_fuzz::BaseModel;

  const BaseModel &
  base_model(const unsigned int i)
  {
    static const std::unique_ptr<const BaseModel> models[2] = {
      poundfe_fuzz::read_base_model("tests/dynamics/uncertain-shear-pair.prm", {}),
      poundfe_fuzz::read_base_model("tests/dynamics/uncertain-3d-pair.prm", {})};
    return *models[i];
  }

  void
  read_table(const BaseModel &base, const std::string &entry)
  {
    poundfe::NodalForceParameters parameters;
    parameters.tabulated = {entry};
    const poundfe::InputParameters &input = base.input;
    for (const poundfe::NodalForce &f :
         poundfe::make_nodal_forces(parameters, input.ground_motion,
                                    input.time_integration.newmark.time_step, input,
                                    base.analysis.model))
      for (std::size_t i = 0; i < f.times.size(); ++i)
        if (!std::isfinite(f.times[i]) || !std::isfinite(f.values[i]) ||
            (i > 0 && !(f.times[i] > f.times[i - 1])))
          std::abort(); // a table the reader should have refused
  }
} // namespace

extern "C" int
LLVMFuzzerInitialize(int *, char ***)
{
  dealii::deal_II_exceptions::disable_abort_on_exception();
  base_model(0);
  return 0;
}

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, const std::size_t size)
{
  const std::string text(reinterpret_cast<const char *>(data), size);
  const std::size_t end_of_entry = std::min(text.find('\n'), text.size());
  const std::string prefix       = text.substr(0, end_of_entry);
  const std::size_t table        = std::min(end_of_entry + 1, size);
  for (unsigned int b = 0; b < 2; ++b)
    poundfe_fuzz::read_expecting_input_errors(
      data + table, size - table, "force.txt", [&](const std::string &file) {
        read_table(base_model(b), prefix + " " + file);
      });
  return 0;
}
