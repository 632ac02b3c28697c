// The poundfe executable: answers `poundfe --version` itself and hands every
// other command line to the program (source/program.cc), a module it loads
// with dlopen from beside itself (the build tree) or from the installed
// library directory.
//
// Why a module: deal.II links PETSc, SLEPc, Trilinos, OpenCASCADE, Gmsh and
// MPI unconditionally, ~200 shared libraries whose ~320 000 symbol
// relocations take the dynamic loader 0.4-0.6 s of CPU before main runs
// (doc/benchmarks.md, "Start-up"). The executable itself links only the C and
// C++ runtimes, so that the version line costs a millisecond; every command
// needs deal.II and pays that load once, as before.
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

  /// The program module, loaded with its libraries (global, as MPI's
  /// plugins need libmpi's symbols), or nullptr and the reason in `error`.
  void *
  load_program(std::string &error)
  {
    const std::string directory = executable_directory();
    // beside the executable in the build tree; POUNDFE_PROGRAM_FROM_BINDIR
    // (CMakeLists.txt) when installed
    for (const char *relative : {"poundfe-program.so", POUNDFE_PROGRAM_FROM_BINDIR})
      {
        const std::string path = directory + relative;
        if (access(path.c_str(), F_OK) != 0)
          continue;
        if (void *handle = dlopen(path.c_str(), RTLD_LAZY | RTLD_GLOBAL))
          return handle;
        error = dlerror();
        return nullptr;
      }
    error = "poundfe-program.so is neither in " + directory + " nor at " + directory +
            POUNDFE_PROGRAM_FROM_BINDIR;
    return nullptr;
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
  std::string error;
  void       *program = load_program(error);
  using Main          = int (*)(int, char **);
  const Main program_main =
    program ? reinterpret_cast<Main>(dlsym(program, "poundfe_program_main")) : nullptr;
  if (program && !program_main)
    error = dlerror();
  if (!program_main)
    {
      std::fprintf(stderr, "poundfe: error: cannot load the program: %s\n", error.c_str());
      return 1;
    }
  return program_main(argc, argv);
}
