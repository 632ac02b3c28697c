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

#include <poundfe/base/input_file.h>

#include <string>
#include <utility>
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

  /// Undoes the output of the command under way in `directory` (prepared by
  /// this process) after bad input was found late, e.g. a sampled value the
  /// model cannot take (bad input writes nothing): removes every file and
  /// subdirectory it listed, the manifest, and the directory when that leaves
  /// it empty. Keeps everything when the command resumed a table there (the
  /// earlier runs' rows are the user's results). Never throws.
  void discard_output_directory(const std::string &directory);

  /// Names the output directory of the command under way (the command
  /// guard does, for every command): the first file or directory created in
  /// it prepares it (prepare_output_directory) unless the command prepared it
  /// itself (those that resume files), so no command's results lie beside an
  /// earlier run's, and bad input, refused before the first write, leaves
  /// nothing. An empty `directory` ends it.
  /// `resume_inputs` (input_parameters.h) are what decide the rows of a
  /// file the command resumes (resume_file below), besides the contents of
  /// the `input_files` the input names (input/engine_parameters.h:
  /// named_input_files).
  void expect_output_directory(const std::string                                      &directory,
                               std::vector<std::pair<std::string, std::string>> resume_inputs = {},
                               std::vector<NamedInputFile> input_files = {});

  /// A table the command appends to and resumes from a later run
  /// (realizations.csv): its inputs are kept beside it in "<file>.inputs"
  /// (one "path = value" line each, then one "digest of the <what>
  /// '<name>' (<entry>) = <size> bytes, FNV-1a <hash>" line per input file
  /// the input names). When `file` exists, it throws an InputError unless
  /// that record equals the inputs of the command under way
  /// (expect_output_directory) and every named file has the digest it had,
  /// so that a run never continues a table computed from another model or
  /// another record; a record without digest lines (an earlier version's)
  /// is refused when the input names a file, since it cannot be checked.
  /// Else it writes the record (atomically) before the table is started. Without inputs (a unit test's scratch
  /// table) it does nothing. prepare_output_directory keeps the record of
  /// every file it keeps.
  void resume_file(const std::string &file);

  /// Lists `path` (a file or a directory about to be created) in the manifest
  /// of the prepared output directory that contains it; does nothing for a
  /// path outside every prepared directory (a test's scratch file).
  void register_output(const std::string &path);

  /// Whether this process has prepared `directory` (prepare_output_directory).
  bool output_directory_prepared(const std::string &directory);

  /// Bytes a CSV table of `rows` rows and `columns` numbers per row takes,
  /// about: 20 characters a number (17 significant digits, sign, point,
  /// separator), the estimate of the size guard below.
  double csv_table_bytes(double rows, double columns);

  /// The size guard: throws OutputError ("disk full: cannot write the ...
  /// (about X GB; Y GB free) in D") when `bytes` exceed the space free to
  /// this user on the file system that holds `directory` (or its nearest
  /// existing parent). Call it before the output begins and before the
  /// command allocates what it will write.
  void require_free_space(const std::string &directory, double bytes, const std::string &what);

  /// Removes the "<name>.tmp" of every file the manifest of the prepared
  /// `directory` lists (a command that stops early: commands/command_guard.h).
  /// Returns the listed files that exist, relative to it, in listing order.
  std::vector<std::string> remove_temporaries(const std::string &directory);
} // namespace poundfe

#endif
