// Output speed (issue 12): the writers of the time series and what they
// write.
//  - NumberText gives std::to_chars's text for every double, whether it
//    remembers the number or not (its table is keyed by the bits).
//  - shortest_text (Dragonbox's digits in std::to_chars's layout) gives
//    std::to_chars's bytes on 2*10^6 doubles of random bits and on edge
//    values (bench/shortest_double.cc --check runs 10^8).
//  - Buffering: CsvWriter and NpyWriter write exactly the rows given, across
//    many buffers and for rows wider than a buffer's block.
//  - Decimation: a recorder every k steps writes the rows of steps 0, k, 2k,
//    ..., with the time of each step to the bit.
//  - .npy against CSV: the same run written in both formats; the .npy files,
//    read by a reader written here from the format's definition (NEP 1,
//    version 1.0), hold the CSV's numbers to the bit and its column names
//    in <name>.columns.txt. summary.json lists exactly the files in the
//    directory, and a run in npy over an earlier CSV run's directory leaves
//    none of that run's tables.
//  - In memory (MemoryResults, Python's results): the same run's tables
//    hold the CSV's numbers to the bit, its other texts (summary.json but
//    for the wall time, impacts.csv, the profiles) are the files' bytes,
//    and no directory is made.
// Every comparison is exact: both formats are exact encodings of the same
// doubles (CSV: the shortest text that strtod reads back to the same
// double; glibc's strtod rounds correctly), so any difference is a bug.
#include <poundfe/base/exceptions.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/report/run_outputs.h>
#include <poundfe/output/csv_writer.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/npy_writer.h>
#include <poundfe/output/number_text.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/shortest_text.h>

#include "output_test_files.h"

#include <boost/test/unit_test.hpp>

#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <regex>
#include <set>
#include <sstream>

using namespace poundfe;

namespace
{
  using poundfe_test::fresh_directory;
  using poundfe_test::read_bytes;
  using poundfe_test::read_csv;
  using poundfe_test::Table;

  /// A .npy file of float64 read from the format's definition: magic
  /// "\x93NUMPY", version 1.0, little-endian uint16 header length, a dict
  /// literal ending in '\n' (10 + length a multiple of 64), then the data.
  /// The data are decoded from little-endian bytes whatever this machine's
  /// byte order.
  Table
  read_npy(const std::string &path)
  {
    const std::string bytes = read_bytes(path);
    BOOST_REQUIRE(bytes.size() >= 10);
    BOOST_REQUIRE(bytes.compare(0, 6, "\x93NUMPY") == 0);
    BOOST_TEST(int(bytes[6]) == 1);
    BOOST_TEST(int(bytes[7]) == 0);
    const std::size_t length =
      static_cast<unsigned char>(bytes[8]) | static_cast<unsigned char>(bytes[9]) << 8;
    BOOST_REQUIRE(bytes.size() >= 10 + length);
    BOOST_TEST((10 + length) % 64 == 0u);
    const std::string dict = bytes.substr(10, length);
    BOOST_TEST(dict.back() == '\n');
    std::smatch m;
    BOOST_REQUIRE_MESSAGE(
      std::regex_match(dict, m,
                       std::regex(R"(\{'descr': '<f8', 'fortran_order': False, 'shape': \((\d+), (\d+)\), \} *\n)")),
      "header " << dict);
    const std::size_t rows = std::stoul(m[1]), columns = std::stoul(m[2]);
    BOOST_REQUIRE(bytes.size() == 10 + length + 8 * rows * columns);
    Table table;
    table.rows.assign(rows, std::vector<double>(columns));
    const unsigned char *data = reinterpret_cast<const unsigned char *>(bytes.data()) + 10 + length;
    for (std::size_t i = 0; i < rows * columns; ++i, data += 8)
      {
        std::uint64_t bits = 0;
        for (int b = 7; b >= 0; --b)
          bits = bits << 8 | data[b];
        std::memcpy(&table.rows[i / columns][i % columns], &bits, 8);
      }
    std::istringstream names(read_bytes(NpyWriter::columns_path(path)));
    for (std::string name; std::getline(names, name);)
      table.header.push_back(name);
    BOOST_TEST(table.header.size() == columns);
    return table;
  }

  /// Equal to the bit (NaN included).
  bool
  same_bits(const double a, const double b)
  {
    return std::memcmp(&a, &b, sizeof a) == 0;
  }

  void
  require_same(const Table &a, const Table &b, const std::string &what)
  {
    BOOST_TEST(a.header == b.header, what);
    BOOST_REQUIRE_MESSAGE(a.rows.size() == b.rows.size(), what << ": " << a.rows.size() << " rows, "
                                                               << b.rows.size());
    std::size_t different = 0;
    for (std::size_t i = 0; i < a.rows.size(); ++i)
      for (std::size_t j = 0; j < a.rows[i].size(); ++j)
        different += !same_bits(a.rows[i][j], b.rows[i][j]);
    BOOST_TEST(different == 0u, what << ": " << different << " numbers differ");
  }

  /// The names of summary.json's output.files.
  std::set<std::string>
  listed_files(const std::string &directory)
  {
    const std::string json = read_bytes(directory + "/summary.json");
    const auto        at   = json.find("\"files\": [");
    BOOST_REQUIRE(at != std::string::npos);
    const std::string list = json.substr(at, json.find(']', at) - at);
    std::set<std::string> names;
    const std::regex      quoted("\"([^\"]+)\"");
    for (auto i = std::sregex_iterator(list.begin() + 9, list.end(), quoted); i != std::sregex_iterator(); ++i)
      names.insert((*i)[1]);
    return names;
  }

  std::set<std::string>
  files_in(const std::string &directory)
  {
    std::set<std::string> names;
    for (const auto &entry : std::filesystem::directory_iterator(directory))
      if (entry.path().filename() != output_manifest_name) // what poundfe wrote there, not a result
        names.insert(entry.path().filename());
    return names;
  }

  RunResult
  run(InputParameters input, const OutputFormat format, const std::string &directory)
  {
    input.output.recorders.format = format;
    const Analysis   analysis     = prepare_analysis(input);
    RunOptions       options;
    options.output_directory = directory;
    options.plots            = false;
    options.vtu              = false;
    return run_time_history(analysis, run_parameters(input), make_excitation(analysis, input),
                            options);
  }
} // namespace

BOOST_AUTO_TEST_CASE(number_text_is_to_chars_text)
{
  // A pool of 3000 numbers (more than the 256 slots: collisions and
  // evictions), drawn 10^6 times: hits and misses both. Exact text.
  std::mt19937_64                  random(12);
  std::normal_distribution<double> normal;
  std::vector<double>              pool{0.0, -0.0, 1.0, 5e-324, 1.7976931348623157e308, 1e22, 1e23,
                                        std::nan(""), -INFINITY, 123456789012345678.0};
  for (int i = 0; pool.size() < 3000; ++i)
    pool.push_back(i % 3 == 0 ? i * 5e-4 : normal(random) * std::pow(10.0, int(random() % 30) - 15));
  NumberText  text;
  std::size_t different = 0;
  for (int i = 0; i < 1000000; ++i)
    {
      const double x = pool[random() % pool.size()];
      char         expected[64], got[NumberText::max_length + 8];
      const auto   end = std::to_chars(expected, expected + sizeof expected, x).ptr;
      different += std::string(got, text.write(got, x)) != std::string(expected, end);
    }
  BOOST_TEST(different == 0u);
}

BOOST_AUTO_TEST_CASE(shortest_text_is_to_chars_text)
{
  // Edge values: ±0, the limits, every power of 2, the powers of 10, the
  // integers around 2^53 and 10^16 (plain texts of the exact integer), and
  // their neighbours; then 2*10^6 doubles of random bits (every exponent,
  // subnormals, NaN, infinities). Exact bytes.
  std::vector<double> edges{0.0, 5e-324, 2.2250738585072014e-308, 1.7976931348623157e308,
                            INFINITY, std::nan(""), 123456789012345678.0};
  for (int p = -1074; p <= 1023; ++p)
    edges.push_back(std::ldexp(1.0, p));
  for (int p = -323; p <= 308; ++p)
    edges.push_back(std::pow(10.0, p));
  for (const double base : {9007199254740992.0, 1e16, 1e17})
    for (int i = -300; i <= 300; ++i)
      edges.push_back(base + i * 16.0);
  for (std::size_t i = 0, n = edges.size(); i < n; ++i)
    for (const double x : {edges[i], std::nextafter(edges[i], 0.0), std::nextafter(edges[i], INFINITY)})
      for (const double signed_x : {x, -x})
        edges.push_back(signed_x);
  std::mt19937_64 random(57);
  std::size_t     different = 0;
  auto            compare   = [&different](const double x) {
    char       expected[64], got[shortest_text_room + 8];
    const auto end = std::to_chars(expected, expected + sizeof expected, x).ptr;
    different += std::string(got, shortest_text(got, x)) != std::string(expected, end);
  };
  for (const double x : edges)
    compare(x);
  for (int i = 0; i < 2000000; ++i)
    {
      const std::uint64_t bits = random();
      double              x;
      std::memcpy(&x, &bits, sizeof x);
      compare(x);
    }
  BOOST_TEST(different == 0u);
}

BOOST_AUTO_TEST_CASE(buffers_write_exactly_the_rows_given)
{
  // 30 000 rows of 4 numbers (1.5 MB of CSV, 0.96 MB of .npy: many 64 KiB
  // blocks), then 40 rows of 3000 numbers (a row wider than a block).
  const std::string dir = fresh_directory("table-writers");
  std::filesystem::create_directories(dir);
  for (const std::size_t width : {std::size_t(4), std::size_t(3000)})
    {
      const std::size_t        n_rows = width == 4 ? 30000 : 40;
      std::vector<std::string> header{"time_s"};
      for (std::size_t j = 1; j < width; ++j)
        header.push_back("c" + std::to_string(j));
      Table expected{header, {}};
      for (const char *name : {"t.csv", "t.npy", "t.columns.txt"})
        std::filesystem::remove(dir + "/" + name); // of the first width
      {
        CsvWriter           csv(dir + "/t.csv", header);
        NpyWriter           npy(dir + "/t.npy", header);
        std::vector<double> values(width - 1);
        for (std::size_t i = 0; i < n_rows; ++i)
          {
            for (std::size_t j = 0; j < values.size(); ++j)
              values[j] = std::sin(1.0 + i * width + j) * std::pow(10.0, double(j % 7) - 3);
            csv.add_row(i * 1e-3, values);
            npy.add_row(i * 1e-3, values);
            expected.rows.push_back({i * 1e-3});
            expected.rows.back().insert(expected.rows.back().end(), values.begin(), values.end());
          }
        // nothing is in place before commit
        BOOST_TEST(!std::filesystem::exists(dir + "/t.csv"));
        BOOST_TEST(!std::filesystem::exists(dir + "/t.npy"));
        BOOST_TEST(!std::filesystem::exists(dir + "/t.columns.txt"));
        csv.commit();
        npy.commit();
      }
      require_same(read_csv(dir + "/t.csv"), expected, "csv, width " + std::to_string(width));
      require_same(read_npy(dir + "/t.npy"), expected, "npy, width " + std::to_string(width));
      BOOST_TEST(files_in(dir) == (std::set<std::string>{"t.csv", "t.npy", "t.columns.txt"}));
    }
  std::filesystem::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(decimation_writes_the_rows_of_every_kth_step)
{
  // A linear SDOF under a harmonic force, dt = 1e-3 s, 1000 steps.
  // Output interval 0.003 s: every 3rd step; ground motion every step;
  // energy every 7th step. Rows: steps 0, k, 2k, ... <= 1000, the time of
  // step n being n dt (the integrator's clock), to the bit; in both formats.
  InputParameters input = read_parameters("input/bouc-wen-sdof.prm");
  input.time_integration.newmark.time_step = 1e-3;
  input.time_integration.end_time          = 1.0;
  input.output.interval                    = 0.003;
  input.output.recorders.output_interval   = input.output.interval;
  input.output.recorders.requests          = RecorderParameters::parse("ground motion every 0; energy every 0.007");
  for (const OutputFormat format : {OutputFormat::csv, OutputFormat::npy})
    {
      const std::string dir = fresh_directory("decimation");
      BOOST_REQUIRE(run(input, format, dir).status.completed());
      for (const auto &[stem, every] : {std::pair{"drift", 3}, std::pair{"hinges", 3},
                                        std::pair{"ground_motion", 1}, std::pair{"energy", 7}})
        {
          const std::string file = dir + "/" + stem + (format == OutputFormat::csv ? ".csv" : ".npy");
          const Table       t    = format == OutputFormat::csv ? read_csv(file) : read_npy(file);
          BOOST_TEST_CONTEXT(file)
          {
            BOOST_REQUIRE(t.rows.size() == std::size_t(1000 / every + 1));
            for (std::size_t i = 0; i < t.rows.size(); ++i)
              BOOST_TEST(same_bits(t.rows[i][0], double(i * every) * 1e-3), "row " << i);
          }
        }
      std::filesystem::remove_all(dir);
    }
}

BOOST_AUTO_TEST_CASE(npy_holds_the_csv_numbers_to_the_bit)
{
  // The 3+2-storey shear pair with linear gaps (bench/, 5 s: impacts) and
  // the Bouc-Wen SDOF (hinge states, phase portrait), every step.
  for (const char *file : {"bench/shear-pair-linear.prm", "input/bouc-wen-sdof.prm"})
    {
      BOOST_TEST_CONTEXT(file)
      {
        InputParameters input                  = read_parameters(file);
        input.time_integration.end_time        = std::min(5.0, input.time_integration.end_time > 0 ?
                                                                 input.time_integration.end_time : 5.0);
        input.output.interval                  = 0;
        input.output.recorders.output_interval = 0;
        const std::string csv = fresh_directory("npy-csv"), npy = fresh_directory("npy-npy");
        const RunResult   a = run(input, OutputFormat::csv, csv), b = run(input, OutputFormat::npy, npy);
        BOOST_REQUIRE(a.status.completed());
        BOOST_REQUIRE(b.status.completed());
        unsigned int n_tables = 0;
        for (const std::string &name : files_in(csv))
          if (name.size() > 4 && name.substr(name.size() - 4) == ".csv" &&
              read_bytes(csv + "/" + name).rfind("time_s,", 0) == 0)
            {
              const std::string stem = name.substr(0, name.size() - 4);
              require_same(read_npy(npy + "/" + stem + ".npy"), read_csv(csv + "/" + name), stem);
              BOOST_TEST(!std::filesystem::exists(npy + "/" + name)); // no CSV of a time series
              ++n_tables;
            }
        BOOST_TEST(n_tables >= 6u);
        // summary.json lists exactly what is in the directory
        BOOST_TEST(listed_files(csv) == files_in(csv));
        BOOST_TEST(listed_files(npy) == files_in(npy));

        // npy over the CSV run's directory: none of its tables stay, and the
        // tables equal the other npy run's bytes
        BOOST_REQUIRE(run(input, OutputFormat::npy, csv).status.completed());
        BOOST_TEST(files_in(csv) == files_in(npy));
        for (const std::string &name : files_in(npy))
          if (name != "summary.json") // it has the wall time
            BOOST_TEST(read_bytes(csv + "/" + name) == read_bytes(npy + "/" + name), name);
        std::filesystem::remove_all(csv);
        std::filesystem::remove_all(npy);
      }
    }
}

BOOST_AUTO_TEST_CASE(memory_holds_the_files_numbers_and_texts)
{
  // the 3+2-storey shear pair with linear gaps, 5 s: impacts and profiles
  InputParameters input                  = read_parameters("bench/shear-pair-linear.prm");
  input.time_integration.end_time        = 5;
  input.output.recorders.output_interval = 0;
  const std::string csv = fresh_directory("memory-csv");
  BOOST_REQUIRE(run(input, OutputFormat::csv, csv).status.completed());

  const Analysis analysis = prepare_analysis(input);
  MemoryResults  memory;
  RunOptions     options;
  options.memory = &memory;
  BOOST_REQUIRE(run_time_history(analysis, run_parameters(input), make_excitation(analysis, input),
                                 options)
                  .status.completed());
  unsigned int n_tables = 0;
  for (const MemoryResults::Table &table : memory.tables)
    {
      Table rows{table.header, {}};
      for (std::size_t i = 0; i < table.values.size(); i += table.header.size())
        rows.rows.emplace_back(table.values.begin() + i,
                               table.values.begin() + i + table.header.size());
      require_same(rows, read_csv(csv + "/" + table.stem + ".csv"), table.stem);
      ++n_tables;
    }
  BOOST_TEST(n_tables >= 4u);
  unsigned int n_texts = 0;
  for (const auto &[name, text] : memory.texts)
    {
      BOOST_TEST_CONTEXT(name)
      {
        const std::string file = read_bytes(csv + "/" + name);
        if (name == "summary.json") // but for its wall time
          {
            const std::regex wall("\"(wall_time_s|steps_per_second)\": [0-9.e+-]+");
            BOOST_TEST(std::regex_replace(text, wall, "") == std::regex_replace(file, wall, ""));
          }
        else
          BOOST_TEST(text == file);
        ++n_texts;
      }
    }
  BOOST_TEST(n_texts >= 4u); // summary, impacts, the two profiles
  std::filesystem::remove_all(csv);

  // a number that is not finite: the file writers' message, naming the table
  MemoryResults                   numbers;
  const std::unique_ptr<TableWriter> writer = numbers.table_writer("drift", {"time_s", "a"});
  writer->add_row(0, {1.5});
  BOOST_CHECK_THROW(writer->add_row(0.1, {std::nan("")}), NumericalError);
  BOOST_TEST(numbers.tables.front().values == std::vector<double>({0, 1.5}));
}

