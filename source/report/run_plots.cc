// The figures of a run (report/run_plots.h): gnuplot scripts of the CSV
// files the recorders wrote and of the peaks, drawn to PNG (output/plots.h).
#include <poundfe/report/run_plots.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/output/csv_columns.h>
#include <poundfe/output/peak_response.h>
#include <poundfe/output/plan_plot.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>

namespace poundfe
{
  namespace
  {
    /// Each drift limit as a dashed vertical line over the height of the
    /// tallest building, the axis from 0 to past the largest limit.
    void
    add_drift_limits(const Model &model, const std::vector<double> &peak_drift_ratios,
                     const std::vector<DriftLimit> &limits, Plot &drift)
    {
      double largest = 0, height = 0;
      for (const double peak : peak_drift_ratios)
        largest = std::max(largest, peak);
      for (const Building &building : model.buildings)
        if (!building.floors.empty())
          height = std::max(height, building.floors.back().level - building.base_level);
      unsigned int n_limits = 0;
      for (const DriftLimit &limit : limits)
        {
          largest = std::max(largest, limit.drift_ratio);
          const std::string  name = "$limit" + std::to_string(++n_limits);
          std::ostringstream block, range;
          block.precision(17);
          block << name << " << EOD\ndrift,height\n"
                << limit.drift_ratio << ",0\n" << limit.drift_ratio << ',' << height << "\nEOD\n";
          drift.data_blocks += block.str();
          drift.series.push_back({name, "1:2", limit.name, "lines dt 2 lw 2"});
          range << "set xrange [0:" << 1.15 * largest << "]\nset yrange [0:*]\n";
          drift.settings = range.str();
        }
    }
  } // namespace

  RunPlots::RunPlots(const Analysis &analysis, const RunParameters &parameters,
                     const Excitation &excitation, const PeakResponse &peaks,
                     const BaseShearPeaks &base_shears, const std::string &directory,
                     const std::vector<std::string> &files)
    : analysis(analysis)
    , parameters(parameters)
    , excitation(excitation)
    , peaks(peaks)
    , base_shears(base_shears)
    , directory(directory)
    , files(files)
  {}

  bool
  RunPlots::writes(const std::string &file) const
  {
    return std::find(files.begin(), files.end(), file) != files.end();
  }

  void
  RunPlots::draw_phase_portraits(std::vector<Plot> &plots) const
  {
    // phase_portrait.csv: time, (u, u') per equation, then each friction
    // element's phase; stick (phase 0) is marked on the element's equation
    const Model       &model = analysis.model;
    const unsigned int n     = model.n_equations();
    for (unsigned int q = 0; q < n; ++q)
      {
        const std::string x = std::to_string(2 * q + 2), v = std::to_string(2 * q + 3);
        Plot plot{"phase_portrait" + (n > 1 ? "_" + std::to_string(q + 1) : std::string()) + ".png",
                  "Phase portrait", "displacement (m)", "velocity (m/s)",
                  {{"phase_portrait.csv", x + ":" + v, "trajectory", "lines"}}};
        for (unsigned int i = 0; i < model.friction_surfaces.size(); ++i)
          if (model.equation(Model::dof(model.friction_surfaces[i].node, Component::ux)) == int(q))
            {
              const std::string phase = std::to_string(2 * n + 2 + i);
              plot.series.push_back({"phase_portrait.csv",
                                     x + ":($" + phase + "==0?$" + v + ":1/0)",
                                     "stick (" + model.friction_surfaces[i].label + ")",
                                     "points pt 7 ps 0.6"});
            }
        plots.push_back(plot);
      }
  }

  Plot
  energy_plot(const Model &model)
  {
    // energy.csv: time, input, kinetic, damping, strain, hysteretic, contact,
    // balance error, friction, belt, links, foundation (with foundations),
    // constant load (after gravity), J,
    // drawn in kJ. Contact and friction energies are small beside the input:
    // a panel of their own, with the balance error (a ratio) against the
    // right-hand axis. Each term has its own colour, the same in both panels,
    // dark enough to read on white (gnuplot's default cycle has yellow).
    const auto term = [](const unsigned int column, const char *title, const char *colour,
                         const std::string &style = "lines lw 2") {
      return PlotSeries{"energy.csv", "1:($" + std::to_string(column) + "/1000)", title,
                        style + " lc rgb '" + colour + "'"};
    };
    Plot energy{"energy.png", "Energy balance (relative coordinates)", "time (s)", "energy (kJ)",
                {term(2, "input", "black"), term(3, "kinetic", "#1f77b4"),
                 term(4, "damping", "#d62728"), term(5, "strain", "#2ca02c"),
                 term(6, "hysteretic", "#9467bd")}};
    Plot small{"", "Contact and friction energy, and the balance error", "time (s)",
               "energy (kJ)", {term(7, "contact", "#ff7f0e")}};
    if (!model.friction_surfaces.empty())
      for (const PlotSeries &series : {term(9, "friction", "#8c564b"), term(10, "belt", "#17becf")})
        {
          energy.series.push_back(series);
          small.series.push_back(series);
        }
    // links_J (column 11) and foundation_J (12, only with foundations):
    // devices and soil dissipate as much as the structure's damping
    if (!model.building_links.empty())
      energy.series.push_back(term(11, "links", "#e377c2"));
    if (!model.foundations.empty())
      energy.series.push_back(term(12, "foundation", "#7f7f7f"));
    // constant_load_J, the last column after gravity first: the held loads'
    // work, of the size of the strain energy it moves
    if (model.gravity_analysis.enabled)
      energy.series.push_back(
        term(model.foundations.empty() ? 12 : 13, "constant load", "#bcbd22"));
    small.y2_label = "balance error (relative)";
    small.series.push_back({"energy.csv", "1:8", "balance error", "lines dt 2 lc rgb 'gray40'", "x1y2"});
    energy.below.push_back(small);
    return energy;
  }

  namespace
  {
    /// A gnuplot data block `name` ("$...") of the columns `x` and `y`
    /// under the header `x_name,y_name`.
    std::string
    data_block(const std::string &name, const std::string &header, const std::vector<double> &x,
               const std::vector<double> &y)
    {
      AssertDimension(x.size(), y.size());
      std::string block = name + " << EOD\n" + header + "\n";
      for (std::size_t i = 0; i < x.size(); ++i)
        block += number_text(x[i]) + ',' + number_text(y[i]) + '\n';
      return block + "EOD\n";
    }

    /// Each name of `header` with its column (0: the first).
    std::map<std::string, unsigned int>
    columns_by_name(const std::vector<std::string> &header)
    {
      std::map<std::string, unsigned int> column_of;
      for (unsigned int c = 0; c < header.size(); ++c)
        column_of.emplace(header[c], c);
      return column_of;
    }

    /// The curves a figure draws of those with peaks `peaks`: all when a
    /// key can name them, else the max_named_curves with the largest peaks;
    /// in their order.
    std::vector<unsigned int>
    curves_to_draw(const std::vector<double> &peaks, const unsigned int limit = max_named_curves)
    {
      std::vector<unsigned int> drawn(peaks.size());
      std::iota(drawn.begin(), drawn.end(), 0u);
      if (drawn.size() <= limit)
        return drawn;
      std::stable_sort(drawn.begin(), drawn.end(),
                       [&](const unsigned int a, const unsigned int b) { return peaks[a] > peaks[b]; });
      drawn.resize(limit);
      std::sort(drawn.begin(), drawn.end());
      return drawn;
    }

    /// `title`, saying which curves it shows when not all `n` `what` are drawn.
    std::string
    title_of_drawn(const std::string &title, const std::size_t n_drawn, const std::size_t n,
                   const std::string &what)
    {
      if (n_drawn == n)
        return title;
      return title + ": the " + std::to_string(n_drawn) + " of " + std::to_string(n) + " " + what +
             " with the largest peaks";
    }

    /// read_csv_columns, or nothing when the file cannot be read (a figure
    /// then falls back or goes without those curves).
    std::vector<std::vector<double>>
    columns_if_readable(const std::string &path, const std::vector<unsigned int> &columns)
    {
      try
        {
          return read_csv_columns(path, columns);
        }
      catch (const OutputError &)
        {
          return {};
        }
    }

    /// Each column name of the CSV file `path` with its column (0: the
    /// first); nothing when the file cannot be read.
    std::optional<std::map<std::string, unsigned int>>
    columns_by_name_if_readable(const std::string &path)
    {
      try
        {
          return columns_by_name(read_csv_header(path));
        }
      catch (const OutputError &)
        {
          return std::nullopt;
        }
    }

    /// max |x|.
    double
    peak_magnitude(const std::vector<double> &x)
    {
      double peak = 0;
      for (const double v : x)
        peak = std::max(peak, std::abs(v));
      return peak;
    }

    /// The curves `drawn` of `y` against `x`, as data blocks "$<prefix>1",
    /// "$<prefix>2", ... under `header`, each titled and plotted `using`.
    void
    add_drawn_curves(Plot &plot, const std::string &prefix, const std::string &header,
                     const std::vector<double> &x, const std::vector<const std::vector<double> *> &y,
                     const std::vector<std::string> &titles, const std::vector<unsigned int> &drawn,
                     const std::string &using_spec)
    {
      for (unsigned int i = 0; i < drawn.size(); ++i)
        {
          const std::string name = "$" + prefix + std::to_string(i + 1);
          plot.data_blocks += data_block(name, header, x, *y[drawn[i]]);
          plot.series.push_back({name, using_spec, titles[drawn[i]], "lines"});
        }
    }

    /// A curve of column `columns[i]` (0: the first) of `file` in
    /// `directory` against its first column (time) for each title, its
    /// values divided by `divisor`. A few are read by gnuplot from the file;
    /// more (a selection of a wide table's columns) as data blocks of
    /// those columns read in one pass, gnuplot reading the file only if
    /// that fails.
    void
    add_time_series(Plot &plot, const std::string &directory, const std::string &file,
                    const std::vector<unsigned int> &columns, const std::vector<std::string> &titles,
                    const std::string &divisor, const bool in_one_pass)
    {
      const auto scaled = [&](const unsigned int column) {
        const std::string c = std::to_string(column + 1);
        return divisor.empty() ? "1:" + c : "1:($" + c + "/" + divisor + ")";
      };
      std::vector<unsigned int> read{0};
      read.insert(read.end(), columns.begin(), columns.end());
      const std::vector<std::vector<double>> values =
        in_one_pass ? columns_if_readable(directory + "/" + file, read) :
                      std::vector<std::vector<double>>();
      for (unsigned int i = 0; i < columns.size(); ++i)
        if (values.empty())
          plot.series.push_back({file, scaled(columns[i]), titles[i], "lines"});
        else
          {
            const std::string name = "$" + plot.file.substr(0, plot.file.find('.')) + std::to_string(i + 1);
            plot.data_blocks += data_block(name, "time,value", values[0], values[i + 1]);
            plot.series.push_back({name, scaled(1), titles[i], "lines"});
          }
    }

    /// A curve per building of column `column_of[b]` of `file` (add_time_series),
    /// of those curves_to_draw picks by `peaks`, titled by the building's name.
    void
    add_building_series(Plot &plot, const Model &model, const std::string &directory,
                        const std::string &file, const std::vector<unsigned int> &column_of,
                        const std::vector<double> &peaks, const std::string &divisor)
    {
      std::vector<unsigned int> columns;
      std::vector<std::string>  titles;
      for (const unsigned int b : curves_to_draw(peaks))
        {
          columns.push_back(column_of[b]);
          titles.push_back(model.buildings[b].name);
        }
      const std::size_t n_buildings = model.buildings.size();
      plot.title = title_of_drawn(plot.title, columns.size(), n_buildings, "buildings");
      add_time_series(plot, directory, file, columns, titles, divisor, columns.size() < n_buildings);
    }

    /// The largest of `values` (indexed by FloorResponse::index) over each
    /// building's floors.
    std::vector<double>
    peak_per_building(const Model &model, const FloorResponse &floors,
                      const std::vector<double> &values)
    {
      std::vector<double> peak(model.buildings.size(), 0.0);
      for (unsigned int b = 0; b < model.buildings.size(); ++b)
        for (unsigned int f = 0; f < model.buildings[b].floors.size(); ++f)
          peak[b] = std::max(peak[b], values[floors.index(b, f)]);
      return peak;
    }

    /// A hysteresis loop to draw: a hinge's or storey's element and its
    /// force and deformation columns in hinges.csv.
    struct HysteresisLoop
    {
      unsigned int element, force_column, deformation_column;
    };

    /// Whether element `e` is drawn as a hinge (moment against rotation)
    /// rather than as a storey (force against drift).
    bool
    drawn_as_hinge(const NonlinearElement &e)
    {
      return e.kind == ElementKind::hinge || e.kind == ElementKind::member;
    }

    /// One loop per building: of its recorded hinges or storeys (`column_of`:
    /// hinges.csv's columns by name), the one with the largest peak plastic
    /// deformation (|d - F/k0|; mirror-image hinges of a symmetric frame tie,
    /// and the first is kept).
    std::vector<HysteresisLoop>
    hysteresis_loops(const Model &model, const ResponseView &state, const PeakResponse &peaks,
                     const std::map<std::string, unsigned int> &column_of)
    {
      std::vector<HysteresisLoop> loops;
      for (unsigned int b = 0; b < model.buildings.size(); ++b)
        {
          std::optional<HysteresisLoop> chosen;
          for (unsigned int h = 0; h < peaks.n_hysteretic(); ++h)
            {
              const NonlinearElement &e     = state.elements[h];
              const bool              hinge = drawn_as_hinge(e);
              const auto f = column_of.find(e.label + (hinge ? "_moment_N_m" : "_force_N"));
              const auto d = column_of.find(e.label + (hinge ? "_rotation_rad" : "_drift_m"));
              if (e.building == b && f != column_of.end() && d != column_of.end() &&
                  (!chosen || peaks.peak_plastic_deformation()[h] >
                                peaks.peak_plastic_deformation()[chosen->element]))
                chosen = HysteresisLoop{h, f->second, d->second};
            }
          if (chosen)
            loops.push_back(*chosen);
        }
      return loops;
    }

    /// The plot of one loop, moments in kN m, forces in kN, read from
    /// hinges.csv by gnuplot.
    Plot
    hysteresis_plot(const Model &model, const ResponseView &state, const PeakResponse &peaks,
                    const HysteresisLoop &loop)
    {
      const unsigned int      h     = loop.element;
      const NonlinearElement &e     = state.elements[h];
      const bool              hinge = drawn_as_hinge(e);
      std::ostringstream      title;
      title << std::setprecision(3) << (hinge ? "Hinge " : "Storey ") << e.label << " of "
            << model.buildings[e.building].name << ": peak plastic "
            << (hinge ? "rotation " : "drift ") << peaks.peak_plastic_deformation()[h]
            << (hinge ? " rad" : " m") << ", ductility " << peaks.ductility(h);
      return Plot{"hysteresis_" + e.label + ".png", title.str(),
                  hinge ? "rotation (rad)" : "drift (m)", hinge ? "moment (kN m)" : "force (kN)",
                  {{"hinges.csv",
                    std::to_string(loop.deformation_column + 1) + ":($" +
                      std::to_string(loop.force_column + 1) + "/1000)",
                    e.label, "lines"}}};
    }
  } // namespace

  void
  RunPlots::draw_hysteresis(const ResponseView &state, std::vector<Plot> &plots) const
  {
    // hinges.csv: time, then force, deformation and z of each recorded
    // element (all, or those Record names), found by their column names
    const auto names = columns_by_name_if_readable(directory + "/hinges.csv");
    if (!names)
      return; // no loops without the file
    const std::vector<HysteresisLoop> loops =
      hysteresis_loops(analysis.model, state, peaks, *names);
    // the loops' columns in one pass (gnuplot would read the file once per
    // loop); if that fails, gnuplot reads the file
    std::vector<unsigned int> columns;
    for (const HysteresisLoop &loop : loops)
      columns.insert(columns.end(), {loop.deformation_column, loop.force_column});
    const std::vector<std::vector<double>> values =
      columns_if_readable(directory + "/hinges.csv", columns);
    for (unsigned int i = 0; i < loops.size(); ++i)
      {
        Plot plot = hysteresis_plot(analysis.model, state, peaks, loops[i]);
        if (!values.empty())
          {
            const std::string name = "$loop" + std::to_string(i + 1);
            plot.data_blocks = data_block(name, "deformation,force", values[2 * i], values[2 * i + 1]);
            plot.series.front().data_file  = name;
            plot.series.front().using_spec = "1:($2/1000)";
          }
        plots.push_back(plot);
      }
  }

  namespace
  {
    /// More gaps than a key can name: a curve of the total force between
    /// each pair of buildings (or a building and a barrier) with `gaps`
    /// between them (`forces`: each one's, at the rows of `time`), of the
    /// max_named_curves pairs with the largest peaks when there are more.
    void
    add_pair_totals(Plot &plot, const Model &model, const std::vector<unsigned int> &gaps,
                    const std::vector<double>                      &time,
                    const std::vector<const std::vector<double> *> &forces)
    {
      std::map<std::string, std::vector<unsigned int>> pairs; // name: its gaps (of `gaps`)
      for (unsigned int i = 0; i < gaps.size(); ++i)
        {
          const Gap &gap  = model.gaps[gaps[i]];
          const auto side = [&](const unsigned int k) {
            return gap.nodes[k] < 0 ? std::string("barrier") : model.buildings[gap.buildings[k]].name;
          };
          pairs[side(0) + "-" + side(1)].push_back(i);
        }
      std::vector<std::string>         titles;
      std::vector<std::vector<double>> totals; // N, at each row
      std::vector<double>              peaks;
      for (const auto &[name, of_pair] : pairs)
        {
          std::vector<double> total(time.size(), 0.0);
          for (const unsigned int i : of_pair)
            for (std::size_t r = 0; r < total.size(); ++r)
              total[r] += (*forces[i])[r];
          titles.push_back(name);
          peaks.push_back(peak_magnitude(total));
          totals.push_back(std::move(total));
        }
      const std::vector<unsigned int> drawn = curves_to_draw(peaks);
      const std::string what = std::to_string(gaps.size()) + " gap elements" +
                               (plot.title.find(" that touched") != std::string::npos ?
                                  " that touched" : "");
      plot.title = title_of_drawn("Total contact force between adjacent buildings (" + what + ")",
                                  drawn.size(), titles.size(), "pairs");
      std::vector<const std::vector<double> *> curves;
      for (const std::vector<double> &total : totals)
        curves.push_back(&total);
      add_drawn_curves(plot, "pair", "time,force", time, curves, titles, drawn, "1:($2/1000)");
    }
  } // namespace

  Plot
  contact_force_plot(const Model &model, const std::string &directory)
  {
    Plot plot{"contact_force.png", "Contact forces of the gap elements", "time (s)",
              "contact force (kN)", {}};
    // contact_force.csv: time, then force and penetration of each recorded
    // gap (all, or those Record names), found by their column names
    const auto names = columns_by_name_if_readable(directory + "/contact_force.csv");
    if (!names)
      return plot; // drawn without curves: the run's file is missing or damaged
    const std::map<std::string, unsigned int> &column_of = *names;
    std::vector<unsigned int> recorded, force_column; // gaps, their force's column
    for (unsigned int g = 0; g < model.gaps.size(); ++g)
      if (const auto c = column_of.find(model.gaps[g].label + "_force_N"); c != column_of.end())
        {
          recorded.push_back(g);
          force_column.push_back(c->second);
        }
    // only the gaps that touched (a force other than 0 at some row): a
    // flat line at 0 says nothing, and many of them hide the curves that do
    std::vector<unsigned int> columns{0};
    columns.insert(columns.end(), force_column.begin(), force_column.end());
    const std::vector<std::vector<double>> values =
      columns_if_readable(directory + "/contact_force.csv", columns);
    if (values.empty())
      return plot; // drawn without curves: the run's file is missing or damaged
    const std::size_t n_recorded = recorded.size();
    std::vector<unsigned int> touched, touched_column;
    std::vector<const std::vector<double> *> touched_values;
    for (unsigned int i = 0; i < n_recorded; ++i)
      if (peak_magnitude(values[i + 1]) > 0)
        {
          touched.push_back(recorded[i]);
          touched_column.push_back(force_column[i]);
          touched_values.push_back(&values[i + 1]);
        }
    if (touched.empty())
      {
        plot.title = "Contact forces: none of the " + std::to_string(n_recorded) +
                     " recorded gap elements touched";
        plot.series.push_back({"contact_force.csv", "1:(0)", "no gap touched", "lines"});
        return plot;
      }
    const unsigned int n_gaps = touched.size();
    if (n_gaps < n_recorded)
      plot.title = "Contact forces of the " + std::to_string(n_gaps) + " of " +
                   std::to_string(n_recorded) + " recorded gap elements that touched";
    if (n_gaps <= max_named_curves)
      {
        for (unsigned int i = 0; i < n_gaps; ++i)
          plot.series.push_back({"contact_force.csv",
                                 "1:($" + std::to_string(touched_column[i] + 1) + "/1000)",
                                 model.gaps[touched[i]].label, "lines"});
        return plot;
      }
    add_pair_totals(plot, model, touched, values[0], touched_values);
    return plot;
  }

  Plot
  RunPlots::floor_spectra_plot() const
  {
    const double zeta = parameters.spectrum.damping_ratios.front();
    std::ostringstream title;
    title << "Floor response spectra (" << 100 * zeta << " % damping)";
    Plot plot{"floor_spectra.png", title.str(), "period (s)", "pseudo-acceleration (m/s^2)",
              {{"floor_spectra.csv", "1:2", "ground", "lines dt 2 lc rgb 'black'"}}};
    plot.log_x         = true;
    plot.key           = "below"; // one curve per floor
    // floor_spectra.csv: period, ground, the floors (first damping ratio)
    std::vector<unsigned int> columns;
    std::vector<std::string>  titles;
    for (const Building &building : analysis.model.buildings)
      for (unsigned int f = 1; f <= building.floors.size(); ++f)
        {
          columns.push_back(columns.size() + 2);
          titles.push_back(building.name + " floor " + std::to_string(f));
        }
    if (columns.size() <= max_named_curves)
      {
        add_time_series(plot, directory, "floor_spectra.csv", columns, titles, "", false);
        return plot;
      }
    // more floors than a key names: those whose spectrum peaks highest
    std::vector<unsigned int> read{0};
    read.insert(read.end(), columns.begin(), columns.end());
    const std::vector<std::vector<double>> values =
      columns_if_readable(directory + "/floor_spectra.csv", read);
    if (values.empty())
      return plot; // the ground's curve alone: the file is missing or damaged
    std::vector<double>                      peaks;
    std::vector<const std::vector<double> *> curves;
    for (unsigned int i = 0; i < columns.size(); ++i)
      {
        peaks.push_back(peak_magnitude(values[i + 1]));
        curves.push_back(&values[i + 1]);
      }
    const std::vector<unsigned int> drawn = curves_to_draw(peaks);
    plot.title = title_of_drawn(plot.title, drawn.size(), columns.size(), "floors");
    add_drawn_curves(plot, "floor", "period,psa", values[0], curves, titles, drawn, "1:2");
    return plot;
  }

  std::array<Plot, 2>
  RunPlots::profile_plots() const
  {
    // Profiles against the height above the ground: a storey's drift ratio
    // holds over the storey (a step), a floor's acceleration belongs to its
    // level, joined to the ground's PGA. Beyond max_named_curves curves,
    // the buildings with the largest peaks. A 3D model: along x (solid)
    // and along y (dashed) in the building's colour.
    const Model         &model  = analysis.model;
    const FloorResponse &floors = peaks.floors();
    const bool           plan   = peaks.floors_y() != nullptr;
    Plot drift{"drift_profile.png", "Peak inter-storey drift ratio against height",
               "peak |inter-storey drift ratio|", "height above the ground (m)", {}};
    Plot accel{"acceleration_profile.png", "Peak absolute floor acceleration against height",
               "peak |absolute acceleration| (m/s^2)", "height above the ground (m)", {}};
    drift.settings = accel.settings = "set xrange [0:*]\nset yrange [0:*]\n";
    const unsigned int per_building = plan ? 2 : 1;
    const std::array<double, 2> pga = plan ? excitation.applied_horizontal_peaks() :
                                             std::array<double, 2>{{peak_ground_acceleration(), 0}};
    const auto both = [&](const std::vector<double> &(FloorResponse::*value)() const) {
      std::vector<double> peak = peak_per_building(model, floors, (floors.*value)());
      if (plan)
        for (unsigned int b = 0; b < peak.size(); ++b)
          peak[b] = std::max(peak[b], peak_per_building(model, *peaks.floors_y(),
                                                        (peaks.floors_y()->*value)())[b]);
      return peak;
    };
    const unsigned int limit = max_named_curves / per_building;
    for (const unsigned int b : curves_to_draw(both(&FloorResponse::peak_drift_ratio), limit))
      for (unsigned int d = 0; d < per_building; ++d)
        add_profile(drift, b, d, plan, true, 0);
    for (const unsigned int b : curves_to_draw(both(&FloorResponse::peak_acceleration), limit))
      for (unsigned int d = 0; d < per_building; ++d)
        add_profile(accel, b, d, plan, false, pga[d]);
    const std::size_t n_buildings = model.buildings.size();
    drift.title = title_of_drawn(drift.title, drift.series.size() / per_building, n_buildings, "buildings");
    accel.title = title_of_drawn(accel.title, accel.series.size() / per_building, n_buildings, "buildings");
    add_drift_limits(model, floors.peak_drift_ratio(), parameters.drift_limits.limits(), drift);
    return {{drift, accel}};
  }

  void
  RunPlots::add_profile(Plot &plot, const unsigned int b, const unsigned int d, const bool plan,
                        const bool drift, const double pga) const
  {
    const Model         &model    = analysis.model;
    const FloorResponse &floors   = d == 0 ? peaks.floors() : *peaks.floors_y();
    const Building      &building = model.buildings[b];
    const std::string    name     = std::string(drift ? "$drift" : "$accel") +
                             std::to_string(b + 1) + (plan ? (d == 0 ? "x" : "y") : "");
    std::ostringstream block;
    block << std::setprecision(10) << name << " << EOD\n"
          << (drift ? "drift,height\n" : "acceleration,height\n");
    if (!drift)
      block << pga << ",0\n";
    for (unsigned int f = 0; f < building.floors.size(); ++f)
      {
        const Floor &floor = building.floors[f];
        const double top   = floor.level - building.base_level; // above the ground
        const unsigned int i = floors.index(b, f);
        if (drift) // the storey's drift ratio over its height
          block << floors.peak_drift_ratio()[i] << ',' << top - floor.storey_height << '\n'
                << floors.peak_drift_ratio()[i] << ',' << top << '\n';
        else
          block << floors.peak_acceleration()[i] << ',' << top << '\n';
      }
    plot.data_blocks += block.str() + "EOD\n";
    std::string style = drift ? "lines lw 2" : "linespoints lw 2 pt 7";
    if (plan) // one colour per building, y dashed
      style += " lc " + std::to_string(b % 8 + 1) + (d == 1 ? " dt 2" : "");
    plot.series.push_back(
      {name, "1:2", building.name + (plan ? (d == 0 ? " along x" : " along y") : ""), style});
  }

  std::string
  buildings_in_title(const Model &model)
  {
    const std::size_t n = model.buildings.size();
    if (n == 0)
      return "";
    if (n > 4) // a city block: the legend names those drawn
      return std::to_string(n) + " buildings: ";
    std::string names = n == 1 ? "Building " : "Buildings ";
    for (std::size_t b = 0; b < n; ++b)
      names += (b == 0 ? "" : b + 1 == n ? " and " : ", ") + model.buildings[b].name;
    return names + ": ";
  }

  void
  name_buildings_in_titles(std::vector<Plot> &plots, const Model &model)
  {
    // the figures of the whole model; a hysteresis loop names its own storey
    // and building, a phase portrait its DOF, ground_motion.png its record
    const std::set<std::string> whole_model{
      "drift_profile.png", "acceleration_profile.png", "roof_displacement.png",
      "base_shear.png",    "energy.png",               "floor_spectra.png",
      "contact_force.png", "impacts_plan.png"};
    const std::string names = buildings_in_title(model);
    for (Plot &plot : plots)
      if (whole_model.count(plot.file) > 0)
        plot.title = names + plot.title;
  }

  Plot
  RunPlots::roof_plot() const
  {
    // floor_displacement.csv: time, then each building's floors, bottom to
    // top (3D: x, y and θz of each floor)
    const Model         &model  = analysis.model;
    const FloorResponse &floors = peaks.floors();
    const bool           plan   = peaks.floors_y() != nullptr;
    std::vector<double>  peak_roof;
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      {
        const unsigned int n_floors = model.buildings[b].floors.size();
        const unsigned int roof     = floors.index(b, n_floors - 1);
        peak_roof.push_back(n_floors == 0 ? 0.0 :
                              std::max(floors.peak_displacement()[roof],
                                       plan ? peaks.floors_y()->peak_displacement()[roof] : 0.0));
      }
    Plot roof{"roof_displacement.png",
              plan ? "Roof displacement of the mass centre (relative to the ground)" :
                     "Roof displacement (relative to the ground)",
              "time (s)", "displacement (mm)", {}};
    if (!plan)
      {
        std::vector<unsigned int> roof_column;
        for (unsigned int b = 0, column = 1; b < model.buildings.size(); ++b)
          {
            column += model.buildings[b].floors.size();
            roof_column.push_back(column - 1);
          }
        add_building_series(roof, model, directory, "floor_displacement.csv", roof_column,
                            peak_roof, "0.001"); // m to mm
        return roof;
      }
    std::vector<unsigned int> columns;
    std::vector<std::string>  titles;
    const std::vector<unsigned int> drawn = curves_to_draw(peak_roof, max_named_curves / 2);
    for (const unsigned int b : drawn)
      {
        const unsigned int roof = floors.index(b, model.buildings[b].floors.size() - 1);
        columns.insert(columns.end(), {1 + 3 * roof, 2 + 3 * roof}); // its x and y
        titles.insert(titles.end(), {model.buildings[b].name + " along x",
                                     model.buildings[b].name + " along y"});
      }
    roof.title = title_of_drawn(roof.title, drawn.size(), model.buildings.size(), "buildings");
    add_time_series(roof, directory, "floor_displacement.csv", columns, titles, "0.001",
                    drawn.size() < model.buildings.size());
    return roof;
  }

  Plot
  RunPlots::base_shear_plot() const
  {
    const Model &model = analysis.model;
    Plot shear{"base_shear.png", "Base shear (element forces)", "time (s)", "base shear (kN)", {}};
    std::vector<unsigned int> column(model.buildings.size()); // base_shear.csv: time, a building each
    std::iota(column.begin(), column.end(), 1u);
    std::vector<double> peak_shear = base_shears.peak();
    peak_shear.resize(model.buildings.size(), 0.0); // not observed: a run stopped before its start
    const PlanResponse *plan = peaks.plan();
    if (!plan)
      {
        add_building_series(shear, model, directory, "base_shear.csv", column, peak_shear, "1000");
        return shear;
      }
    // 3D: base_shear.csv holds V_x, V_y and the torque of each building; the
    // shears along x (solid) and y, the torque (another unit) left out
    for (unsigned int b = 0; b < plan->buildings().size() && b < peak_shear.size(); ++b)
      peak_shear[b] = std::max(plan->buildings()[b].base_shear_x, plan->buildings()[b].base_shear_y);
    std::vector<unsigned int> columns;
    std::vector<std::string>  titles;
    const std::vector<unsigned int> drawn = curves_to_draw(peak_shear, max_named_curves / 2);
    for (const unsigned int b : drawn)
      {
        columns.insert(columns.end(), {1 + 3 * b, 2 + 3 * b});
        titles.insert(titles.end(), {model.buildings[b].name + " along x",
                                     model.buildings[b].name + " along y"});
      }
    shear.title = title_of_drawn("Base shears along x and y (element forces)", drawn.size(),
                                 model.buildings.size(), "buildings");
    add_time_series(shear, directory, "base_shear.csv", columns, titles, "1000",
                    drawn.size() < model.buildings.size());
    return shear;
  }

  double
  RunPlots::peak_ground_acceleration() const
  {
    return excitation.ground_motion().empty() ? 0 : excitation.ground_motion().peak();
  }

  std::vector<std::string>
  RunPlots::draw(const ResponseView &state) const
  {
    const Model      &model    = analysis.model;
    const auto        profiles = profile_plots();
    std::vector<Plot> all(profiles.begin(), profiles.end());
    if (writes("floor_displacement.csv"))
      all.push_back(roof_plot());
    if (writes("ground_motion.csv") && peak_ground_acceleration() > 0) // not for force-driven runs
      {
        Plot ground{"ground_motion.png", excitation.ground_motion().description(), "time (s)",
                    "ground acceleration (m/s^2)", {{"ground_motion.csv", "1:2", "a_g", "lines"}}};
        if (model.dimension == 3) // every component as applied, after the incidence rotation
          ground.series = {{"ground_motion.csv", "1:2", "a_x", "lines"},
                           {"ground_motion.csv", "1:3", "a_y", "lines"}};
        all.push_back(ground);
      }
    if (writes("base_shear.csv"))
      all.push_back(base_shear_plot());
    if (writes("energy.csv"))
      all.push_back(energy_plot(model));
    if (writes("hinges.csv"))
      draw_hysteresis(state, all);
    if (writes("floor_spectra.csv"))
      all.push_back(floor_spectra_plot());
    if (writes("phase_portrait.csv"))
      draw_phase_portraits(all);
    if (writes("contact_force.csv"))
      all.push_back(contact_force_plot(model, directory));
    if (model.dimension == 3 && !model.gaps.empty())
      all.push_back(impact_plan_plot(model, state.impact_log().impacts()));
    name_buildings_in_titles(all, model);
    return draw_plots(directory, all);
  }
} // namespace poundfe
