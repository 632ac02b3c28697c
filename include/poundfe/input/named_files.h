// The files a parameter file names: records, tabulated forces, Gmsh
// meshes, catalogues, fragility and hazard files. Every entry that names a
// file is one whose name is "File" or ends in " file", or a tabulated
// force's fifth field (Nodal forces/Tabulated).
#ifndef poundfe_input_named_files_h
#define poundfe_input_named_files_h

#include <poundfe/input/input_parameters.h>

#include <string>
#include <vector>

namespace poundfe
{
  /// A file named by an entry of the input.
  struct NamedFile
  {
    std::string entry; // "Ground motion/Record/File", "Nodal forces/Tabulated"
    std::string given; // as written in the input
    std::string path;  // resolved against the parameter file's directory
  };

  /// Every file `input` names, in the order of its entries (an entry left
  /// empty names none).
  std::vector<NamedFile> named_files(const InputParameters &input);
} // namespace poundfe

#endif
