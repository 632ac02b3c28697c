// The poundfe executable: answers `poundfe --version` itself and hands every
// other command line to the program (source/program.cc), a module it loads
// with dlopen from beside itself (the build tree) or from the installed
// library directory; `poundfe opensees SCRIPT [ARGS...]` goes to the lean
// module of the OpenSees interpreter instead (source/opensees_program.cc).
//
// Why modules: deal.II links PETSc, SLEPc, Trilinos, OpenCASCADE, Gmsh and
// MPI unconditionally, ~200 shared libraries whose ~320 000 symbol
// relocations take the dynamic loader 0.3-0.6 s of CPU before main runs
// (doc/benchmarks.md, "Start-up"). The executable itself links only the C and
// C++ runtimes, so that the version line costs a millisecond; the
// interpreter's module links Tcl, UMFPACK and the runtimes, no deal.II, so
// that a short script is not dominated by that load; every other command
// needs deal.II and pays it once, as before.
#include <dlfcn.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <string>

namespace poundfe
{
  /// "poundfe (git REVISION), deal.II VERSION", written by scripts/revision.cmake at build time.
  extern const char *const version_line;
} // namespace poundfe

namespace
{
  /// The directory of this executable, with its trailing '/' (empty when
  /// /proc cannot say it: the module is then looked for relative to the
  /// working directory, and not found).
  std::string
  executable_directory()
  {
    std::string  path(4096, '\0');
    const auto   n     = readlink("/proc/self/exe", path.data(), path.size());
    const size_t slash = n > 0 ? path.rfind('/', static_cast<size_t>(n)) : std::string::npos;
    return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
  }

  /// The module `name`, loaded with its libraries (global, as MPI's
  /// plugins need libmpi's symbols), or nullptr and the reason in `error`.
  void *
  load_module(const std::string &name, std::string &error)
  {
    const std::string directory = executable_directory();
    // beside the executable in the build tree; in POUNDFE_MODULES_FROM_BINDIR
    // (CMakeLists.txt) when installed
    for (const std::string &path : {directory + name,
                                    directory + POUNDFE_MODULES_FROM_BINDIR + name})
      {
        if (access(path.c_str(), F_OK) != 0)
          continue;
        if (void *handle = dlopen(path.c_str(), RTLD_LAZY | RTLD_GLOBAL))
          return handle;
        error = dlerror();
        return nullptr;
      }
    error = name + " is neither in " + directory + " nor in " + directory +
            POUNDFE_MODULES_FROM_BINDIR;
    return nullptr;
  }

  /// Whether the command line is `poundfe opensees SCRIPT [ARGS...]`, which
  /// the interpreter's module runs alone: every word after the script is
  /// the script's own (the program's parsing, program.cc), and any other
  /// form (an option first, no script) is the program's to parse or refuse.
  bool
  runs_a_script(const int argc, char **argv)
  {
    const auto is_option = [](const char *word) { return word[0] == '-' && word[1] != '\0'; };
    return argc >= 3 && std::strcmp(argv[1], "opensees") == 0 && !is_option(argv[2]);
  }
} // namespace

int
main(int argc, char **argv)
{
  // Only the lone option: in any other command line --version is one word
  // among others, which the program checks (an unknown option is refused).
  if (argc == 2 && std::strcmp(argv[1], "--version") == 0)
    {
      std::printf("%s\n", poundfe::version_line);
      return 0;
    }
  const bool  lean   = runs_a_script(argc, argv);
  std::string error;
  void       *module = load_module(lean ? "poundfe-opensees.so" : "poundfe-program.so", error);
  using Main         = int (*)(int, char **);
  const char *entry  = lean ? "poundfe_opensees_main" : "poundfe_program_main";
  const Main  module_main = module ? reinterpret_cast<Main>(dlsym(module, entry)) : nullptr;
  if (module && !module_main)
    error = dlerror();
  if (!module_main)
    {
      std::fprintf(stderr, "poundfe: error: cannot load the program: %s\n", error.c_str());
      return 1;
    }
  return module_main(argc, argv);
}
