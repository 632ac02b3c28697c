#include <poundfe/base/content_digest.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

namespace poundfe
{
  ContentDigest &
  ContentDigest::add(const char *bytes, const std::size_t n)
  {
    for (std::size_t i = 0; i < n; ++i)
      {
        hash ^= static_cast<unsigned char>(bytes[i]);
        hash *= 1099511628211ULL; // the FNV prime
      }
    return *this;
  }

  ContentDigest &
  ContentDigest::add(const std::string &text)
  {
    const std::uint64_t n = text.size();
    char                length[sizeof n];
    std::memcpy(length, &n, sizeof n);
    return add(length, sizeof n).add(text.data(), text.size());
  }

  FileDigest
  digest_of_file(const std::string &path)
  {
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::file_type type = fs::status(path, error).type();
    if (type == fs::file_type::not_found)
      return {0, "no such file"};
    if (type != fs::file_type::regular)
      return {0, error ? error.message() : "not a regular file"};
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in)
      return {0, errno != 0 ? std::strerror(errno) : "cannot open it"};
    ContentDigest     digest;
    std::vector<char> buffer(1 << 16);
    while (in.read(buffer.data(), buffer.size()) || in.gcount() > 0)
      digest.add(buffer.data(), static_cast<std::size_t>(in.gcount()));
    if (in.bad())
      return {0, "an error while reading it"};
    return {digest.value(), ""};
  }
} // namespace poundfe
