#include <poundfe/base/exceptions.h>
#include <poundfe/output/append_file.h>
#include <poundfe/output/finite_output.h>
#include <poundfe/output/output_directory.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <charconv>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <system_error>
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
    if (syncing.valid())
      syncing.wait(); // the descriptor it syncs stays open until then
    if (descriptor >= 0)
      ::close(descriptor);
  }

  void
  AppendFile::sync()
  {
    if (syncing.valid())
      syncing.wait();
    ::fdatasync(descriptor);
    synced = std::chrono::steady_clock::now();
  }

  void
  AppendFile::append_grouped(const std::string &line)
  {
    append(line, false);
    if (syncing.valid() && syncing.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
      return;
    if (std::chrono::steady_clock::now() - synced > std::chrono::milliseconds(500))
      {
        synced           = std::chrono::steady_clock::now();
        const int handle = descriptor;
        try
          {
            syncing = std::async(std::launch::async, [handle] { ::fdatasync(handle); });
          }
        catch (const std::system_error &) // no thread to be had: sync here
          {
            ::fdatasync(handle);
          }
      }
  }

  void
  AppendFile::append(const std::string &line, const bool sync_now)
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
    if (sync_now)
      sync();
  }

  void
  append_number(std::string &text, const double x)
  {
    if (!std::isfinite(x))
      {
        // a CSV built as text: its header is the first line, the column
        // is the count of commas on the line under way
        const std::size_t line_start = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
        const long        column =
          std::count(text.begin() + line_start, text.end(), ',');
        std::string header = text.substr(0, text.find('\n')), name = "a table value";
        for (long c = 0, from = 0; c <= column && line_start > 0; ++c)
          {
            const std::size_t to = header.find(',', from);
            if (c == column)
              name = header.substr(from, to == std::string::npos ? std::string::npos : to - from);
            if (to == std::string::npos)
              break;
            from = to + 1;
          }
        throw_not_finite(x, name, "");
      }
    char buffer[32];
    text.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, x).ptr);
  }

  void
  append_field(std::string &text, const double x)
  {
    text += ',';
    if (std::isfinite(x))
      append_number(text, x);
  }
} // namespace poundfe
