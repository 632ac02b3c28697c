// What every libFuzzer target of a reader does with one input: write the
// bytes to a scratch file (scratch_file.h), hand its path to the reader and
// accept only poundfe's own InputError. Any other exception is a finding
// (program.cc would print it, but it means a check is missing): the target
// aborts, which libFuzzer reports with the input. Crashes, sanitizer reports
// and hangs are findings by themselves.
#ifndef POUNDFE_TESTS_FUZZ_READER_TARGET_H
#define POUNDFE_TESTS_FUZZ_READER_TARGET_H

#include <poundfe/base/exceptions.h>

#include "scratch_file.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

namespace poundfe_fuzz
{
  /// `read(path)` on `data` written to a scratch file called `name`.
  template <typename Read>
  void
  read_expecting_input_errors(const std::uint8_t *data, const std::size_t size,
                              const std::string &name, const Read &read)
  {
    const std::string file = write_scratch_file(data, size, name);
    try
      {
        read(file);
      }
    catch (const poundfe::InputError &)
      {
      }
    catch (const std::exception &e)
      {
        std::fprintf(stderr, "not an InputError: %s\n", e.what());
        std::abort();
      }
  }

  /// `step()`, a step of a target that builds or runs a model: an
  /// InputError or a NumericalError (a model that cannot be integrated, a
  /// limit state undefined on a row) is a normal outcome, any other
  /// exception a finding.
  template <typename Step>
  void
  run_expecting_refusals(const Step &step)
  {
    try
      {
        step();
      }
    catch (const poundfe::InputError &)
      {
      }
    catch (const poundfe::NumericalError &)
      {
      }
    catch (const std::exception &e)
      {
        std::fprintf(stderr, "not an InputError or NumericalError: %s\n", e.what());
        std::abort();
      }
  }
} // namespace poundfe_fuzz

#endif
