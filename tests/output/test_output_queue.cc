// The writer thread of a run's tables (output/output_queue.h).
//  - Bytes: tables written through a threaded OutputQueue are the files the
//    same writers give inline, byte for byte (exact: the writer thread runs
//    the same code on the same doubles, so any difference is a bug): CSV and
//    .npy sharing one queue (and one NumberText) over many blocks and ring
//    turns, and rows wider than a block (handed over on the stepping thread).
//  - A row that is not finite throws NumericalError at once, on the
//    stepping thread, at the row that holds it; the rows before it are in
//    the files committed afterwards, as inline.
//  - A write error on the writer thread (EFBIG: the process's files limited
//    to 200 kB by RLIMIT_FSIZE, as a full disk) reaches the stepping thread: add_row throws OutputError
//    within the ring's rows (the next hand-over, whichever table's row makes
//    it), commit throws it again, no file appears, and the other table of
//    the same queue is committed with every row it took.
#include <poundfe/base/exceptions.h>
#include <poundfe/output/csv_writer.h>
#include <poundfe/output/npy_writer.h>
#include <poundfe/output/number_text.h>
#include <poundfe/output/output_queue.h>

#include "output_test_files.h"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <limits>
#include <memory>
#include <sys/resource.h>

using namespace poundfe;
using namespace poundfe_test;

namespace
{
  std::vector<std::string>
  header_of(const std::size_t width)
  {
    std::vector<std::string> header{"time_s"};
    for (std::size_t j = 1; j < width; ++j)
      header.push_back("c" + std::to_string(j));
    return header;
  }

  /// Row i of a table of `width` columns: numbers of many magnitudes.
  void
  fill_row(const std::size_t i, std::vector<double> &values)
  {
    for (std::size_t j = 0; j < values.size(); ++j)
      values[j] = std::sin(1.0 + i * 7.0 + j) * std::pow(10.0, double(j % 7) - 3);
  }

  /// A CSV and an .npy table of `width` columns and `n_rows` rows in `dir`
  /// (the CSV one `width_csv` wide), through a threaded queue or inline; a
  /// NaN in the CSV's row `nan_row` (if below n_rows) stops the writing.
  /// Returns whether NumericalError came at that row.
  bool
  write_tables(const std::string &dir, const bool threaded, const std::size_t width,
               const std::size_t width_csv, const std::size_t n_rows, const std::size_t nan_row)
  {
    std::filesystem::create_directories(dir);
    const auto queue = std::make_shared<OutputQueue>(threaded);
    BOOST_TEST(queue->threaded() == threaded);
    const auto text  = std::make_shared<NumberText>();
    const auto csv_header = header_of(width_csv), npy_header = header_of(width);
    const std::unique_ptr<TableWriter> csv = queued_table_writer(
      std::make_unique<CsvWriter>(dir + "/t.csv", csv_header, text), queue, csv_header, dir + "/t.csv");
    const std::unique_ptr<TableWriter> npy = queued_table_writer(
      std::make_unique<NpyWriter>(dir + "/t.npy", npy_header), queue, npy_header, dir + "/t.npy");
    std::vector<double> csv_values(width_csv - 1), npy_values(width - 1);
    bool                stopped_at_nan = false;
    for (std::size_t i = 0; i < n_rows; ++i)
      {
        fill_row(i, csv_values);
        fill_row(i + 1, npy_values);
        npy->add_row(i * 1e-3, npy_values);
        if (i == nan_row)
          csv_values.back() = std::numeric_limits<double>::quiet_NaN();
        try
          {
            csv->add_row(i * 1e-3, csv_values);
          }
        catch (const NumericalError &)
          {
            stopped_at_nan = i == nan_row;
            break;
          }
      }
    csv->commit();
    npy->commit();
    return stopped_at_nan;
  }
} // namespace

BOOST_AUTO_TEST_CASE(threaded_and_inline_tables_are_the_same_bytes)
{
  const std::string dir = fresh_directory("output-queue");
  // 40 000 rows of 5 and 3 numbers (about 80 blocks, 20 turns of the
  // ring), then 30 rows of 9000 numbers (wider than a block of 8192)
  for (const auto &[width, n_rows] : {std::pair<std::size_t, std::size_t>{5, 40000}, {9000, 30}})
    {
      const std::size_t none = n_rows; // no NaN
      write_tables(dir + "/inline", false, width, width > 5 ? width : 3, n_rows, none);
      write_tables(dir + "/threaded", true, width, width > 5 ? width : 3, n_rows, none);
      for (const char *name : {"t.csv", "t.npy", "t.columns.txt"})
        {
          const std::string a = read_bytes(dir + "/inline/" + name),
                            b = read_bytes(dir + "/threaded/" + name);
          BOOST_TEST(a.size() > 10);
          BOOST_TEST((a == b), name << ", width " << width << ": " << a.size() << " and " << b.size()
                                    << " bytes");
        }
      std::filesystem::remove_all(dir);
    }
}

BOOST_AUTO_TEST_CASE(a_row_not_finite_stops_at_its_step)
{
  const std::string dir = fresh_directory("output-queue-nan");
  BOOST_TEST(write_tables(dir + "/inline", false, 5, 3, 20000, 12345));
  BOOST_TEST(write_tables(dir + "/threaded", true, 5, 3, 20000, 12345));
  for (const char *name : {"t.csv", "t.npy"})
    BOOST_TEST((read_bytes(dir + "/inline/" + name) == read_bytes(dir + "/threaded/" + name)), name);
  // 12345 rows kept, the header and no more
  const std::string csv = read_bytes(dir + "/threaded/t.csv");
  BOOST_TEST(std::count(csv.begin(), csv.end(), '\n') == 12346);
  std::filesystem::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_write_error_reaches_the_stepping_thread)
{
  // files of this process limited to 200 kB: a write past it fails (EFBIG)
  // once SIGXFSZ is ignored
  rlimit old_limit;
  getrlimit(RLIMIT_FSIZE, &old_limit);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit limit = old_limit;
  limit.rlim_cur = 200000;
  BOOST_REQUIRE(setrlimit(RLIMIT_FSIZE, &limit) == 0);
  for (const bool threaded : {false, true})
    {
      const std::string dir = fresh_directory("output-queue-full");
      std::filesystem::create_directories(dir);
      const auto queue = std::make_shared<OutputQueue>(threaded);
      const auto wide = header_of(6), narrow = header_of(1); // the narrow table stays small
      const std::unique_ptr<TableWriter> full = queued_table_writer(
        std::make_unique<CsvWriter>(dir + "/full.csv", wide), queue, wide, dir + "/full.csv");
      const std::unique_ptr<TableWriter> fine = queued_table_writer(
        std::make_unique<CsvWriter>(dir + "/fine.csv", narrow), queue, narrow, dir + "/fine.csv");
      std::vector<double> values(5), none;
      std::size_t         n_rows = 0, fine_rows = 0, thrown_at = 0;
      // the first hand-over after the failure throws, whichever table's row
      // makes it
      for (; n_rows < 100000 && thrown_at == 0; ++n_rows)
        try
          {
            fill_row(n_rows, values);
            fine->add_row(n_rows * 1e-3, none);
            ++fine_rows;
            full->add_row(n_rows * 1e-3, values);
          }
        catch (const OutputError &)
          {
            thrown_at = n_rows + 1;
          }
      // 200 kB is about 1800 rows of 6 numbers. The writer thread may lag by
      // the whole ring, and the error surfaces at the hand-over after the
      // block the writer failed in: n_blocks + 2 blocks of 8192 doubles, at
      // least 5 doubles a row of both tables, at most about 9 800 rows more
      // (a bound on the lag, not a timing: the stepper waits for the ring)
      BOOST_TEST(thrown_at > 1000u);
      BOOST_TEST(thrown_at < (threaded ? 2500u + 6u * 8192u / 5u : 2500u),
                 "threaded " << threaded << ", thrown at row " << thrown_at);
      BOOST_CHECK_THROW(full->commit(), OutputError);
      fine->commit();
      BOOST_TEST(!std::filesystem::exists(dir + "/full.csv"));
      BOOST_TEST(!std::filesystem::exists(dir + "/full.csv.tmp")); // removed at the failure
      const std::string text = read_bytes(dir + "/fine.csv");
      BOOST_TEST(std::count(text.begin(), text.end(), '\n') == long(fine_rows + 1));
      std::filesystem::remove_all(dir);
    }
  setrlimit(RLIMIT_FSIZE, &old_limit);
  std::signal(SIGXFSZ, old_handler);
}
