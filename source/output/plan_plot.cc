// The plan-view impact plot of include/poundfe/output/plan_plot.h.
#include <poundfe/output/plan_plot.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace poundfe
{
  namespace
  {
    /// A gnuplot datablock `name` of (x, y) rows: each outline closed, the
    /// outlines apart by a blank line (gnuplot lifts the pen there).
    std::string
    outline_block(const std::string &name, const std::vector<std::vector<Point2>> &outlines)
    {
      std::ostringstream block;
      block.precision(17);
      block << name << " << EOD\nx,y\n";
      for (const std::vector<Point2> &outline : outlines)
        {
          for (std::size_t k = 0; k <= outline.size(); ++k)
            block << outline[k % outline.size()].x << ',' << outline[k % outline.size()].y
                  << '\n';
          block << '\n';
        }
      return block.str() + "EOD\n";
    }

    bool
    same_outline(const std::vector<Point2> &a, const std::vector<Point2> &b)
    {
      return a.size() == b.size() &&
             std::equal(a.begin(), a.end(), b.begin(), [](const Point2 &p, const Point2 &q) {
               return std::abs(p.x - q.x) < 1e-9 && std::abs(p.y - q.y) < 1e-9;
             });
    }
  } // namespace

  Plot
  impact_plan_plot(const Model &model, const std::vector<Impact> &impacts)
  {
    Plot plot{"impacts_plan.png", "Impacts in plan (point size ~ peak force)", "x (m)", "y (m)",
              {}};
    plot.settings = "set size ratio -1\nset offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05\n";
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      {
        std::vector<std::vector<Point2>> outlines; // the distinct ones, bottom up
        for (const PlanFloor &floor : model.buildings[b].plan)
          if (!floor.outline.empty() &&
              std::none_of(outlines.begin(), outlines.end(), [&](const auto &o) {
                return same_outline(o, floor.outline);
              }))
            outlines.push_back(floor.outline);
        if (outlines.empty())
          continue;
        const std::string name = "$slab" + std::to_string(b + 1);
        plot.data_blocks += outline_block(name, outlines);
        plot.series.push_back({name, "1:2", model.buildings[b].name, "lines lw 2"});
      }
    double largest = 0;
    for (const Impact &impact : impacts)
      largest = std::max(largest, impact.peak_force);
    std::ostringstream block;
    block.precision(17);
    block << "$impacts << EOD\nx,y,size\n";
    unsigned int n_points = 0;
    for (const Impact &impact : impacts)
      if (std::isfinite(impact.point[0]) && std::isfinite(impact.point[1]))
        {
          block << impact.point[0] << ',' << impact.point[1] << ','
                << 1 + 3 * (largest > 0 ? impact.peak_force / largest : 0.0) << '\n';
          ++n_points;
        }
    if (n_points > 0) // gnuplot refuses a series without points
      {
        plot.data_blocks += block.str() + "EOD\n";
        plot.series.push_back({"$impacts", "1:2:3",
                               std::to_string(n_points) + " impacts",
                               "points pt 6 lw 2 ps variable lc rgb 'red'"});
      }
    else
      plot.title = "Impacts in plan: none";
    return plot;
  }
} // namespace poundfe
