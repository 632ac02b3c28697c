// Section shorthands of a generated frame (model/section_shorthands.h):
// solid rectangles and circles, A = b h, I = b h^3 / 12, Iz = h b^3 / 12 and
// the Saint-Venant torsion constant of a rectangle by its series
// (Timoshenko & Goodier 1970, §109), so that a first model needs no hand
// computation; G from a Poisson ratio, G = E / (2 (1 + nu)).
#include <poundfe/base/numbers.h>
#include <poundfe/model/parameters.h>
#include <poundfe/model/section_shorthands.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace poundfe
{
  double
  rectangle_torsion_constant(const double a, const double b)
  {
    const double longer = std::max(a, b), shorter = std::min(a, b);
    // the terms fall as 1/n^5: 500 odd terms leave < 1e-13 of the sum
    double sum = 0;
    for (unsigned int n = 1; n < 1000; n += 2)
      sum += std::tanh(n * M_PI * longer / (2 * shorter)) / std::pow(double(n), 5);
    return longer * std::pow(shorter, 3) *
           (1.0 / 3 - 64 / std::pow(M_PI, 5) * shorter / longer * sum);
  }

  SolidSection
  rectangle_section(const double b, const double h)
  {
    return {b * h, b * h * h * h / 12, h * b * b * b / 12, rectangle_torsion_constant(b, h)};
  }

  SolidSection
  circle_section(const double diameter)
  {
    const double d4 = std::pow(diameter, 4);
    return {M_PI * diameter * diameter / 4, M_PI * d4 / 64, M_PI * d4 / 64, M_PI * d4 / 32};
  }

  std::optional<SolidSection>
  parse_solid_section(const std::string &text)
  {
    std::istringstream words(text);
    std::string        shape, rest;
    double             first = 0, second = 0;
    words >> shape;
    const bool rectangle = shape == "rectangle";
    if ((!rectangle && shape != "circle") || !read_number(words, first) ||
        (rectangle && !read_number(words, second)) || (words >> rest))
      return std::nullopt;
    for (const double length : {first, rectangle ? second : first})
      if (!(length > 0 && length <= largest_building_length))
        return std::nullopt;
    return rectangle ? rectangle_section(first, second) : circle_section(first);
  }

  namespace
  {
    /// The items of a ';'-separated list, trimmed, empty ones dropped.
    std::vector<std::string>
    list_items(const std::string &text)
    {
      std::vector<std::string> items;
      std::istringstream       in(text);
      for (std::string item; std::getline(in, item, ';');)
        if (!trimmed(item).empty())
          items.push_back(trimmed(item));
      return items;
    }

    /// One shorthand entry (columns or beams) into its four lists.
    void
    expand_shorthand(const InputFile &input, const std::string &s, const std::string &member,
                     const std::string &text, const unsigned int n_storeys,
                     const std::array<std::vector<double> *, 4> &lists)
    {
      const std::vector<std::string> texts = list_items(text);
      if (texts.empty())
        return;
      const std::string path = s + member + " section";
      if (texts.size() != 1 && texts.size() != n_storeys)
        input.fail(path, "needs 1 section or " + std::to_string(n_storeys) + " (one per " +
                           (member == "Column" ? "storey" : "floor") + ", ';' between), got " +
                           std::to_string(texts.size()));
      for (const char *entry : {" A", " I", " Iz", " J"})
        if (input.lines.count(s + member + entry) > 0)
          input.fail(s + member + entry, "is given by " + member + " section as well: give "
                                         "one of them");
      for (std::vector<double> *list : lists)
        list->clear();
      for (const std::string &item : texts)
        {
          const std::optional<SolidSection> section = parse_solid_section(item);
          if (!section)
            input.fail(path, "'" + item + "' is not 'rectangle b h' or 'circle D' (positive "
                             "lengths in m, at most 10 km)");
          const std::array<double, 4> values{{section->area, section->second_moment,
                                              section->second_moment_z,
                                              section->torsion_constant}};
          for (unsigned int k = 0; k < 4; ++k)
            lists[k]->push_back(values[k]);
        }
    }
  } // namespace

  void
  expand_section_shorthands(const InputFile &input, const std::string &s,
                            const std::string &column_text, const std::string &beam_text,
                            BuildingParameters &b)
  {
    expand_shorthand(input, s, "Column", column_text, b.n_storeys,
                     {{&b.column_area, &b.column_second_moment, &b.column_second_moment_z,
                       &b.column_torsion_constant}});
    expand_shorthand(input, s, "Beam", beam_text, b.n_storeys,
                     {{&b.beam_area, &b.beam_second_moment, &b.beam_second_moment_z,
                       &b.beam_torsion_constant}});
  }

  void
  shear_moduli_from_poisson_ratio(const InputFile &input, const std::string &s,
                                  const std::string &text, BuildingParameters &b)
  {
    if (trimmed(text).empty())
      return;
    const std::string  path = s + "Poisson ratio";
    std::istringstream words(text);
    double             nu = 0;
    std::string        rest;
    if (!read_number(words, nu) || (words >> rest))
      input.fail(path, "'" + trimmed(text) + "' is not a number");
    if (!(nu > -1 && nu <= 0.5))
      input.fail(path, "must lie in (-1, 0.5] (G = E / (2 (1 + nu)) > 0), got " + number_text(nu));
    for (const char *member : {"Column G", "Beam G"})
      if (input.lines.count(s + member) > 0)
        input.fail(s + member, "is given by Poisson ratio as well: give one of them");
    const auto moduli = [nu](const std::vector<double> &youngs_moduli) {
      std::vector<double> g;
      for (const double e : youngs_moduli)
        g.push_back(e / (2 * (1 + nu)));
      return g;
    };
    b.column_shear_modulus = moduli(b.column_youngs_modulus);
    b.beam_shear_modulus   = moduli(b.beam_youngs_modulus);
  }

  void
  declare_section_shorthands(dealii::ParameterHandler &prm)
  {
    prm.declare_entry("Column section", "", dealii::Patterns::Anything(),
                      "[frame] Instead of Column A, I (3D: and Iz, J): 'rectangle b h' (h "
                      "the side along x with Column angle 0, the depth Column I bends; b "
                      "across) or 'circle D', one for all or one per storey separated by ';'. "
                      "A = b h, I = b h^3/12, Iz = h b^3/12, J the Saint-Venant constant of "
                      "the rectangle (series; 0.1406 a^4 for a square); circle: pi D^2/4, "
                      "pi D^4/64, pi D^4/32. Empty: the entries as given. Unit: m.");
    prm.declare_entry("Beam section", "", dealii::Patterns::Anything(),
                      "[frame] Instead of Beam A, I (3D: and Iz, J): 'rectangle b h' (b the "
                      "width, h the depth, vertical) or 'circle D', one for all or one per "
                      "floor separated by ';' (as Column section). Unit: m.");
  }

  void
  declare_poisson_ratio(dealii::ParameterHandler &prm)
  {
    prm.declare_entry("Poisson ratio", "", dealii::Patterns::Anything(),
                      "[3D frame] nu of the members' material: Column G = Column E / (2 (1 + "
                      "nu)) and Beam G = Beam E / (2 (1 + nu)), storey by storey (0.2 for "
                      "concrete, 0.3 for steel), instead of Column G and Beam G; empty: "
                      "those as given. Unit: dimensionless.");
  }

  void
  apply_section_shorthands(const InputFile                                        &input,
                           const std::vector<std::pair<std::string, std::string>> &values,
                           ModelParameters                                        &model)
  {
    const auto value = [&](const std::string &path) {
      for (const auto &[entry, text] : values)
        if (entry == path)
          return text;
      return std::string();
    };
    for (unsigned int i = 0; i < model.buildings.size(); ++i)
      {
        BuildingParameters &b = model.buildings[i];
        const std::string   s = "Building " + std::to_string(i + 1) + "/";
        if (b.type != BuildingType::frame)
          continue; // refused by ModelParameters::finalize when written
        expand_section_shorthands(input, s, value(s + "Column section"), value(s + "Beam section"),
                                  b);
        if (model.dimension == 3)
          shear_moduli_from_poisson_ratio(input, s, value(s + "Poisson ratio"), b);
      }
  }
} // namespace poundfe
