// Files appear complete or not at all: written to a temporary beside them
// (atomic_file.cc says which) and renamed into place on commit, a link to a
// file written through. An uncommitted file is removed when destroyed, and
// at once when a write fails (a full disk gets its space back for the
// summary that reports it). Failures throw OutputError (base/exceptions.h)
// with the operating system's reason. Each call is a safe point where a
// command that stops at them (base/interruption.h) throws Interrupted.
// Unbuffered: its writers (CsvWriter, NpyWriter) hand over one buffer per
// file whole, so each block is one write(2) and no second buffer copies it.
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

    /// Appends. Throws OutputError on I/O failure, after removing the
    /// temporary; every later call throws the same error again.
    void write(const char *data, std::size_t size);
    void write(const std::string &text) { write(text.data(), text.size()); }
    /// Overwrites `size` bytes at `offset` of what was written (a header
    /// whose content is known only at the end).
    void overwrite(std::size_t offset, const char *data, std::size_t size);
    /// Close and rename into place. Throws OutputError on I/O failure.
    void commit();
    const std::string &path() const { return final_path; }

  private:
    /// Removes the temporary and throws OutputError(errno = error_number).
    [[noreturn]] void fail(int error_number);

    std::string final_path;
    std::string temporary_path;
    int         descriptor = -1;
    int         failed_with = 0; // errno of the first failure, 0: none
  };

  /// Write a whole file atomically.
  void write_file_atomically(const std::string &path, const std::string &contents);

  /// Create a directory and its parents. Throws OutputError.
  void create_directories(const std::string &path);
} // namespace poundfe

#endif
