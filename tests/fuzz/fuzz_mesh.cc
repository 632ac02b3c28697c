// libFuzzer target: the Gmsh reader of frame meshes (read_line_mesh, over
// deal.II's GridIn<1,2>) on arbitrary bytes. A finding: a crash, a sanitizer report, a hang, or an
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
  return 0;
}
