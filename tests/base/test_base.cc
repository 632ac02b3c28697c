// Progress lines (rate, ETA, durations), when Progress prints, and the
// interruption flag.
#include <poundfe/base/interruption.h>
#include <poundfe/base/progress.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <sstream>
#include <thread>

#include <boost/test/unit_test.hpp>

using namespace poundfe;

BOOST_AUTO_TEST_CASE(progress_line_has_the_rate_and_the_time_left)
{
  BOOST_TEST(progress_line("run: steps", 12000, 20000, 12000 / 52000.0) ==
             "  run: 12000/20000 steps, 52,000 steps/s, ETA 0.2 s");
  // three significant digits, ',' between thousands
  BOOST_TEST(progress_line("samples", 1234567, 5000000, 1.0) ==
             "  1234567/5000000 samples, 1,230,000 samples/s, ETA 3.1 s");
  BOOST_TEST(progress_line("realizations", 3, 40, 4.0) ==
             "  3/40 realizations, 0.75 realizations/s, ETA 49 s");
  BOOST_TEST(progress_line("level 2: samples", 150, 1000, 1.0) ==
             "  level 2: 150/1000 samples, 150 samples/s, ETA 5.7 s");
  // nothing done yet: no rate; all done: no ETA
  BOOST_TEST(progress_line("realizations", 0, 8, 1.0) == "  0/8 realizations");
  BOOST_TEST(progress_line("realizations", 8, 8, 4.0) == "  8/8 realizations, 2 realizations/s");
  // resumed: the rate counts from what was already done
  BOOST_TEST(progress_line("realizations", 15, 20, 10.0, 10) ==
             "  15/20 realizations, 0.5 realizations/s, ETA 10 s");
  BOOST_TEST(progress_line("realizations", 10, 20, 10.0, 10) == "  10/20 realizations");
}

BOOST_AUTO_TEST_CASE(durations)
{
  BOOST_TEST(format_duration(0.04) == "0.0 s");
  BOOST_TEST(format_duration(9.94) == "9.9 s");
  BOOST_TEST(format_duration(42.4) == "42 s");
  BOOST_TEST(format_duration(59.7) == "1 min 00 s");
  BOOST_TEST(format_duration(185) == "3 min 05 s");
  BOOST_TEST(format_duration(7620) == "2 h 07 min");
}

BOOST_AUTO_TEST_CASE(progress_prints_only_when_shown)
{
  std::ostringstream quiet;
  {
    Progress progress(quiet, "things", 2);
    BOOST_TEST(!progress.active()); // not a terminal
    std::this_thread::sleep_for(std::chrono::milliseconds(550));
    progress.update(1);
  }
  BOOST_TEST(quiet.str().empty());

  setenv("POUNDFE_PROGRESS", "1", 1);
  std::ostringstream out;
  {
    Progress progress(out, "x: things", 2);
    BOOST_TEST(progress.active());
    progress.update(0); // too early: nothing
    BOOST_TEST(out.str().empty());
    std::this_thread::sleep_for(std::chrono::milliseconds(550));
    progress.update(1);
    BOOST_TEST(out.str().rfind("\r  x: 1/2 things, ", 0) == 0);
    progress.update(2); // within 0.5 s of the last line: nothing new
    const std::string line = out.str().substr(1);
    progress.finish(); // erases the line
    BOOST_TEST(out.str() == "\r" + line + "\r" + std::string(line.size(), ' ') + "\r");
  }
  unsetenv("POUNDFE_PROGRESS");
}

// A shell without job control starts a background job with SIGINT ignored:
// the handler is installed all the same (no signal is raised here, so the
// next case still sees none).
BOOST_AUTO_TEST_CASE(a_signal_ignored_at_start_is_caught_too)
{
  struct sigaction ignore = {};
  ignore.sa_handler       = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  sigaction(SIGINT, &ignore, nullptr);
  install_interruption_handlers();
  struct sigaction now = {};
  sigaction(SIGINT, nullptr, &now);
  BOOST_TEST((now.sa_handler != SIG_IGN && now.sa_handler != SIG_DFL));
  BOOST_TEST(!interruption_requested());
}

BOOST_AUTO_TEST_CASE(the_first_signal_sets_the_flag_the_second_kills)
{
  install_interruption_handlers();
  BOOST_TEST(!interruption_requested());
  std::raise(SIGTERM);
  BOOST_TEST(interruption_requested());
  BOOST_TEST(interrupted_exit_status() == 143);
  for (const int signal : {SIGINT, SIGTERM})
    {
      struct sigaction now = {};
      sigaction(signal, nullptr, &now);
      BOOST_TEST((now.sa_handler == SIG_DFL)); // the next one takes the default action
    }
}
