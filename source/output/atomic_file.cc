#include <poundfe/output/atomic_file.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

namespace poundfe
{
  AtomicFile::AtomicFile(std::string path)
    : final_path(std::move(path))
    , temporary_path(final_path + ".tmp")
    , descriptor(::open(temporary_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666))
  {
    if (descriptor < 0)
      throw std::runtime_error("cannot write " + temporary_path + ": " + std::strerror(errno));
  }

  AtomicFile::~AtomicFile()
  {
    if (descriptor >= 0)
      {
        ::close(descriptor);
        std::remove(temporary_path.c_str());
      }
  }

  void
  AtomicFile::write(const char *data, std::size_t size)
  {
    while (size > 0)
      {
        const ssize_t written = ::write(descriptor, data, size);
        if (written < 0 && errno == EINTR)
          continue;
        if (written < 0)
          throw std::runtime_error("cannot write " + temporary_path + ": " + std::strerror(errno));
        data += written;
        size -= written;
      }
  }

  void
  AtomicFile::overwrite(std::size_t offset, const char *data, std::size_t size)
  {
    while (size > 0)
      {
        const ssize_t written = ::pwrite(descriptor, data, size, offset);
        if (written < 0 && errno == EINTR)
          continue;
        if (written < 0)
          throw std::runtime_error("cannot write " + temporary_path + ": " + std::strerror(errno));
        data += written;
        offset += written;
        size -= written;
      }
  }

  void
  AtomicFile::commit()
  {
    if (descriptor < 0)
      return;
    const bool closed = ::close(descriptor) == 0;
    descriptor        = -1;
    if (!closed || std::rename(temporary_path.c_str(), final_path.c_str()) != 0)
      {
        const std::string reason = std::strerror(errno); // e.g. "No space left on device"
        std::remove(temporary_path.c_str());
        throw std::runtime_error("cannot write " + final_path + ": " + reason);
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
    std::error_code error;
    std::filesystem::create_directories(path, error);
    if (error)
      throw std::runtime_error("cannot create directory " + path + ": " + error.message());
  }
} // namespace poundfe
