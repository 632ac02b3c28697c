#include <poundfe/base/progress.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <unistd.h>

namespace poundfe
{
  namespace
  {
    constexpr double print_interval = 0.5; // s

    /// Three significant digits; integers from 100 up, with ',' between thousands.
    std::string
    format_rate(const double rate)
    {
      char buffer[64];
      if (rate < 99.95)
        {
          std::snprintf(buffer, sizeof buffer, "%.3g", rate);
          return buffer;
        }
      const double scale   = std::pow(10.0, std::floor(std::log10(rate)) - 2);
      const long long rounded = std::llround(std::llround(rate / scale) * scale);
      std::string  digits  = std::to_string(rounded), text;
      for (std::size_t i = 0; i < digits.size(); ++i)
        {
          if (i > 0 && (digits.size() - i) % 3 == 0)
            text += ',';
          text += digits[i];
        }
      return text;
    }

    bool
    shown_on(const std::ostream &out)
    {
      if (out.rdbuf() == nullptr)
        return false;
      if (const char *forced = std::getenv("POUNDFE_PROGRESS"); forced && *forced)
        return std::string(forced) != "0";
      // Open MPI's mpirun gives ranks a pseudo-terminal as stdout even when
      // its own goes to a file, but a pipe as stderr: stderr decides.
      if (::isatty(STDERR_FILENO) != 1)
        return false;
      return &out == &std::cerr || &out == &std::clog ||
             (&out == &std::cout && ::isatty(STDOUT_FILENO) == 1);
    }
  } // namespace

  std::string
  format_duration(const double seconds)
  {
    char buffer[64];
    if (seconds < 9.95)
      std::snprintf(buffer, sizeof buffer, "%.1f s", seconds);
    else if (seconds < 59.5)
      std::snprintf(buffer, sizeof buffer, "%.0f s", seconds);
    else if (seconds < 3599.5)
      {
        const long s = std::lround(seconds);
        std::snprintf(buffer, sizeof buffer, "%ld min %02ld s", s / 60, s % 60);
      }
    else
      {
        const long m = std::lround(seconds / 60);
        std::snprintf(buffer, sizeof buffer, "%ld h %02ld min", m / 60, m % 60);
      }
    return buffer;
  }

  std::string
  progress_line(const std::string &what, const unsigned long done, const unsigned long total,
                const double elapsed_seconds, const unsigned long first_done)
  {
    const std::size_t colon = what.rfind(": ");
    const std::string label = colon == std::string::npos ? "" : what.substr(0, colon + 2);
    const std::string unit  = colon == std::string::npos ? what : what.substr(colon + 2);
    std::string line = "  " + label + std::to_string(done) + "/" + std::to_string(total) + " " + unit;
    if (done > first_done && elapsed_seconds > 0)
      {
        const double rate = (done - first_done) / elapsed_seconds;
        line += ", " + format_rate(rate) + " " + unit + "/s";
        if (done < total)
          line += ", ETA " + format_duration((total - done) / rate);
      }
    return line;
  }

  Progress::Progress(std::ostream &out, const std::string &what, const unsigned long total)
    : out(out)
    , what(what)
    , total(total)
    , shown(shown_on(out))
    , start(Clock::now())
    , last_print(start)
  {}

  Progress::~Progress()
  {
    finish();
  }

  void
  Progress::update(const unsigned long done)
  {
    if (!shown)
      return;
    const Clock::time_point now = Clock::now();
    if (!started)
      {
        started    = true;
        first_done = done;
        start      = now;
      }
    if (std::chrono::duration<double>(now - last_print).count() < print_interval)
      return;
    last_print             = now;
    const std::string line = progress_line(what, done, total,
                                           std::chrono::duration<double>(now - start).count(),
                                           first_done);
    // pad over the rest of a longer previous line
    out << '\r' << line << std::string(printed_width > line.size() ? printed_width - line.size() : 0, ' ')
        << std::flush;
    printed_width = line.size();
  }

  void
  Progress::finish()
  {
    if (printed_width == 0)
      return;
    out << '\r' << std::string(printed_width, ' ') << '\r' << std::flush;
    printed_width = 0;
  }
} // namespace poundfe
