// One command's results per output directory. A second command into the
// same directory must not leave the first one's files beside its own (the
// contact forces of a model that no longer has gaps, VTU frames that the new
// .pvd does not list, the plots of other hinges), and it must never delete
// what the user keeps there. So every file and subdirectory poundfe creates
// in an output directory is first listed in the directory's manifest,
// `.poundfe-files` (one path relative to the directory per line, written
// before the file is created, so a killed command's files are listed too),
// and a command starts by removing what the previous command listed, with
// its "<name>.tmp" temporaries, except the files it resumes from
// (montecarlo's realizations.csv). Files poundfe did not create are never
// touched. Every writer lists its file: AtomicFile, AppendFile,
// create_directories and draw_plots call register_output().
#ifndef poundfe_output_output_directory_h
#define poundfe_output_output_directory_h

#include <string>
#include <vector>

namespace poundfe
{
  /// The manifest's file name in an output directory.
  inline const char *const output_manifest_name = ".poundfe-files";

  /// Starts a command's output in `directory`: creates it with its parents,
  /// removes every file its manifest lists (and its "<name>.tmp") except those
  /// whose file name is in `resumed`, then the listed subdirectories that are
  /// empty, and starts a new manifest listing what was kept. Call it after the
  /// input is checked (bad input writes nothing) and before the first file.
  /// Throws OutputError when the directory cannot be made or cleared.
  void prepare_output_directory(const std::string              &directory,
                                const std::vector<std::string> &resumed = {});

  /// Lists `path` (a file or a directory about to be created) in the manifest
  /// of the prepared output directory that contains it; does nothing for a
  /// path outside every prepared directory (a test's scratch file).
  void register_output(const std::string &path);

  /// Whether this process has prepared `directory` (prepare_output_directory).
  bool output_directory_prepared(const std::string &directory);

  /// Removes the "<name>.tmp" of every file the manifest of the prepared
  /// `directory` lists (a command that stops early: commands/command_guard.h).
  /// Returns the listed files that exist, relative to it, in listing order.
  std::vector<std::string> remove_temporaries(const std::string &directory);
} // namespace poundfe

#endif
