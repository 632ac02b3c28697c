// The figures of a response's distribution (reliability/distribution_plots.h).
#include <poundfe/base/numbers.h>
#include <poundfe/reliability/distribution_plots.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  namespace
  {
    /// Column `column` over (or times) k for gnuplot's using: "($3/0.001)",
    /// or the bare column number when k = 1 (gnuplot reads "$3" alone as
    /// an error).
    std::string
    in_unit(const std::string &column, const double si_per_unit, const bool divide)
    {
      if (si_per_unit == 1)
        return column;
      return "($" + column + (divide ? "/" : "*") + number_text(si_per_unit) + ")";
    }

    /// "set yrange [0:top]" a tenth above the tallest bar `tallest`, so that
    /// no bar touches the frame (autoscaling stops at the bar when its
    /// height is a tic).
    std::string
    range_above_bars(const double tallest)
    {
      return "set yrange [0:" + number_text(tallest > 0 ? 1.1 * tallest : 1.0) + "]\n";
    }

    /// One bar per whole number of `values`: a data block "$counts" of
    /// (value, realizations), with its x range half a unit beyond the ends.
    void
    add_count_bars(Plot &pdf, const std::vector<double> &values)
    {
      const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
      const unsigned int n_whole =
        static_cast<unsigned int>(std::round(*hi) - std::round(*lo)) + 1;
      const Histogram bars = count_histogram(values, n_whole); // width 1
      pdf.data_blocks      = "$counts << EOD\nvalue,realizations\n";
      for (std::size_t i = 0; i < bars.counts.size(); ++i)
        pdf.data_blocks += number_text(bars.edges[i] + 0.5) + "," +
                           std::to_string(bars.counts[i]) + "\n";
      pdf.data_blocks += "EOD\n";
      pdf.y_label = "realizations";
      pdf.series  = {{"$counts", "1:2", "realizations", "boxes"}};
      const unsigned long tallest = *std::max_element(bars.counts.begin(), bars.counts.end());
      pdf.settings = "set boxwidth 0.8\n" + range_above_bars(tallest) + "set xrange [" +
                     number_text(bars.edges.front()) + ":" + number_text(bars.edges.back()) +
                     "]\n" + (n_whole <= 30 ? "set xtics 1\n" : "");
    }
  } // namespace

  std::array<Plot, 2>
  distribution_plots(const ResponseFigure &f, const Histogram &h,
                     const std::vector<double> &values)
  {
    const std::string n = std::to_string(values.size()) + " realizations";
    Plot pdf{"pdf_" + f.stem + ".png", f.quantity + ": histogram of " + n, f.axis,
             f.unit.empty() ? "probability density" : "probability density (1/" + f.unit + ")", {}, false, true};
    if (f.is_count && !values.empty())
      add_count_bars(pdf, values);
    else
      {
        pdf.series = {{"pdf_" + f.stem + ".csv",
                       in_unit("3", f.si_per_unit, true) + ":" + in_unit("5", f.si_per_unit, false),
                       "histogram", "boxes"}};
        const double tallest =
          h.density.empty() ? 0.0 : *std::max_element(h.density.begin(), h.density.end());
        pdf.settings = range_above_bars(tallest * f.si_per_unit); // the density per unit of the axis
        if (!h.edges.empty() && h.edges.back() > h.edges.front()) // the outer edges: no bar cut
          pdf.settings += "set xrange [" + number_text(h.edges.front() / f.si_per_unit) + ":" +
                          number_text(h.edges.back() / f.si_per_unit) + "]\n";
      }
    Plot cdf{"cdf_" + f.stem + ".png", f.quantity + ": empirical CDF of " + n, f.axis,
             "P(X <= x)",
             {{"cdf_" + f.stem + ".csv", in_unit("1", f.si_per_unit, true) + ":2", "ECDF", "steps"}}};
    cdf.settings = "set yrange [0:1.05]\n";
    return {{pdf, cdf}};
  }
} // namespace poundfe
