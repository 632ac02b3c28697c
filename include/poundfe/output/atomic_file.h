// Files appear complete or not at all: written to "<name>.tmp" and renamed
// into place on commit. An uncommitted file is removed when destroyed.
#ifndef poundfe_output_atomic_file_h
#define poundfe_output_atomic_file_h

#include <cstdio>
#include <string>

namespace poundfe
{
  class AtomicFile
  {
  public:
    explicit AtomicFile(std::string path);
    ~AtomicFile();
    AtomicFile(const AtomicFile &) = delete;
    AtomicFile &operator=(const AtomicFile &) = delete;

    void write(const char *data, std::size_t size);
    void write(const std::string &text) { write(text.data(), text.size()); }
    /// Flush, close and rename into place. Throws std::runtime_error on I/O failure.
    void commit();
    const std::string &path() const { return final_path; }

  private:
    std::string final_path;
    std::string temporary_path;
    std::FILE  *file = nullptr;
  };

  /// Write a whole file atomically.
  void write_file_atomically(const std::string &path, const std::string &contents);

  /// Create a directory and its parents.
  void create_directories(const std::string &path);
} // namespace poundfe

#endif
