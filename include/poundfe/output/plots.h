// PNG plots drawn by gnuplot from the CSV files of a run. Plots are optional:
// without gnuplot a warning is printed and the run still succeeds.
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
  };

  struct Plot
  {
    std::string             file; // PNG name in the output directory
    std::string             title, x_label, y_label;
    std::vector<PlotSeries> series;
    bool                    log_y      = false;
    bool                    style_fill = false; // filled boxes (histograms)
    /// Panels drawn under this one in the same PNG (gnuplot multiplot, one
    /// column); their own `file` and `below` are not used.
    std::vector<Plot>       below{};
    bool                    log_x = false; // e.g. periods of a spectrum
    /// gnuplot's key position for this panel, e.g. "below" (many curves
    /// that fill the frame); empty: inside, top right.
    std::string             key{};
  };

  /// Draw the plots; returns the files written. Writes each PNG atomically.
  std::vector<std::string> draw_plots(const std::string &directory, const std::vector<Plot> &plots);
} // namespace poundfe

#endif
