// The phase portrait of `poundfe switching` (report/switching_plot.h).
#include <poundfe/report/switching_plot.h>

#include <cmath>
#include <sstream>

namespace poundfe
{
  namespace
  {
    /// A dashed line of the (u, v) plane for each surface on equation 1's
    /// u or v alone (n . x = c with n along u_1 or v_1 only).
    std::string
    surface_lines(const std::vector<SwitchingSurface> &surfaces, const unsigned int n)
    {
      std::ostringstream lines;
      for (const SwitchingSurface &s : surfaces)
        {
          const double u_part = s.normal[0], v_part = s.normal[n];
          if (s.normal.cwiseAbs().sum() != std::abs(u_part) + std::abs(v_part) ||
              (u_part != 0) == (v_part != 0))
            continue; // not a line of this portrait
          const double at = s.offset / (u_part != 0 ? u_part : v_part);
          lines << "set arrow from " << (u_part != 0 ? "first " : "graph 0, first ") << at
                << (u_part != 0 ? ", graph 0 to first " : " to graph 1, first ") << at
                << (u_part != 0 ? ", graph 1" : "") << " nohead dt 2 lc rgb 'gray40'\n";
        }
      return lines.str();
    }
  } // namespace

  Plot
  switching_phase_portrait(const std::vector<SwitchingSurface> &surfaces,
                           const unsigned int n, const std::set<std::string> &classes,
                           const bool slides, const bool rotation)
  {
    const std::string u = "2", v = std::to_string(2 + n), sliding = std::to_string(2 + 2 * n);
    const std::string cls = std::to_string(2 * n + 9); // switching.csv's class column
    Plot plot{"phase_portrait.png", "Phase portrait of equation 1 with its switching surfaces",
              rotation ? "rotation u_1 (rad)" : "displacement u_1 (m)",
              rotation ? "angular velocity v_1 (rad/s)" : "velocity v_1 (m/s)",
              {{"trajectory.csv", u + ":" + v, "trajectory", "lines lc rgb 'black'"}}};
    if (slides)
      plot.series.push_back({"trajectory.csv", u + ":($" + sliding + " > 0 ? $" + v + " : 1/0)",
                             "sliding (Filippov)", "points pt 7 ps 0.6 lc rgb 'red'"});
    const struct
    {
      const char *name, *title, *style;
    } markers[] = {{"crossing", "crossing", "points pt 6 ps 1.2 lc rgb 'blue'"},
                   {"attracting-sliding", "attracting sliding", "points pt 9 ps 1.4 lc rgb 'dark-green'"},
                   {"sliding-exit", "sliding exit", "points pt 11 ps 1.4 lc rgb 'orange'"},
                   {"grazing", "grazing", "points pt 4 ps 1.4 lc rgb 'magenta'"},
                   {"repulsive-sliding", "repulsive sliding", "points pt 2 ps 1.4 lc rgb 'purple'"}};
    for (const auto &marker : markers)
      if (classes.count(marker.name))
        plot.series.push_back({"switching.csv",
                               u + ":(strcol(" + cls + ") eq '" + marker.name + "' ? $" + v + " : 1/0)",
                               marker.title, marker.style});
    plot.settings = "set datafile separator ','\n" + surface_lines(surfaces, n);
    return plot;
  }
} // namespace poundfe
