// read_csv_columns (output/csv_columns.h) against the test's own reader
// (output_test_files.h: getline and strtod, a second implementation) on a
// table written by CsvWriter: doubles over the whole exponent range, a row
// wider than the writer's buffer, columns asked in any order and twice.
// Every comparison is exact: the CSV holds the shortest text that reads
// back to the same double, and both readers round correctly. A missing file,
// a short row and a cell that is not a number are OutputErrors naming the file.
#include <poundfe/base/exceptions.h>
#include <poundfe/output/csv_columns.h>
#include <poundfe/output/csv_writer.h>

#include "output_test_files.h"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

BOOST_AUTO_TEST_SUITE(csv_columns)

BOOST_AUTO_TEST_CASE(columns_read_in_one_pass_are_the_written_doubles)
{
  const std::string directory = poundfe_test::fresh_directory("csv-columns");
  std::filesystem::create_directories(directory);
  const std::string  path = directory + "/wide.csv";
  const unsigned int n_columns = 5000; // a row of ~100 kB: wider than a write block
  std::vector<std::string> header{"time_s"};
  for (unsigned int c = 0; c < n_columns; ++c)
    header.push_back("c" + std::to_string(c));
  {
    poundfe::CsvWriter                     csv(path, header);
    std::mt19937                           random(2026);
    std::uniform_real_distribution<double> mantissa(-1, 1);
    std::uniform_int_distribution<int>     exponent(-300, 300);
    std::vector<double>                    row(n_columns);
    for (unsigned int r = 0; r < 7; ++r)
      {
        for (double &x : row)
          x = std::ldexp(mantissa(random), exponent(random));
        row[3] = 0; // column 4 of the file
        csv.add_row(0.01 * r, row);
      }
    csv.commit();
  }
  const poundfe_test::Table              table = poundfe_test::read_csv(path);
  const std::vector<unsigned int>        asked{5000, 0, 17, 4, 17, 4};
  const std::vector<std::vector<double>> read = poundfe::read_csv_columns(path, asked);
  BOOST_REQUIRE_EQUAL(read.size(), asked.size());
  for (unsigned int i = 0; i < asked.size(); ++i)
    {
      BOOST_REQUIRE_EQUAL(read[i].size(), table.rows.size());
      for (unsigned int r = 0; r < table.rows.size(); ++r)
        BOOST_CHECK_EQUAL(read[i][r], table.rows[r][asked[i]]); // exact
    }
  BOOST_CHECK_EQUAL(read[1][6], 0.06); // the time column
}

BOOST_AUTO_TEST_CASE(what_cannot_be_read_is_an_output_error_naming_the_file)
{
  const std::string directory = poundfe_test::fresh_directory("csv-columns-bad");
  std::filesystem::create_directories(directory);
  const auto message = [](const std::string &path, const std::vector<unsigned int> &columns) {
    try
      {
        poundfe::read_csv_columns(path, columns);
      }
    catch (const poundfe::OutputError &e)
      {
        return std::string(e.what());
      }
    return std::string("no error");
  };
  const std::string missing = directory + "/missing.csv";
  BOOST_CHECK_EQUAL(message(missing, {0}),
                    "cannot read " + missing + ": No such file or directory");
  const std::string damaged = directory + "/damaged.csv";
  std::ofstream(damaged) << "t,a,b\n0,1,2\n0.1,1\n";
  BOOST_CHECK_EQUAL(message(damaged, {0, 2}),
                    "cannot read row 3, column 3 of " + damaged + ": Invalid argument");
  BOOST_CHECK_EQUAL(message(damaged, {1}).substr(0, 4), "no e"); // column 2 is in every row
  const std::string text = directory + "/text.csv";
  std::ofstream(text) << "t,a\n0,1\n0.1,1x\n";
  BOOST_CHECK_EQUAL(message(text, {1}),
                    "cannot read row 3, column 2 of " + text + ": Invalid argument");
}

BOOST_AUTO_TEST_SUITE_END()
