// libFuzzer target: a building drawn in Gmsh, from the .msh text to the
// built model (prepare_analysis: check_gmsh_text, read_line_mesh or
// read_line_mesh_3d, the floors found from the beam levels, the groups'
// sections, in 3D the rigid diaphragms on the floors' joints and the column
// base hinges; then M, K and the modes of its damping). Each input is the
// mesh file of two inputs read once (base_model.h): input/setback-frame.prm
// (2D) and tests/cli/mesh-3d-pair.prm (a 3D L-shaped frame beside a
// generated one), whose Mesh file is the scratch file the input is written
// to. Inputs are at most 4 KiB (run.sh), so a mesh has at most about 100
// nodes and an execution stays short. Crashes, sanitizer reports, hangs and
// exceptions other than InputError and NumericalError are findings
// (reader_target.h). Built and run by tests/fuzz/run.sh.
#include <deal.II/base/exceptions.h>

#include "base_model.h"
#include "reader_target.h"

#include <fstream>
#include <iterator>
#include <string>

namespace
{
  using poundfe_fuzz::BaseModel;

  /// The base input `file` with its Building 1/Mesh file at the scratch
  /// file, which holds `mesh` (the input's own mesh) while it is read.
  std::unique_ptr<const BaseModel>
  mesh_base(const std::string &file, const std::string &mesh)
  {
    std::ifstream     in(std::string(POUNDFE_SOURCE_DIR) + "/" + mesh, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string scratch = poundfe_fuzz::write_scratch_file(
      reinterpret_cast<const std::uint8_t *>(text.data()), text.size(), "frame.msh");
    return poundfe_fuzz::read_base_model(file, {{"Building 1/Mesh file", scratch}}, false);
  }

  const BaseModel &
  base_model(const unsigned int i)
  {
    static const std::unique_ptr<const BaseModel> models[2] = {
      mesh_base("input/setback-frame.prm", "meshes/setback.msh"),
      mesh_base("tests/cli/mesh-3d-pair.prm", "meshes/frame3d-l.msh")};
    return *models[i];
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
  poundfe_fuzz::write_scratch_file(data, size, "frame.msh");
  for (unsigned int b = 0; b < 2; ++b)
    poundfe_fuzz::run_expecting_refusals([&] { poundfe::prepare_analysis(base_model(b).input); });
  return 0;
}
