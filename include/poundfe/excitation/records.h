// Recorded accelerograms: PEER .AT2 (NGA "NPTS=..., DT=..." header line and
// the NGA-West2 "n dt NPTS, DT" style; any number of header lines before it;
// values in g) and plain text with one (acceleration) or two (time,
// acceleration) columns.
#ifndef poundfe_excitation_records_h
#define poundfe_excitation_records_h

#include <poundfe/excitation/ground_motion.h>

#include <string>
#include <vector>

namespace poundfe
{
  enum class RecordFileFormat
  {
    automatic, // from the extension: .at2 (any case) or text
    at2,
    text
  };

  enum class RecordUnits
  {
    g,
    m_per_s2 // AT2 files are always in g
  };

  struct RecordFormat
  {
    RecordFileFormat format    = RecordFileFormat::automatic;
    RecordUnits      units     = RecordUnits::g;
    double      time_step = 0;      // for one-column text
  };

  /// Rows of one or two numeric columns (',', ';' or blanks between; '#'
  /// comments; a leading header row of names is skipped).
  struct ColumnTable
  {
    std::size_t         columns = 0;
    std::vector<double> times; // first column when there are two
    std::vector<double> values;
  };
  ColumnTable read_columns(const std::string &file);

  /// Read a record; throws InputError naming the file and line.
  GroundMotion read_record(const std::string &file, const RecordFormat &format);

  /// The text of a PEER AT2 file of `acceleration` (m/s^2, written in g with
  /// nine significant digits, five values a line) at time step `dt`: four
  /// header lines, the second `title`, the fourth "NPTS= n, DT= dt SEC", so
  /// that read_record gives the values back to within 5e-9 relative.
  std::string at2_text(const std::vector<double> &acceleration, double dt,
                       const std::string &title);
} // namespace poundfe

#endif
