// Strict numbers, exact number text, and the parameter-file scan that
// guards deal.II's ParameterHandler (issue 14 items 1, 3, 4, 5, 8).
#include <poundfe/base/exceptions.h>
#include <poundfe/base/input_text.h>
#include <poundfe/base/numbers.h>

#include "test_utilities.h"

#include <cfloat>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <boost/test/unit_test.hpp>

#include <sys/stat.h>

using namespace poundfe;

BOOST_AUTO_TEST_CASE(numbers_are_read_whole_or_refused)
{
  BOOST_TEST(*parse_number("0.015") == 0.015);
  BOOST_TEST(*parse_number("  -2.5e-3 ") == -2.5e-3);
  BOOST_TEST(*parse_number(".5") == 0.5);
  for (const char *bad : {"15mm", "0.015 junk", "1e-2x", "0.02.5", "2e-2e", "", " ", "1e999",
                          "-1e999", "inf", "nan", "0x10", "1,5", "1 2", "D-2", "2.0D-02"})
    BOOST_TEST(!parse_number(bad).has_value(), "'" << bad << "' refused");
  // Fortran D exponents only where asked for (AT2 files)
  BOOST_TEST(*parse_number("2.0D-02", Exponent::e_or_fortran_d) == 2.0e-2);
  BOOST_TEST(*parse_number(".2D-01", Exponent::e_or_fortran_d) == 0.02);
  BOOST_TEST(*parse_number("-.1d+01", Exponent::e_or_fortran_d) == -1.0);
  BOOST_TEST(!parse_number("0.02.5", Exponent::e_or_fortran_d).has_value());
  // a field longer than any written number is refused, not copied
  BOOST_TEST(!parse_number(std::string(30000, '1')).has_value());
  BOOST_TEST(*parse_number("4.9e-324") == 4.9e-324); // denormal, finite: the callers judge

  BOOST_TEST(!parse_count("5590", 100).has_value());
  BOOST_TEST(*parse_count(" 42 ", 100) == 42u);
  for (const char *bad : {"-5", "4.0", "1e3", "99999999999999999999999", "", "7x"})
    BOOST_TEST(!parse_count(bad, 1000000).has_value(), "'" << bad << "' refused");
}

BOOST_AUTO_TEST_CASE(fields_of_a_stream_are_whole_numbers)
{
  std::istringstream good("2 1 right 0.015");
  unsigned int       b = 0, f = 0;
  std::string        side;
  double             gap = 0;
  BOOST_TEST(static_cast<bool>(read_number(read_number(good, b), f) >> side));
  BOOST_TEST(static_cast<bool>(read_number(good, gap)));
  BOOST_TEST((b == 2 && f == 1 && side == "right" && gap == 0.015));
  std::istringstream trailing("15mm");
  BOOST_TEST(!read_number(trailing, gap)); // `>>` would read 15
  std::istringstream fraction("1.5");
  BOOST_TEST(!read_number(fraction, b));   // `>>` would read 1
  std::istringstream negative("-1");
  BOOST_TEST(!read_number(negative, b));   // `>>` would wrap to 4294967295
}

BOOST_AUTO_TEST_CASE(number_text_reads_back_exactly)
{
  BOOST_TEST(number_text(-1e-300) == "-1e-300");
  BOOST_TEST(number_text(1 - 1e-11) == "0.99999999999");
  BOOST_TEST(number_text(1e308) == "1e+308");
  BOOST_TEST(number_text(0.015) == "0.015");
  BOOST_TEST(number_text(3) == "3");
  for (const double x : {0.1, 1.0 / 3, -2.5e-7, DBL_MIN, DBL_MAX, 4.9e-324})
    BOOST_TEST(std::strtod(number_text(x).c_str(), nullptr) == x); // stod refuses denormals
}

BOOST_AUTO_TEST_CASE(parameter_text_is_scanned_by_lines)
{
  const std::string text = "# heading \\\n"
                           "subsection Building 1\n"
                           "  set Storey heights = 3, \\\n"
                           "                       4 # comment\n"
                           "  set Floor masses = 1000 # mass \\\n"
                           "  set Type = shear\n"
                           "end\n";
  const PrmText prm = prepare_prm_text("f.prm", text);
  // the comment's backslash does not swallow line 2 or line 6
  BOOST_TEST(prm.lines.at("Building 1/Storey heights") == 3);
  BOOST_TEST(prm.lines.at("Building 1/Floor masses") == 5);
  BOOST_TEST(prm.lines.at("Building 1/Type") == 6);
  // one line out for each line in (ParameterHandler's line numbers stay right)
  BOOST_TEST(prm.text == "\nsubsection Building 1\nset Storey heights = 3, \\\n4\n"
                         "set Floor masses = 1000\nset Type = shear\nend\n");

  // long lines: a hand-written scan, linear in the length
  const std::string long_line = "subsection Model\n  set Separations = " +
                                std::string(200000, '1') + "\nend\n";
  BOOST_TEST(prepare_prm_text("f.prm", long_line).lines.at("Model/Separations") == 2);

  BOOST_TEST(poundfe_test::input_error_of([] { prepare_prm_text("f.prm", ""); }).find("sets no parameter") !=
             std::string::npos);
  BOOST_TEST(poundfe_test::input_error_of([] { prepare_prm_text("f.prm", "# nothing \n\n"); })
               .find("f.prm: the file sets no parameter") == 0);
  BOOST_TEST(poundfe_test::input_error_of([] { prepare_prm_text("f.prm", "set a = 1\nend\n"); }) ==
             "f.prm:2: 'end' without an open 'subsection'");
  BOOST_TEST(poundfe_test::input_error_of([] { prepare_prm_text("f.prm", "subsection A\nset a = 1\n"); }) ==
             "f.prm:1: 'subsection A' is never closed by 'end'");
  BOOST_TEST(poundfe_test::input_error_of([] { prepare_prm_text("f.prm", "set a = 1 \\"); }).find("f.prm:1:") ==
             0);
}

BOOST_AUTO_TEST_CASE(json_text_is_an_object_of_bounded_depth)
{
  check_json_text("f.json", "{ \"Model\": { \"Number of buildings\": \"1\" } }");
  check_json_text("f.json", "{ \"A\": \"}{][\\\"\" }"); // brackets in strings do not count
  BOOST_TEST(poundfe_test::input_error_of([] { check_json_text("f.json", "null"); }).find("f.json:1: a JSON") == 0);
  BOOST_TEST(poundfe_test::input_error_of([] { check_json_text("f.json", " \n{ }"); }).find("sets no parameter") !=
             std::string::npos);
  BOOST_TEST(poundfe_test::input_error_of([] { check_json_text("f.json", ""); }).find("sets no parameter") !=
             std::string::npos);
  const std::string deep = "{\"a\": " + std::string(30000, '[') + std::string(30000, ']') + "}";
  BOOST_TEST(poundfe_test::input_error_of([&] { check_json_text("f.json", deep); }) ==
             "f.json:1: nested more than 64 levels deep");
  std::string fine = "{\"a\": " + std::string(60, '[') + std::string(60, ']') + "}";
  check_json_text("f.json", fine);
  BOOST_TEST(poundfe_test::input_error_of([] { check_json_text("f.json", "{\"a\": [}"); }) ==
             "f.json:1: unexpected '}'");
}

BOOST_AUTO_TEST_CASE(line_ends_cr_lf_and_cr_alone)
{
  const std::string file = "test_input_text_cr.prm";
  for (const std::string end : {"\n", "\r\n", "\r", "\r\r\n"})
    {
      {
        std::ofstream out(file, std::ios::binary);
        out << "# starts with a comment" << end << "subsection Model" << end
            << "  set Gravity = 9.8" << end << "end" << end;
      }
      const std::string text = read_input_text(file);
      BOOST_TEST(text == "# starts with a comment\nsubsection Model\n  set Gravity = 9.8\nend\n");
      BOOST_TEST(prepare_prm_text(file, text).lines.at("Model/Gravity") == 3);
    }
  std::remove(file.c_str());
  BOOST_TEST(poundfe_test::input_error_of([] { read_input_text("."); }) == ".: is a directory, not a parameter file");
}

// Issue 28 classes 1, 8, 9: the reader every input file goes through.
BOOST_AUTO_TEST_CASE(every_reader_is_bounded)
{
  using poundfe_test::input_error_of;
  // a byte-order mark is dropped, a NUL byte refused with its line and column
  const std::string bom = poundfe_test::temporary_file("bom.csv", "\xEF\xBB\xBF" "date,x\n1950,1\n");
  BOOST_TEST(read_input_text(bom, "catalogue") == "date,x\n1950,1\n");
  const std::string binary =
    poundfe_test::temporary_file("binary.prm", std::string("set a = 1\nELF\x7f", 14) + '\0' + "x");
  BOOST_TEST(input_error_of([&] { read_input_text(binary); }) ==
             binary + ":2: a NUL byte (column 5): a binary file, not a text parameter file");
  // a line of max_line_length + 1 characters, with the parameter named
  const std::string wide =
    poundfe_test::temporary_file("wide.csv", "a\n" + std::string(max_line_length + 1, 'x') + "\n");
  BOOST_TEST(input_error_of([&] { read_input_text(wide, "catalogue", "Site hazard/Catalogue file"); }) ==
             wide + ":2: parameter 'Site hazard/Catalogue file': a line of 1048577 characters, "
                    "more than the 1048576 a line may have");
  // devices and FIFOs are refused before they are opened (no wait, no endless read)
  BOOST_TEST(input_error_of([] { read_input_text("/dev/zero", "record file"); }) ==
             "/dev/zero: is a device (like /dev/zero), not a regular file: the record file must be "
             "a file whose end can be known");
  const std::string fifo = std::filesystem::temp_directory_path() / "poundfe_test_fifo.json";
  std::remove(fifo.c_str());
  BOOST_TEST(mkfifo(fifo.c_str(), 0600) == 0);
  BOOST_TEST(input_error_of([&] { read_json_text(fifo, "hazard file", "Separation/Site hazard/File"); })
               .find(fifo + ": parameter 'Separation/Site hazard/File': is a named pipe (FIFO)") == 0);
  BOOST_TEST(input_error_of([] { read_input_text("/no/such/file.at2", "record file"); }) ==
             "/no/such/file.at2: cannot open the record file (no such file)");
  for (const std::string &f : {bom, binary, wide, fifo})
    std::remove(f.c_str());
}

BOOST_AUTO_TEST_CASE(duplicates_are_errors)
{
  using poundfe_test::input_error_of;
  BOOST_TEST(input_error_of([] {
               prepare_prm_text("f.prm", "subsection A\n  set x = 1\n  set y = 2\n  set x = 3\nend\n");
             }) == "f.prm:4: parameter 'A/x': is set a second time; the first is at line 2 (the last "
                   "would win silently)");
  BOOST_TEST(input_error_of([] {
               prepare_prm_text("f.prm", "subsection A\n  set x = 1\nend\nsubsection A\n  set y = 1\nend\n");
             }) == "f.prm:4: 'subsection A' (A) is entered a second time; the first is at line 1 (set "
                   "its entries in one place)");
  // the same entry in two sections, the same section in two parents: fine
  prepare_prm_text("f.prm", "subsection A\n  subsection D\n    set x = 1\n  end\nend\n"
                            "subsection B\n  subsection D\n    set x = 1\n  end\nend\n");
  BOOST_TEST(input_error_of([] { check_json_text("f.json", "{ \"A\": { \"x\": 1,\n \"x\": 2 } }"); }) ==
             "f.json:2: the key \"x\" appears a second time in one object; the first is at line 1");
  check_json_text("f.json", "{ \"A\": { \"x\": 1 }, \"B\": { \"x\": [\"x\", \"x\"] } }");
}
