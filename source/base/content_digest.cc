#include <poundfe/base/content_digest.h>

#include <cstring>

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
} // namespace poundfe
