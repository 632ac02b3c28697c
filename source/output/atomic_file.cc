#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/output_directory.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

namespace poundfe
{
  namespace
  {
    /// Whether `path` names something other than a regular file that
    /// exists (a device such as /dev/null or /dev/stdout, a FIFO): written
    /// in place, never replaced by a renamed temporary nor removed (an
    /// empty temporary_path says so), and not listed as an output that a
    /// later run or a failed one removes.
    bool
    is_stream(const std::string &path)
    {
      struct stat status;
      return ::stat(path.c_str(), &status) == 0 && !S_ISREG(status.st_mode) &&
             !S_ISDIR(status.st_mode);
    }

    /// The file a commit replaces: `path`, or for a symbolic link to a
    /// regular file the file it leads to, written through as cp does, so
    /// that the link stays a link.
    std::string
    destination_of(const std::string &path)
    {
      struct stat status;
      if (::lstat(path.c_str(), &status) != 0 || !S_ISLNK(status.st_mode) ||
          ::stat(path.c_str(), &status) != 0 || !S_ISREG(status.st_mode))
        return path;
      std::error_code error;
      const std::filesystem::path target = std::filesystem::canonical(path, error);
      return error ? path : target.string();
    }

    /// Opens a temporary in `destination`'s directory (the rename stays on
    /// one file system) with O_EXCL, so that no other writer shares it:
    /// ".poundfe-<pid>-<n>.tmp", unique to this process and call.
    int
    open_unique_temporary(const std::string &destination, std::string &temporary)
    {
      static std::atomic<unsigned long> next{0};
      const std::filesystem::path path(destination);
      const std::string directory = path.has_parent_path() ? path.parent_path().string() + "/" : "";
      while (true)
        {
          temporary = directory + ".poundfe-" + std::to_string(::getpid()) + "-" +
                      std::to_string(next++) + ".tmp";
          const int descriptor =
            ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
          if (descriptor >= 0 || errno != EEXIST)
            return descriptor;
        }
    }

    /// Opens the temporary of `path`, which a commit renames onto
    /// `destination`: "<path>.tmp", which a later run's cleanup knows by
    /// its name (output_directory.cc), when `path` is the destination itself
    /// and the name fits NAME_MAX; otherwise a unique temporary. A link's
    /// destination may be reached by several outputs of one run (two links
    /// to one file, or a link to another output): each writes its own
    /// temporary, whole, and the last commit's file is the one that stays.
    /// Returns the descriptor (< 0: errno says why); `temporary` its path.
    int
    open_temporary(const std::string &path,
                   const std::string &destination,
                   std::string       &temporary)
    {
      const bool plain = destination == path &&
                         std::filesystem::path(path).filename().string().size() +
                             std::strlen(".tmp") <= NAME_MAX;
      if (!plain)
        return open_unique_temporary(destination, temporary);
      temporary = path + ".tmp";
      return ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    }

    /// Removes a file's temporary, if it has one (a device's has none).
    void
    remove_temporary(const std::string &temporary_path)
    {
      if (!temporary_path.empty())
        std::remove(temporary_path.c_str());
    }
  } // namespace

  AtomicFile::AtomicFile(std::string path)
    : final_path(std::move(path))
  {
    throw_if_interrupted(); // a safe point: nothing of this file exists yet
    if (is_stream(final_path))
      {
        descriptor = ::open(final_path.c_str(), O_WRONLY | O_CLOEXEC);
        if (descriptor < 0)
          throw OutputError("write", final_path, errno);
        return;
      }
    register_output(final_path); // listed before it exists (output_directory.h)
    descriptor = open_temporary(final_path, destination_of(final_path), temporary_path);
    if (descriptor < 0)
      {
        const int error_number = errno;
        temporary_path.clear(); // nothing of it to remove
        throw OutputError("write", final_path, error_number);
      }
  }

  AtomicFile::~AtomicFile()
  {
    if (descriptor >= 0)
      {
        ::close(descriptor);
        remove_temporary(temporary_path);
      }
  }

  void
  AtomicFile::fail(const int error_number)
  {
    if (descriptor >= 0)
      {
        ::close(descriptor);
        remove_temporary(temporary_path);
        descriptor = -1;
      }
    failed_with = error_number;
    throw OutputError("write", final_path, error_number);
  }

  void
  AtomicFile::write(const char *data, std::size_t size)
  {
    if (failed_with != 0) // the first failure again, already reported by its caller
      throw OutputError("write", final_path, failed_with);
    throw_if_interrupted(); // the destructor removes the temporary
    while (size > 0)
      {
        const ssize_t written = ::write(descriptor, data, size);
        if (written < 0 && errno == EINTR)
          continue;
        if (written < 0)
          fail(errno);
        data += written;
        size -= written;
      }
  }

  void
  AtomicFile::overwrite(std::size_t offset, const char *data, std::size_t size)
  {
    if (failed_with != 0) // the first failure again, already reported by its caller
      throw OutputError("write", final_path, failed_with);
    while (size > 0)
      {
        const ssize_t written = ::pwrite(descriptor, data, size, offset);
        if (written < 0 && errno == EINTR)
          continue;
        if (written < 0)
          fail(errno);
        data += written;
        offset += written;
        size -= written;
      }
  }

  void
  AtomicFile::commit()
  {
    if (failed_with != 0) // the first failure again, already reported by its caller
      throw OutputError("write", final_path, failed_with);
    if (descriptor < 0)
      return;
    throw_if_interrupted(); // before the rename: an interrupted file never appears
    const int closed = ::close(descriptor);
    descriptor       = -1;
    if (closed != 0 ||
        (!temporary_path.empty() &&
         std::rename(temporary_path.c_str(), destination_of(final_path).c_str()) != 0))
      {
        const int error_number = errno; // before remove() may change it
        remove_temporary(temporary_path);
        failed_with = error_number;
        throw OutputError("write", final_path, error_number);
      }
  }

  void
  write_file_atomically(const std::string &path, const std::string &contents)
  {
    AtomicFile file(path);
    file.write(contents);
    file.commit();
  }

  void
  create_directories(const std::string &path)
  {
    register_output(path); // listed before it exists (output_directory.h)
    std::error_code error;
    std::filesystem::create_directories(path, error);
    if (error)
      throw OutputError("create directory", path, error.value());
  }
} // namespace poundfe
