// One command's results per output directory (output/output_directory.h)
// and files that fail cleanly (output/atomic_file.h), issue 14 items 11-12:
//  - every writer lists its file in the manifest before creating it, so a
//    second command removes exactly what the first one wrote (with a killed
//    command's temporaries), keeps the user's files and the files it resumes
//    from, and removes the subdirectories it emptied;
//  - a damaged manifest cannot make it delete outside the directory;
//  - a write to a full device (/dev/full) throws OutputError naming the file
//    and "No space left on device", prefixed "disk full", and leaves no
//    temporary; a commit over a directory says "Is a directory".
// The reference is the file system itself: what exists afterwards.
#include <poundfe/base/exceptions.h>
#include <poundfe/output/append_file.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/output_directory.h>

#include "output_test_files.h"

#include <unistd.h>

#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <set>
#include <utility>
#include <vector>
#include <string>

using namespace poundfe;
namespace fs = std::filesystem;

namespace
{
  using poundfe_test::fresh_directory;

  /// Every file and directory under `directory`, relative, sorted.
  std::set<std::string>
  tree(const std::string &directory)
  {
    std::set<std::string> names;
    for (const auto &entry : fs::recursive_directory_iterator(directory))
      names.insert(fs::relative(entry.path(), directory).generic_string());
    return names;
  }

  void
  touch(const std::string &path, const std::string &text = "x")
  {
    std::ofstream(path) << text;
  }
} // namespace

BOOST_AUTO_TEST_CASE(a_second_command_removes_what_the_first_wrote_and_nothing_else)
{
  const std::string dir = fresh_directory("reused");
  prepare_output_directory(dir);
  write_file_atomically(dir + "/summary.json", "{}");
  write_file_atomically(dir + "/contact_force.csv", "time\n");
  create_directories(dir + "/solution");
  for (const char *frame : {"solution-00000.vtu", "solution-00001.vtu", "solution-00002.vtu"})
    write_file_atomically(dir + "/solution/" + frame, "<VTKFile/>");
  AppendFile(dir + "/realizations.csv").append("realization\n");
  {
    AtomicFile killed(dir + "/hinges.csv"); // listed when made
  }
  touch(dir + "/hinges.csv.tmp"); // what a process killed while writing it leaves
  touch(dir + "/notes.txt");                // the user's
  touch(dir + "/solution/user-frame.vtu");  // the user's, in a directory poundfe made
  fs::create_directories(dir + "/modal");   // another command's directory, not listed
  touch(dir + "/modal/summary.json");

  // the second command resumes from realizations.csv and writes one frame
  prepare_output_directory(dir, {"realizations.csv"});
  write_file_atomically(dir + "/solution/solution-00000.vtu", "<VTKFile/>");
  const std::set<std::string> expected{".poundfe-files",
                                       "modal",
                                       "modal/summary.json",
                                       "notes.txt",
                                       "realizations.csv",
                                       "solution",
                                       "solution/solution-00000.vtu",
                                       "solution/user-frame.vtu"};
  BOOST_TEST(tree(dir) == expected, boost::test_tools::per_element());

  // a third command that does not resume: what the second listed goes,
  // including the kept realizations.csv; the emptied directory goes too
  fs::remove(dir + "/solution/user-frame.vtu");
  prepare_output_directory(dir);
  const std::set<std::string> left{".poundfe-files", "modal", "modal/summary.json", "notes.txt"};
  BOOST_TEST(tree(dir) == left, boost::test_tools::per_element());
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(the_next_command_removes_unique_temporaries_a_kill_left)
{
  // AtomicFile's ".poundfe-<pid>-<n>.tmp" (a name too long for "<name>.tmp")
  // left by a process killed with -9: removed by the next command, in the
  // directory and in one it listed, when their process is gone (no pid is
  // 999999999: above any pid_max). This process's, and other names, stay.
  const std::string dir = fresh_directory("stale-temporaries");
  prepare_output_directory(dir);
  write_file_atomically(dir + "/summary.json", "{}");
  create_directories(dir + "/solution");
  write_file_atomically(dir + "/solution/solution-00000.vtu", "<VTKFile/>");
  const std::string live = ".poundfe-" + std::to_string(::getpid()) + "-0.tmp";
  touch(dir + "/.poundfe-999999999-0.tmp");
  touch(dir + "/solution/.poundfe-999999999-7.tmp");
  touch(dir + "/" + live);
  touch(dir + "/.poundfe-notes-0.tmp"); // not a pid: the user's
  prepare_output_directory(dir);
  const std::set<std::string> expected{".poundfe-files", ".poundfe-notes-0.tmp", live};
  BOOST_TEST(tree(dir) == expected, boost::test_tools::per_element());
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_link_is_written_through_by_one_command_and_replaced_by_the_next)
{
  // The link is a listed output: the next command's cleaning removes it and
  // writes a regular file; the file it led to keeps the first results.
  const std::string parent = fresh_directory("link-one-command");
  const std::string dir    = parent + "/out";
  fs::create_directories(parent + "/kept");
  touch(parent + "/kept/drift.csv", "old\n");
  fs::create_directories(dir);
  fs::create_symlink("../kept/drift.csv", dir + "/drift.csv");
  prepare_output_directory(dir);
  write_file_atomically(dir + "/drift.csv", "first\n");
  BOOST_TEST(fs::is_symlink(dir + "/drift.csv"));
  BOOST_TEST(poundfe_test::read_bytes(parent + "/kept/drift.csv") == "first\n");
  prepare_output_directory(dir);
  write_file_atomically(dir + "/drift.csv", "second\n");
  BOOST_TEST(!fs::is_symlink(dir + "/drift.csv"));
  BOOST_TEST(poundfe_test::read_bytes(dir + "/drift.csv") == "second\n");
  BOOST_TEST(poundfe_test::read_bytes(parent + "/kept/drift.csv") == "first\n");
  fs::remove_all(parent);
}

BOOST_AUTO_TEST_CASE(a_damaged_manifest_cannot_reach_outside_the_directory)
{
  const std::string parent = fresh_directory("manifest-outside");
  const std::string dir    = parent + "/results";
  fs::create_directories(dir);
  touch(parent + "/precious.txt");
  touch(dir + "/inside.csv");
  std::ofstream(dir + "/" + output_manifest_name)
    << "../precious.txt\n" << fs::absolute(parent + "/precious.txt").string() << "\n"
    << "inside.csv\n\n.poundfe-files\n";
  prepare_output_directory(dir);
  BOOST_TEST(fs::exists(parent + "/precious.txt"));
  BOOST_TEST(!fs::exists(dir + "/inside.csv"));
  BOOST_TEST(fs::exists(dir + "/" + output_manifest_name));
  fs::remove_all(parent);
}

BOOST_AUTO_TEST_CASE(a_symbolic_link_never_leads_the_cleaning_outside_the_directory)
{
  // poundfe listed solution/frame.vtu, results.csv and their temporaries;
  // the user then put links in their place or in the way to them, and
  // edited the manifest: nothing outside may go, nor be truncated
  const std::string parent = fresh_directory("manifest-links");
  const std::string dir = parent + "/results", outside = parent + "/outside";
  fs::create_directories(dir);
  fs::create_directories(outside + "/deep");
  for (const char *name : {"frame.vtu", "frame.vtu.tmp", "results.csv", "deep/kept.txt", "notes.txt"})
    touch(outside + "/" + name, "the user's");
  fs::create_directory_symlink(outside, dir + "/solution");      // a listed directory
  fs::create_symlink(outside + "/results.csv", dir + "/results.csv"); // a listed file
  fs::create_directory_symlink(outside + "/deep", dir + "/deep");
  touch(dir + "/inside.csv");
  std::ofstream(dir + "/" + output_manifest_name)
    << "solution/frame.vtu\nsolution\nresults.csv\ndeep/kept.txt\ndeep\ninside.csv\n"
    << "solution/../outside/notes.txt\n./inside.csv\n" << fs::absolute(outside).string() << "/notes.txt\n";
  const auto outside_intact = [&]() {
    for (const char *name : {"frame.vtu", "frame.vtu.tmp", "results.csv", "deep/kept.txt", "notes.txt"})
      {
        BOOST_TEST(fs::exists(outside + "/" + name), name);
        BOOST_TEST(poundfe_test::read_bytes(outside + "/" + name) == "the user's", name);
      }
  };
  prepare_output_directory(dir);
  outside_intact();
  BOOST_TEST(!fs::exists(dir + "/inside.csv"));
  BOOST_TEST(!fs::exists(fs::symlink_status(dir + "/results.csv"))); // the link alone went

  // a command that lists a file behind the link and is then undone (bad
  // input found late) or stopped (its temporaries removed)
  fs::create_directory_symlink(outside, dir + "/solution");
  write_file_atomically(dir + "/inside.csv", "x");
  register_output(dir + "/solution/frame.vtu");
  BOOST_TEST(remove_temporaries(dir) == std::vector<std::string>{"inside.csv"},
             boost::test_tools::per_element());
  discard_output_directory(dir);
  outside_intact();

  // a link in the manifest's place: the file it points to is not truncated
  fs::create_directories(dir);
  fs::create_symlink(outside + "/notes.txt", dir + "/" + output_manifest_name);
  prepare_output_directory(dir);
  write_file_atomically(dir + "/summary.json", "{}");
  outside_intact();
  BOOST_TEST(!fs::is_symlink(fs::symlink_status(dir + "/" + output_manifest_name)));
  fs::remove_all(parent);
}

BOOST_AUTO_TEST_CASE(a_resumed_table_is_tied_to_the_contents_of_the_files_its_input_names)
{
  const std::string dir    = fresh_directory("resume-digests");
  const std::string record = dir + "/record.txt", table = dir + "/out/realizations.csv";
  fs::create_directories(dir);
  touch(record, "0 0.1\n0.01 0.2\n");
  const std::vector<std::pair<std::string, std::string>> inputs{{"command", "montecarlo"},
                                                                {"Ground motion/Type", "record"}};
  const std::vector<NamedInputFile> files{
    {"Ground motion/Record/File", "record file", "record.txt", record}};
  const auto resume = [&]() {
    expect_output_directory(dir + "/out", inputs, files);
    prepare_output_directory(dir + "/out", {"realizations.csv"});
    resume_file(table);
    expect_output_directory("");
  };
  const auto refused = [&](const std::string &words) {
    try
      {
        resume();
        BOOST_ERROR("resumed; expected: " << words);
      }
    catch (const InputError &e)
      {
        BOOST_TEST_MESSAGE(e.what());
        BOOST_TEST(std::string(e.what()).find(words) != std::string::npos, e.what());
      }
  };
  resume(); // the first run: the record written, with the record file's digest
  BOOST_TEST(poundfe_test::read_bytes(table + ".inputs").find(
               "digest of the record file 'record.txt' (Ground motion/Record/File) = 15 bytes, "
               "FNV-1a ") != std::string::npos);
  AppendFile(table).append("realization\n");
  resume(); // the same file: resumed
  touch(record, "0 0.2\n0.01 0.4\n"); // doubled: the same size, other bytes
  refused("the record file 'record.txt' (Ground motion/Record/File) changed since these "
          "realizations were computed");
  fs::remove(record);
  refused("the record file 'record.txt' (Ground motion/Record/File) changed");
  touch(record, "0 0.1\n0.01 0.2\n");
  resume(); // back as it was

  // a record of an earlier version (no digest lines) cannot be checked
  std::ofstream(table + ".inputs") << "command = montecarlo\nGround motion/Type = record\n";
  refused("no digest of the files the input names");
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_full_device_is_reported_with_its_reason_and_leaves_no_temporary)
{
  const std::string dir = fresh_directory("full");
  prepare_output_directory(dir);
  // the temporary of drift.csv is /dev/full: every write fails with ENOSPC
  fs::create_symlink("/dev/full", dir + "/drift.csv.tmp");
  try
    {
      AtomicFile file(dir + "/drift.csv");
      file.write(std::string(1000, 'x'));
      file.commit();
      BOOST_FAIL("a write to /dev/full succeeded");
    }
  catch (const OutputError &e)
    {
      const std::string message = e.what();
      BOOST_TEST_MESSAGE(message);
      BOOST_TEST(message.rfind("disk full: cannot write " + dir + "/drift.csv: ", 0) == 0);
      BOOST_TEST(message.find("No space left on device") != std::string::npos);
    }
  BOOST_TEST(!fs::exists(fs::symlink_status(dir + "/drift.csv.tmp")));
  BOOST_TEST(!fs::exists(dir + "/drift.csv"));

  // summary.json cannot replace a directory: the reason, no temporary
  fs::create_directories(dir + "/summary.json");
  try
    {
      write_file_atomically(dir + "/summary.json", "{}");
      BOOST_FAIL("renamed over a directory");
    }
  catch (const OutputError &e)
    {
      const std::string message = e.what();
      BOOST_TEST_MESSAGE(message);
      BOOST_TEST(message == "cannot write " + dir + "/summary.json: Is a directory");
    }
  BOOST_TEST(!fs::exists(dir + "/summary.json.tmp"));
  fs::remove_all(dir);
}
