// The file a fuzz target writes each input to, for the readers take a path.
// It lives in a fresh directory under /dev/shm (tmpfs) when the machine has
// one: on a disk file system, truncating and rewriting a file hundreds of
// times a second waits on the journal, and that wait, not the reader, set
// the pace (AT2 target: 0.2 ms of CPU per execution, 3 ms of wall time).
#ifndef POUNDFE_TESTS_FUZZ_SCRATCH_FILE_H
#define POUNDFE_TESTS_FUZZ_SCRATCH_FILE_H

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/stat.h>

namespace poundfe_fuzz
{
  /// `data` written to "<scratch directory>/<name>"; returns that path.
  inline std::string
  write_scratch_file(const std::uint8_t *data, const std::size_t size, const std::string &name)
  {
    static const std::string directory = [] {
      struct stat shm;
      std::string pattern = (stat("/dev/shm", &shm) == 0 && S_ISDIR(shm.st_mode)) ?
                              "/dev/shm/poundfe-fuzz-XXXXXX" :
                              "/tmp/poundfe-fuzz-XXXXXX";
      if (mkdtemp(pattern.data()) == nullptr)
        std::abort(); // no scratch directory: nothing can be fuzzed
      return pattern;
    }();
    // removed when the process exits (each -fork job is a process of its own)
    static const bool removed_at_exit = [] {
      return std::atexit([] {
               std::error_code ignored;
               std::filesystem::remove_all(directory, ignored);
             }) == 0;
    }();
    (void)removed_at_exit;
    const std::string file = directory + "/" + name;
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char *>(data),
                                                static_cast<std::streamsize>(size));
    return file;
  }
} // namespace poundfe_fuzz

#endif
