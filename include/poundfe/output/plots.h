// PNG plots drawn by gnuplot from the CSV files of a run. Plots are optional:
// without gnuplot, or when gnuplot fails, a warning is printed, the figures
// that were not drawn are remembered (missing_figures()) and the command
// still succeeds, but its summary.json says "completed with warnings" and
// lists them (commands/command_guard.h). gnuplot's script and log are
// removed either way: no helper file stays in the results. Legends go below
// the plot area, so they never cover the data.
#ifndef poundfe_output_plots_h
#define poundfe_output_plots_h

#include <string>
#include <vector>

namespace poundfe
{
  struct PlotSeries
  {
    std::string data_file; // CSV relative to the output directory
    std::string using_spec; // gnuplot "using" clause, e.g. "1:3"
    std::string title;
    std::string style = "lines";
    std::string axes  = ""; // "x1y2": against the right-hand axis
  };

  struct Plot
  {
    std::string             file; // PNG name in the output directory
    std::string             title, x_label, y_label;
    std::vector<PlotSeries> series;
    bool                    log_y      = false;
    bool                    style_fill = false; // filled boxes (histograms)
    /// Label of the right-hand axis (series with axes = "x1y2"); empty: none.
    std::string             y2_label{};
    /// gnuplot datablocks the series can name as data ("$name"), each with
    /// a header row: data not in any CSV (e.g. profiles against height).
    std::string             data_blocks{};
    /// Further gnuplot settings of this panel (ranges, reference lines).
    std::string             settings{};
    /// Panels drawn under this one in the same PNG (gnuplot multiplot, one
    /// column); their own `file` and `below` are not used.
    std::vector<Plot>       below{};
    bool                    log_x = false; // e.g. periods of a spectrum
    std::string             x_range{}; // gnuplot's "[min:max]"; empty: autoscaled
    std::string             key{};     // gnuplot key placement, e.g. "outside right top"; empty: below
  };

  /// The gnuplot script that draws `plots` (each PNG to its name + ".tmp"):
  /// each panel first resets what an earlier one may have set (ranges,
  /// arrows, labels, tics, box width, log scales, the right-hand axis), so
  /// that a figure draws the same alone or after others.
  std::string plot_script(const std::vector<Plot> &plots);
  /// Draw the plots; returns the files written. Writes each PNG atomically.
  std::vector<std::string> draw_plots(const std::string &directory, const std::vector<Plot> &plots);

  /// The figures draw_plots was asked for and did not write, in this
  /// process, since forget_missing_figures(); with the reason for each.
  struct MissingFigure
  {
    std::string file;   // relative to `directory`, e.g. "drift.png"
    std::string directory;
    std::string reason; // "gnuplot not found", gnuplot's first error line
  };
  const std::vector<MissingFigure> &missing_figures();
  void                              forget_missing_figures();
} // namespace poundfe

#endif
