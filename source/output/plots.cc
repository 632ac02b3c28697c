#include <poundfe/base/interruption.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/plots.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <sys/wait.h>

namespace poundfe
{
  namespace
  {
    std::string
    quoted(const std::string &s)
    {
      std::string out = "'";
      for (const char c : s)
        out += (c == '\'') ? std::string("''") : std::string(1, c);
      return out + "'";
    }

    /// Title, labels, scales and the plot command of one panel.
    void
    write_panel(std::ostream &script, const Plot &plot)
    {
      // what an earlier panel may have set (a count histogram's one tic per
      // whole number and its bars' width would reach the next figure's axis;
      // mitigation's rotated case names and offsets)
      script << "set autoscale\nunset arrow\nunset label\nset xtics norotate autofreq\n"
                "set boxwidth\nset offsets 0, 0, 0, 0\n";
      if (plot.y2_label.empty())
        script << "unset y2label\nunset y2tics\nset ytics mirror\n";
      else
        script << "set y2label " << quoted(plot.y2_label) << "\nset y2tics\nset ytics nomirror\n";
      script << plot.data_blocks << "set title " << quoted(plot.title) << " noenhanced\n"
             << "set xlabel " << quoted(plot.x_label) << "\n"
             << "set ylabel " << quoted(plot.y_label) << "\n"
             << (plot.log_y ? "set logscale y\n" : "unset logscale y\n")
             << (plot.log_x ? "set logscale x\n" : "unset logscale x\n")
             << (plot.x_range.empty() ? "set autoscale x\n" : "set xrange " + plot.x_range + "\n")
             << "set key " << (plot.key.empty() ? "below" : plot.key) << "\n"
             << (plot.style_fill ? "set style fill solid 0.5 border\n" : "set style fill empty\n")
             << plot.settings << "plot ";
      for (std::size_t i = 0; i < plot.series.size(); ++i)
        {
          const PlotSeries &s = plot.series[i];
          const bool block = !s.data_file.empty() && s.data_file[0] == '$';
          script << (i ? ", " : "") << (block ? s.data_file : quoted(s.data_file)) << " using "
                 << s.using_spec << (s.axes.empty() ? "" : " axes " + s.axes) << " with "
                 << s.style << " title " << quoted(s.title) << " noenhanced";
        }
      script << "\n";
    }
  } // namespace

  namespace
  {
    std::vector<MissingFigure> &
    missing()
    {
      static std::vector<MissingFigure> figures;
      return figures;
    }

    /// The first line of gnuplot's log that says what went wrong.
    std::string
    first_error(const std::string &log_file)
    {
      std::ifstream log(log_file);
      std::string   first, line;
      while (std::getline(log, line))
        {
          if (first.empty() && !line.empty())
            first = line;
          if (line.find("rror") != std::string::npos || line.find("arning") != std::string::npos)
            return line.substr(0, 300);
        }
      return first.empty() ? "gnuplot failed without a message" : first.substr(0, 300);
    }

    /// "SIGINT" or "SIGTERM" when the shell running gnuplot, or gnuplot,
    /// was stopped by that signal (std::system's `status`: the shell's wait
    /// status, or its exit status 128 + n for a child killed by signal n);
    /// empty otherwise. std::system ignores SIGINT in the caller while the
    /// shell runs, so a Ctrl-C at a terminal stops gnuplot alone.
    std::string
    stopping_signal(const int status)
    {
      int signal = 0;
      if (status != -1 && WIFSIGNALED(status))
        signal = WTERMSIG(status);
      else if (status != -1 && WIFEXITED(status) && WEXITSTATUS(status) > 128)
        signal = WEXITSTATUS(status) - 128;
      return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "";
    }
  } // namespace

  const std::vector<MissingFigure> &
  missing_figures()
  {
    return missing();
  }

  void
  forget_missing_figures()
  {
    missing().clear();
  }

  std::string
  plot_script(const std::vector<Plot> &plots)
  {
    std::ostringstream script;
    script << "set datafile separator ','\nset key autotitle columnhead below\n"
              "set grid\n";
    for (const Plot &plot : plots)
      {
        const std::size_t n_panels = 1 + plot.below.size();
        script << "set terminal pngcairo size 900," << 600 + 300 * (n_panels - 1)
               << " enhanced font 'Sans,11'\n"
               << "set output " << quoted(plot.file + ".tmp") << "\n";
        if (n_panels > 1)
          script << "set multiplot layout " << n_panels << ",1\n";
        write_panel(script, plot);
        for (const Plot &panel : plot.below)
          write_panel(script, panel);
        script << (n_panels > 1 ? "unset multiplot\n" : "") << "unset output\n";
      }
    return script.str();
  }

  std::vector<std::string>
  draw_plots(const std::string &directory, const std::vector<Plot> &plots)
  {
    std::vector<std::string> written;
    if (plots.empty())
      return written;
    throw_if_interrupted(); // gnuplot can take seconds: a safe point before it
    if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
      {
        std::cerr << "poundfe: warning: gnuplot not found; no PNG plots written\n";
        for (const Plot &plot : plots)
          missing().push_back({plot.file, directory, "gnuplot not found"});
        return written;
      }
    const std::string script = plot_script(plots);
    // gnuplot writes these itself: listed first (output_directory.h)
    for (const Plot &plot : plots)
      register_output(directory + "/" + plot.file);
    register_output(directory + "/.plots.log");
    const std::string script_file = directory + "/.plots.gp";
    write_file_atomically(script_file, script);
    const std::string command =
      "cd " + quoted(directory) + " && gnuplot .plots.gp > .plots.log 2>&1";
    const int         status  = std::system(command.c_str());
    const std::string log     = directory + "/.plots.log";
    const std::string problem = status == 0 ? "" : stopping_signal(status).empty() ?
                                              first_error(log) :
                                              "stopped by " + stopping_signal(status) +
                                                " while drawing (the run was interrupted)";
    for (const Plot &plot : plots)
      {
        const std::string temporary = directory + "/" + plot.file + ".tmp";
        if (status == 0 && std::filesystem::exists(temporary))
          {
            std::filesystem::rename(temporary, directory + "/" + plot.file);
            written.push_back(plot.file);
          }
        else
          {
            std::remove(temporary.c_str());
            missing().push_back({plot.file, directory,
                                 status == 0 ? "gnuplot wrote no file" : "gnuplot: " + problem});
          }
      }
    if (status != 0)
      std::cerr << "poundfe: warning: gnuplot failed (" << problem << "); "
                << plots.size() - written.size() << " figure(s) not drawn\n";
    // helpers of gnuplot, not results (the reason is in the warning)
    std::remove(script_file.c_str());
    std::remove(log.c_str());
    return written;
  }
} // namespace poundfe
