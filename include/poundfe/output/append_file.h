// A results file that grows one line at a time and survives being killed:
// each line goes out in a single write() on an O_APPEND descriptor and is
// synced, so after a crash the file holds complete lines and at most one
// partial last line (which its reader must drop). A line written is in the
// kernel's page cache once write() returns, so it survives the process being
// killed even unsynced; the sync guards against the machine going down. A
// writer of many short lines (ida's journal, a line every few ms, where a
// sync can take longer than the run the line records) syncs them in groups,
// each group's sync on a thread of its own while the writer goes on: a
// machine going down loses at most the lines since the last sync completed,
// which a resume computes again.
#ifndef poundfe_output_append_file_h
#define poundfe_output_append_file_h

#include <chrono>
#include <future>
#include <string>

namespace poundfe
{
  class AppendFile
  {
  public:
    explicit AppendFile(const std::string &path);
    ~AppendFile();
    AppendFile(const AppendFile &) = delete;
    AppendFile &operator=(const AppendFile &) = delete;

    /// Appends `line` (which must end with '\n') and, with `sync`, syncs
    /// the file to disk.
    void append(const std::string &line, bool sync = true);
    /// Syncs what was appended to disk (after a grouped sync under way).
    void sync();
    /// Appends `line` and, when the last sync started over half a second
    /// ago and has ended, starts another on a thread of its own: a journal
    /// of many short rows (a few ms each, where a sync can outlast the row)
    /// synced in groups without waiting on the disk; its writer syncs at
    /// its end.
    void append_grouped(const std::string &line);

  private:
    std::string path;
    int         descriptor = -1;
    std::chrono::steady_clock::time_point synced = std::chrono::steady_clock::now();
    std::future<void> syncing; // a grouped sync under way (or ended)
  };

  /// Appends x in the shortest form that reads back to the same double;
  /// NumericalError unless it is finite (output/finite_output.h).
  void append_number(std::string &text, double x);

  /// Appends ',' and x, or ',' alone when x is not finite (a value a table
  /// has not: a fit that was not made, a fractile above collapse).
  void append_field(std::string &text, double x);
} // namespace poundfe

#endif
