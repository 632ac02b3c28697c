#include <poundfe/analysis/input_parameters.h>
#include <poundfe/base/exceptions.h>

#include <deal.II/base/parameter_handler.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace poundfe
{
  namespace
  {
    using dealii::ParameterHandler;

    std::string
    collapse_whitespace(const std::string &text)
    {
      std::string out;
      bool        space = false;
      for (const char c : text)
        if (std::isspace(static_cast<unsigned char>(c)))
          space = !out.empty();
        else
          {
            if (space)
              out += ' ';
            out += c;
            space = false;
          }
      return out;
    }

    /// deal.II's messages carry "Line <n> of file <f>": turn them into ours.
    [[noreturn]] void
    rethrow_parse_error(const std::string &file, const dealii::ExceptionBase &e)
    {
      std::ostringstream info;
      e.print_info(info);
      std::string text = collapse_whitespace(info.str());
      int         line = 0;
      std::smatch match;
      static const std::regex where("Line <([0-9]+)> of file <[^>]*>:? ?");
      if (std::regex_search(text, match, where))
        {
          line = std::stoi(match[1]);
          text = match.prefix().str() + match.suffix().str();
        }
      if (text.empty())
        text = collapse_whitespace(e.what());
      throw InputError(file, line, "", text);
    }

    void
    index_lines(InputFile &p)
    {
      std::ifstream            in(p.file);
      std::string              line;
      std::vector<std::string> sections;
      static const std::regex  subsection("^\\s*subsection\\s+(.*?)\\s*$");
      static const std::regex  end("^\\s*end\\s*$");
      static const std::regex  set("^\\s*set\\s+(.*?)\\s*=.*$");
      for (int number = 1; std::getline(in, line); ++number)
        {
          const auto hash = line.find('#');
          if (hash != std::string::npos)
            line.erase(hash);
          std::smatch m;
          if (std::regex_match(line, m, subsection))
            sections.push_back(m[1]);
          else if (std::regex_match(line, end) && !sections.empty())
            sections.pop_back();
          else if (std::regex_match(line, m, set))
            {
              std::string path;
              for (const auto &s : sections)
                path += s + "/";
              p.lines[path + m[1].str()] = number;
            }
        }
    }

    void
    parse(ParameterHandler &prm, const std::string &file, const bool skip_undefined)
    {
      try
        {
          prm.parse_input(file, "", skip_undefined);
        }
      catch (const dealii::ExceptionBase &e)
        {
          rethrow_parse_error(file, e);
        }
    }
  } // namespace

  void
  InputParameters::declare(ParameterHandler &prm)
  {
    model.declare(prm);
    ground_motion.declare(prm);
    prm.enter_subsection("Contact");
    contact.declare(prm);
    time_integration.declare_event_refinement(prm);
    prm.leave_subsection();
    prm.enter_subsection("Springs");
    springs.declare(prm);
    prm.leave_subsection();
    prm.enter_subsection("Friction");
    friction.declare(prm);
    prm.leave_subsection();
    nodal_forces.declare(prm);
    time_integration.declare(prm);
    output.declare(prm);
    monte_carlo.declare(prm);
    subset.declare(prm);
    fragility.declare(prm);
    stationary_pdf.declare(prm);
  }

  void
  InputParameters::finalize()
  {
    for (BuildingParameters &building : model.buildings)
      {
        building.hysteresis.theta          = time_integration.hysteresis_theta();
        building.hysteresis.tolerance      = time_integration.law_tolerance;
        building.hysteresis.max_iterations = time_integration.law_max_iterations;
      }
    output.finalize(*this);
    model.finalize(*this);
    ground_motion.check(*this, time_integration.newmark.time_step);
    time_integration.check(*this);
    contact.check(*this);
    friction.check(*this);
    monte_carlo.check(*this);
    subset.check(*this, model);
    fragility.check(*this);
    stationary_pdf.check(*this, time_integration.newmark.time_step);
  }

  InputParameters
  read_parameters(const std::string &file)
  {
    {
      std::ifstream in(file);
      if (!in)
        throw InputError(file, 0, "", "cannot open the parameter file");
    }
    const std::string extension = std::filesystem::path(file).extension().string();
    if (extension != ".prm" && extension != ".json")
      throw InputError(file, 0, "", "parameter files end in .prm or .json");

    InputParameters p;
    p.file      = file;
    p.directory = std::filesystem::path(file).parent_path().string();
    if (extension == ".prm")
      index_lines(p);

    // First pass: only the number of buildings, which shapes the declarations.
    unsigned int n_buildings = 1;
    {
      ParameterHandler prm;
      ModelParameters::declare_number_of_buildings(prm, n_buildings);
      parse(prm, file, true);
    }
    p.model.buildings.resize(n_buildings);
    ParameterHandler prm;
    p.declare(prm);
    parse(prm, file, false);
    p.finalize();
    return p;
  }

  void
  print_parameters(std::ostream &out)
  {
    InputParameters p;
    p.model.buildings.resize(1);
    ParameterHandler prm;
    p.declare(prm);
    out << "# poundfe parameters. 'Building 1' stands for every 'Building <i>',\n"
        << "# i = 1 .. Number of buildings. Lists are comma separated.\n";
    prm.print_parameters(out, ParameterHandler::PRM);
  }
} // namespace poundfe
