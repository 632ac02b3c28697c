// The figures of a response's distribution over the realizations of a Monte
// Carlo run (pdf_<stem>.png, cdf_<stem>.png): the title names the quantity
// and the building (or "all buildings"), the axis is in the unit engineers
// read (g, mm, kN; the CSV files stay in SI), the histogram's x range is its
// bins' outer edges so that no bar is cut at either end, and a count
// (impacts) gets one bar per whole number, its height the number of
// realizations.
#ifndef poundfe_reliability_distribution_plots_h
#define poundfe_reliability_distribution_plots_h

#include <poundfe/output/plots.h>
#include <poundfe/reliability/statistics.h>

#include <array>
#include <string>
#include <vector>

namespace poundfe
{
  struct ResponseFigure
  {
    std::string stem;     // pdf_<stem>.csv (bin_low, bin_high, bin_center, count, density)
    std::string quantity; // the title: "Peak roof displacement of building A"
    std::string axis;     // the axis, with its unit: "peak roof displacement (mm)"
    std::string unit;     // of the axis, for the density's: "mm"; empty: dimensionless
    double      si_per_unit = 1; // SI value of one unit of the axis: 1e-3 for mm
    bool        is_count    = false; // whole numbers
  };

  /// pdf_<stem>.png from pdf_<stem>.csv (histogram `h` of the completed
  /// `values`, SI) or, for a count, from a data block of one bin per whole
  /// number; cdf_<stem>.png from cdf_<stem>.csv (value, probability).
  std::array<Plot, 2> distribution_plots(const ResponseFigure &figure, const Histogram &h,
                                         const std::vector<double> &values);
} // namespace poundfe

#endif
