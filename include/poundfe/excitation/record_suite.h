// A suite of recorded ground motions for record-based assessment (IDA):
//  - a CSV file with a header row naming its columns: file (required; the
//    record of the first horizontal component), file2 (the second horizontal
//    component of a pair, for 3D models), name, scale, event, station,
//    magnitude, distance_km, vs30_m_s; '#' starts a comment line;
//  - a JSON file {"records": [{"name": ..., "files": ["a.AT2", "b.AT2"],
//    "scale": 1.5, "event": ..., "station": ..., "magnitude": ...,
//    "distance_km": ..., "vs30_m_s": ...}, ...]};
//  - a folder: every PEER .AT2 file in it (any case), in the order of
//    their names, one component each.
// Record paths are relative to the suite file (to the folder). Each record
// is read (records.h: AT2 by extension, else two-column text) and scaled by
// its factor when the suite is read, so that a missing or unreadable record,
// a pair whose components differ in time step or length, a name given
// twice or a scale factor that is not positive is an InputError naming the
// suite's file, line and field before anything runs.
#ifndef poundfe_excitation_record_suite_h
#define poundfe_excitation_record_suite_h

#include <poundfe/excitation/ground_motion.h>

#include <cmath>
#include <string>
#include <vector>

namespace poundfe
{
  struct SuiteRecord
  {
    std::string               name;
    std::vector<std::string>  files;      // as resolved, one or two
    std::vector<GroundMotion> components; // in m/s^2, times scale_factor
    double                    scale_factor = 1;
    std::string               event, station;
    double                    magnitude = NAN, distance_km = NAN, vs30_m_s = NAN;
    int                       line = 0; // in the suite file (0: a folder or JSON)
  };

  struct RecordSuite
  {
    std::string              file; // the suite file or folder
    std::vector<SuiteRecord> records;
    /// Records with two components (every record has the same number).
    bool pairs() const { return !records.empty() && records[0].components.size() == 2; }
  };

  /// The periods every record of a suite resolves: from the longest
  /// Nyquist period, twice a record's time step (below it an oscillator
  /// follows the ground and Sa is the PGA), to the shortest duration
  /// (beyond it a record holds not one cycle); the records that set them.
  struct ResolvedPeriods
  {
    double      shortest = 0, longest = INFINITY; // s
    std::string shortest_of, longest_of;          // the records' names

    /// Within the range but for round-off: a duration dt (n - 1) may fall
    /// an ulp short of the period written as its decimal.
    bool
    holds(const double period) const
    {
      const double slack = 1e-12;
      return period >= shortest * (1 - slack) && period <= longest * (1 + slack);
    }
    /// "0.02 to 4 s: from twice the time step (the Nyquist period) of
    /// record 'a' to the duration of record 'b'" (six digits: a period and
    /// the limit it passes differ visibly).
    std::string text() const;
  };

  ResolvedPeriods resolved_periods(const RecordSuite &suite);

  /// Reads the suite at `path` (a .csv, a .json or a folder of .AT2 files);
  /// `parameter` is the entry that names it, for messages about the path
  /// itself. Throws InputError.
  RecordSuite read_record_suite(const std::string &path, const std::string &parameter = "");

  /// The columns a CSV suite may have, in their usual order.
  const std::vector<std::string> &record_suite_columns();
} // namespace poundfe

#endif
