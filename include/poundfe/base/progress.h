// A one-line progress report for long loops, rewritten in place ('\r') with
// the rate and the time left:
//   "  run: 12000/20000 steps, 52,000 steps/s, ETA 0.2 s"
// It shows only on a terminal (stderr is one, and the stream is std::cerr,
// std::clog, or std::cout when stdout is one too), so tests, pipes and log
// files see nothing; POUNDFE_PROGRESS=1 forces it on (e.g. under mpirun,
// whose ranks write stderr to a pipe), POUNDFE_PROGRESS=0 off.
#ifndef poundfe_base_progress_h
#define poundfe_base_progress_h

#include <chrono>
#include <iosfwd>
#include <string>

namespace poundfe
{
  /// The line for `done` of `total`, `elapsed_seconds` after `first_done`
  /// were done. `what` names the counted things, optionally after a label
  /// and ": " ("run: steps", "realizations"). The rate has three significant
  /// digits (thousands separated by ','); no rate or ETA before there is one.
  std::string progress_line(const std::string &what, unsigned long done, unsigned long total,
                            double elapsed_seconds, unsigned long first_done = 0);

  /// "0.4 s", "42 s", "3 min 05 s", "2 h 07 min".
  std::string format_duration(double seconds);

  class Progress
  {
  public:
    /// Nothing is printed before half a second has passed, so short loops
    /// stay silent even on a terminal.
    Progress(std::ostream &out, const std::string &what, unsigned long total);
    /// finish()
    ~Progress();
    Progress(const Progress &) = delete;
    Progress &operator=(const Progress &) = delete;

    /// `done` of `total` are done; prints at most every 0.5 s. The rate and
    /// the ETA count from the first call: on resuming, call it once at the
    /// start with what an earlier run did.
    void update(unsigned long done);
    /// Erases the line (the command prints its own summary). Idempotent.
    void finish();

    /// Whether it prints at all (callers drop their own periodic messages then).
    bool active() const { return shown; }

  private:
    using Clock = std::chrono::steady_clock;

    std::ostream     &out;
    const std::string what;
    const unsigned long total;
    const bool        shown;
    bool              started = false;
    unsigned long     first_done = 0;
    Clock::time_point start, last_print;
    std::size_t       printed_width = 0; // of the line on screen, 0: none
  };
} // namespace poundfe

#endif
