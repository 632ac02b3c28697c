// libFuzzer target: the Gmsh readers of frame meshes (read_line_mesh and
// read_line_mesh_3d, over deal.II's GridIn<1,2> and GridIn<1,3>) on arbitrary bytes. A finding: a crash, a sanitizer report, a hang, or an
// exception other than InputError (reader_target.h). Built and run by
// tests/fuzz/run.sh.
#include <poundfe/mesh/line_mesh.h>

#include "reader_target.h"

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, const std::size_t size)
{
  poundfe_fuzz::read_expecting_input_errors(data, size, "frame.msh", [](const std::string &file) {
    poundfe::read_line_mesh(file);
  });
  poundfe_fuzz::read_expecting_input_errors(data, size, "frame.msh", [](const std::string &file) {
    poundfe::read_line_mesh_3d(file);
  });
  return 0;
}
