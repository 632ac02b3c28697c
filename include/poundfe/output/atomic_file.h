// Files appear complete or not at all: written to "<name>.tmp" and renamed
// into place on commit. An uncommitted file is removed when destroyed.
// Unbuffered: its writers (CsvWriter, NpyWriter) keep one buffer per file
// and hand it over whole, so each block is one write(2) and no second
// buffer copies it again.
#ifndef poundfe_output_atomic_file_h
#define poundfe_output_atomic_file_h

#include <cstddef>
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

    /// Appends. Throws std::runtime_error on I/O failure.
    void write(const char *data, std::size_t size);
    void write(const std::string &text) { write(text.data(), text.size()); }
    /// Overwrites `size` bytes at `offset` of what was written (a header
    /// whose content is known only at the end).
    void overwrite(std::size_t offset, const char *data, std::size_t size);
    /// Close and rename into place. Throws std::runtime_error on I/O failure.
    void commit();
    const std::string &path() const { return final_path; }

  private:
    std::string final_path;
    std::string temporary_path;
    int         descriptor = -1;
  };

  /// Write a whole file atomically.
  void write_file_atomically(const std::string &path, const std::string &contents);

  /// Create a directory and its parents.
  void create_directories(const std::string &path);
} // namespace poundfe

#endif
