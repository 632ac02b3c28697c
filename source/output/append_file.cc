#include <poundfe/base/exceptions.h>
#include <poundfe/output/append_file.h>
#include <poundfe/output/output_directory.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <unistd.h>

namespace poundfe
{
  AppendFile::AppendFile(const std::string &file)
    : path(file)
  {
    register_output(path); // listed before it exists (output_directory.h)
    descriptor = ::open(file.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
    if (descriptor < 0)
      throw OutputError("open for appending", path, errno);
  }

  AppendFile::~AppendFile()
  {
    if (descriptor >= 0)
      ::close(descriptor);
  }

  void
  AppendFile::append(const std::string &line)
  {
    const char *data = line.data();
    std::size_t left = line.size();
    while (left > 0)
      {
        const ssize_t written = ::write(descriptor, data, left);
        if (written < 0)
          {
            if (errno == EINTR)
              continue;
            throw OutputError("write", path, errno);
          }
        data += written;
        left -= written;
      }
    ::fdatasync(descriptor);
  }

  void
  append_number(std::string &text, const double x)
  {
    char buffer[32];
    text.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, x).ptr);
  }
} // namespace poundfe
