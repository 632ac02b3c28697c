// A digest of text and of a file's bytes (64-bit FNV-1a; Fowler, Noll and
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

  /// The digest of a file's bytes, or of what stopped it from being read.
  struct FileDigest
  {
    std::uint64_t value = 0;
    /// Why the file could not be read (not a regular file, no such file,
    /// an error while reading), "" when it was: then `value` is the
    /// digest of its bytes.
    std::string unreadable;
  };

  /// The digest of `path`'s bytes. Only a regular file is opened (a FIFO
  /// would wait for a writer, a device never ends).
  FileDigest digest_of_file(const std::string &path);
} // namespace poundfe

#endif
