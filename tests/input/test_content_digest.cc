// The digest of bytes (base/content_digest.h) and of an input file's
// contents (input_file_digest), which a resumed table and the ranks of an
// MPI job compare (output_directory.h, commands/rank_agreement.h).
#include <poundfe/base/content_digest.h>
#include <poundfe/base/input_text.h>

#include <boost/test/unit_test.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace poundfe;

BOOST_AUTO_TEST_CASE(content_digest_is_fnv_1a_of_the_bytes)
{
  // the FNV-1a test vectors (64 bit): "" and "a"
  BOOST_TEST(ContentDigest().value() == 0xcbf29ce484222325ULL);
  BOOST_TEST(ContentDigest().add("a", 1).value() == 0xaf63dc4c8601ec8cULL);
  // texts carry their length: a boundary moved is another input
  BOOST_TEST(ContentDigest().add(std::string("ab")).add(std::string("c")).value() !=
             ContentDigest().add(std::string("a")).add(std::string("bc")).value());

  const std::filesystem::path file =
    std::filesystem::temp_directory_path() / "poundfe-test-content-digest.txt";
  std::ofstream(file) << "0 0\n1 1000\n";
  const std::string read = input_file_digest(file.string());
  char              hex[17];
  std::snprintf(hex, sizeof hex, "%016llx",
                static_cast<unsigned long long>(ContentDigest().add("0 0\n1 1000\n", 11).value()));
  BOOST_TEST(read == std::string("11 bytes, FNV-1a ") + hex);
  std::ofstream(file) << "0 0\n1 2000\n";
  BOOST_TEST(input_file_digest(file.string()) != read);
  std::remove(file.c_str());
  BOOST_TEST(input_file_digest(file.string()).find("no such file") != std::string::npos);
  BOOST_TEST(input_file_digest(file.parent_path().string()).front() == '('); // a directory
}
