// Output writers: CSV round trip, atomic replacement, JSON in memory and streamed.
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/csv_writer.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/plots.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <boost/test/unit_test.hpp>

using namespace poundfe;

BOOST_AUTO_TEST_CASE(csv_round_trips_doubles_exactly)
{
  const std::string path = "/tmp/poundfe-test-roundtrip.csv";
  std::filesystem::remove(path);
  {
    CsvWriter csv(path, {"time", "x"});
    for (int i = 0; i < 20000; ++i) // more than one buffer
      {
        csv.begin_row(i * 0.1);
        csv.add(1.0 / (i + 3));
        csv.end_row();
      }
    BOOST_TEST(!std::filesystem::exists(path)); // nothing until commit
    csv.commit();
  }
  std::ifstream in(path);
  std::string   line;
  std::getline(in, line);
  BOOST_TEST(line == "time,x");
  int i = 0;
  while (std::getline(in, line))
    {
      const double x = std::stod(line.substr(line.find(',') + 1));
      BOOST_TEST(x == 1.0 / (i + 3)); // shortest round-trip form is exact
      ++i;
    }
  BOOST_TEST(i == 20000);
}

BOOST_AUTO_TEST_CASE(uncommitted_files_leave_nothing)
{
  const std::string path = "/tmp/poundfe-test-uncommitted.csv";
  std::filesystem::remove(path);
  {
    CsvWriter csv(path, {"a"});
    csv.begin_row(1);
    csv.end_row();
  }
  BOOST_TEST(!std::filesystem::exists(path));
  BOOST_TEST(!std::filesystem::exists(path + ".tmp"));
}

BOOST_AUTO_TEST_CASE(json_is_well_formed)
{
  JsonWriter json;
  json.begin_object().value("a", 1.5).value("s", "q\"uote").begin_array("list");
  json.begin_object().value("n", 2).end_object().end_array().end_object();
  const std::string text = json.str();
  BOOST_TEST(text.find("\"a\": 1.5") != std::string::npos);
  BOOST_TEST(text.find("\"s\": \"q\\\"uote\"") != std::string::npos);
}

// A streamed summary (JsonWriter into an AtomicFile, handed over in blocks
// of about a megabyte) is the in-memory text to the byte: here about 4 MB,
// so several blocks, with nested objects and arrays across their joins;
// nothing appears before the commit, and an unfinished one leaves nothing.
BOOST_AUTO_TEST_CASE(a_streamed_json_is_the_in_memory_text)
{
  const auto fill = [](JsonWriter &json) {
    json.begin_object().value("program", "poundfe").begin_array("hinges");
    for (int h = 0; h < 40000; ++h)
      json.begin_object()
        .value("label", "B" + std::to_string(h % 97) + "_C" + std::to_string(h))
        .value("peak", 1.0 / (h + 3))
        .value("history", std::vector<double>{h * 0.5, -h * 0.25, 1e-300 * h})
        .end_object();
    json.end_array().value("done", true).end_object();
  };
  JsonWriter memory;
  fill(memory);
  const std::string path = "/tmp/poundfe-test-streamed.json";
  std::filesystem::remove(path);
  {
    AtomicFile file(path);
    JsonWriter streamed(&file);
    fill(streamed);
    streamed.finish();
    BOOST_TEST(!std::filesystem::exists(path)); // nothing until commit
    file.commit();
  }
  std::ifstream      in(path);
  std::ostringstream text;
  text << in.rdbuf();
  BOOST_TEST(memory.str().size() > 3u * (1u << 20)); // more than three blocks
  BOOST_TEST((text.str() == memory.str()));
  std::filesystem::remove(path);
  {
    AtomicFile file(path);
    JsonWriter streamed(&file);
    fill(streamed); // an error before finish() and commit(): unwound
  }
  BOOST_TEST(!std::filesystem::exists(path));
  BOOST_TEST(!std::filesystem::exists(path + ".tmp"));
}

// A count histogram's "set xtics 1" and "set boxwidth 0.8" once reached the
// next figure drawn by the same gnuplot call (thousands of tics, overlapping
// bars): the script resets them, and the ranges, before each panel's own
// settings, a figure after another and a panel under another alike.
BOOST_AUTO_TEST_CASE(plot_script_resets_each_panel)
{
  poundfe::Plot histogram{"pdf_n_impacts.png", "impacts", "number of impacts", "realizations",
                          {{"$counts", "1:2", "realizations", "boxes"}}};
  histogram.settings = "set boxwidth 0.8\nset xtics 1\nset yrange [0:3.3]\n";
  poundfe::Plot next{"cdf_drift.png", "drift", "drift", "P", {{"cdf.csv", "1:2", "ECDF", "steps"}}};
  next.below.push_back(next);
  const std::string script = poundfe::plot_script({histogram, next});
  // each "plot" command and the settings that precede it, back to the last one
  std::vector<std::string> panels;
  std::size_t              from = 0;
  for (std::size_t at = script.find("\nplot "); at != std::string::npos;
       at = script.find("\nplot ", at + 1))
    {
      panels.push_back(script.substr(from, at - from));
      from = at + 1;
    }
  BOOST_REQUIRE_EQUAL(panels.size(), 3u);
  for (const std::string &panel : panels)
    {
      const std::size_t reset = panel.find("set xtics norotate autofreq\n");
      BOOST_CHECK_MESSAGE(reset != std::string::npos, panel);
      BOOST_CHECK(panel.find("set boxwidth\n") != std::string::npos);
      BOOST_CHECK(panel.find("set offsets 0, 0, 0, 0\n") != std::string::npos);
      BOOST_CHECK(panel.find("set autoscale\n") != std::string::npos);
      BOOST_CHECK(panel.find("unset logscale y\n") != std::string::npos);
      // the histogram's own settings come after the reset
      if (panel.find("set xtics 1\n") != std::string::npos)
        BOOST_CHECK_LT(reset, panel.find("set xtics 1\n"));
    }
  BOOST_CHECK(panels[0].find("set boxwidth 0.8\n") != std::string::npos);
  BOOST_CHECK(panels[1].find("set boxwidth 0.8\n") == std::string::npos);
}

namespace
{
  /// The names in `directory`, sorted.
  std::vector<std::string>
  names_in(const std::string &directory)
  {
    std::vector<std::string> names;
    for (const auto &entry : std::filesystem::directory_iterator(directory))
      names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  std::string
  contents_of(const std::string &path)
  {
    std::ifstream      in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
} // namespace

BOOST_AUTO_TEST_CASE(a_name_too_long_for_a_tmp_suffix_is_written_through_a_short_temporary)
{
  // NAME_MAX is 255: "<name>.tmp" of a 252-character name would be 256
  // characters, refused (ENAMETOOLONG) were it the temporary's name.
  const std::string directory = "/tmp/poundfe-test-long-name";
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  for (const std::size_t length : {251, 252, 255})
    {
      const std::string name = std::string(length - 4, 'n') + ".csv";
      {
        AtomicFile file(directory + "/" + name);
        file.write("written\n");
        BOOST_TEST(names_in(directory).size() == 1u); // its temporary alone
        file.commit();
      }
      BOOST_TEST_INFO("name of " << length << " characters");
      BOOST_TEST(names_in(directory) == std::vector<std::string>{name}); // no temporary left
      BOOST_TEST(contents_of(directory + "/" + name) == "written\n");
      {
        AtomicFile file(directory + "/" + name); // uncommitted: its temporary removed
        file.write("not committed\n");
      }
      BOOST_TEST(names_in(directory) == std::vector<std::string>{name});
      BOOST_TEST(contents_of(directory + "/" + name) == "written\n");
      std::filesystem::remove(directory + "/" + name);
    }
  std::filesystem::remove_all(directory);
}

BOOST_AUTO_TEST_CASE(a_link_to_a_regular_file_is_written_through_and_stays_a_link)
{
  // As cp does: the file the link leads to (in another directory, by a
  // relative link) gets the new contents; the link stays a link to it.
  const std::string directory = "/tmp/poundfe-test-link";
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory + "/out");
  std::filesystem::create_directories(directory + "/kept");
  std::ofstream(directory + "/kept/drift.csv") << "old\n";
  std::filesystem::create_symlink("../kept/drift.csv", directory + "/out/drift.csv");
  write_file_atomically(directory + "/out/drift.csv", "new\n");
  BOOST_TEST(std::filesystem::is_symlink(directory + "/out/drift.csv"));
  BOOST_TEST(std::filesystem::read_symlink(directory + "/out/drift.csv") == "../kept/drift.csv");
  BOOST_TEST(contents_of(directory + "/kept/drift.csv") == "new\n");
  BOOST_TEST(names_in(directory + "/out") == std::vector<std::string>{"drift.csv"});
  BOOST_TEST(names_in(directory + "/kept") == std::vector<std::string>{"drift.csv"});
  std::filesystem::remove_all(directory);
}

BOOST_AUTO_TEST_CASE(two_outputs_linked_to_one_file_leave_it_whole)
{
  // Two outputs of one run linked to one file, open at once: each writes
  // its own temporary, so the file is the last commit's contents, whole,
  // and no commit fails; both links stay links and no temporary is left.
  const std::string directory = "/tmp/poundfe-test-two-links";
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory + "/out");
  std::filesystem::create_directories(directory + "/kept");
  std::ofstream(directory + "/kept/shared.csv") << "old\n";
  for (const std::string name : {"drift.csv", "energy.csv"})
    std::filesystem::create_symlink("../kept/shared.csv", directory + "/out/" + name);
  {
    AtomicFile drift(directory + "/out/drift.csv");
    AtomicFile energy(directory + "/out/energy.csv");
    drift.write("time_s,drift\n0,1\n");
    energy.write("time_s,input_J\n0,2\n");
    BOOST_CHECK_NO_THROW(drift.commit());
    BOOST_TEST(contents_of(directory + "/kept/shared.csv") == "time_s,drift\n0,1\n");
    BOOST_CHECK_NO_THROW(energy.commit());
  }
  BOOST_TEST(contents_of(directory + "/kept/shared.csv") == "time_s,input_J\n0,2\n");
  for (const std::string name : {"drift.csv", "energy.csv"})
    BOOST_TEST(std::filesystem::is_symlink(directory + "/out/" + name));
  BOOST_TEST(names_in(directory + "/out") == (std::vector<std::string>{"drift.csv", "energy.csv"}));
  BOOST_TEST(names_in(directory + "/kept") == std::vector<std::string>{"shared.csv"});
  std::filesystem::remove_all(directory);
}
