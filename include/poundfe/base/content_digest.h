// A digest of text and bytes (64-bit FNV-1a; Fowler, Noll and
// Vo, IETF draft-eastlake-fnv): cheap and the same on every machine, for
// telling whether two processes were given the same input. Not a
// cryptographic hash: it detects accidents (another file, an edited one),
// not a forgery.
#ifndef poundfe_base_content_digest_h
#define poundfe_base_content_digest_h

#include <cstddef>
#include <cstdint>
#include <string>

namespace poundfe
{
  /// A running 64-bit FNV-1a digest.
  class ContentDigest
  {
  public:
    ContentDigest &add(const char *bytes, std::size_t n);
    /// The text and its length (so that "ab"+"c" and "a"+"bc" differ).
    ContentDigest &add(const std::string &text);
    std::uint64_t  value() const { return hash; }

  private:
    std::uint64_t hash = 14695981039346656037ULL; // the FNV offset basis
  };
} // namespace poundfe

#endif
