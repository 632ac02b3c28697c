// The files an input names (input/named_files.h) and the digest of their
// bytes (base/content_digest.h), which the ranks of an MPI job compare
// before they start (commands/rank_agreement.h).
#include <poundfe/base/content_digest.h>
#include <poundfe/input/named_files.h>

#include <boost/test/unit_test.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace poundfe;

BOOST_AUTO_TEST_CASE(named_files_are_every_file_entry_and_each_tabulated_force)
{
  InputParameters input;
  input.directory = "/data/model";
  input.values    = {{"Model/Number of buildings", "2"},
                     {"Building 1/Mesh file", "../meshes/a.msh"},
                     {"Building 2/Mesh file", ""}, // none
                     {"Ground motion/Record/Second file", ""},
                     {"Ground motion/Record/File", "el-centro.at2"},
                     {"Nodal forces/Tabulated", "1 2 0 ux a.txt; B 1 1 uy /abs/b.txt"},
                     {"Site hazard/Catalogue file", "catalogue.csv"},
                     {"Output/Default files", "true"}, // recorders, not a file
                     {"Output/Directory", "results"}};
  const std::vector<NamedFile> files = named_files(input);
  BOOST_TEST_REQUIRE(files.size() == 5u);
  BOOST_TEST(files[0].entry == "Building 1/Mesh file");
  BOOST_TEST(files[0].path == "/data/meshes/a.msh");
  BOOST_TEST(files[1].given == "el-centro.at2");
  BOOST_TEST(files[1].path == "/data/model/el-centro.at2");
  BOOST_TEST(files[2].entry == "Nodal forces/Tabulated");
  BOOST_TEST(files[2].path == "/data/model/a.txt");
  BOOST_TEST(files[3].path == "/abs/b.txt");
  BOOST_TEST(files[4].path == "/data/model/catalogue.csv");
}

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
  const FileDigest read = digest_of_file(file.string());
  BOOST_TEST(read.unreadable.empty());
  BOOST_TEST(read.value == ContentDigest().add("0 0\n1 1000\n", 11).value());
  std::ofstream(file) << "0 0\n1 2000\n";
  BOOST_TEST(digest_of_file(file.string()).value != read.value);
  std::remove(file.c_str());
  BOOST_TEST(digest_of_file(file.string()).unreadable == "no such file");
  BOOST_TEST(!digest_of_file(file.parent_path().string()).unreadable.empty()); // a directory
}
