// Placing the `Links` section's links between floor nodes and the
// `Bumpers` section's bumper in the gaps (laws: laws/link_laws.h,
// laws/bumper.h; doc/theory.md §1.14, §4.9).
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/model/model_builder.h>

#include <cmath>
#include <sstream>

namespace poundfe
{
  namespace
  {
    /// The law's numbers after the two nodes: its fields by kind.
    struct LinkForm
    {
      LinkKind                 kind;
      const char              *path;
      std::vector<const char *> fields;
    };

    const std::vector<LinkForm> &
    link_forms()
    {
      static const std::vector<LinkForm> forms{
        {LinkKind::viscous, "Links/Viscous dampers", {"c", "alpha"}},
        {LinkKind::kelvin_voigt, "Links/Kelvin-Voigt links", {"k", "c", "alpha"}},
        {LinkKind::maxwell, "Links/Maxwell links", {"k", "c"}},
        {LinkKind::elastic_plastic, "Links/Elastic-plastic links", {"k", "Fy", "r"}}};
      return forms;
    }

    /// The law from its numbers (in the order of `form.fields`); the
    /// problem with them, or empty.
    std::string
    set_link_law(const LinkForm &form, const std::vector<double> &x, LinkLawParameters &law)
    {
      law.kind = form.kind;
      for (const double value : x)
        if (!(std::abs(value) <= largest_model_value))
          return "every number must be finite and at most 1e150 in size, got " +
                 number_text(value) + " (beyond any physical link)";
      switch (form.kind)
        {
          case LinkKind::viscous:
            law.damping  = x[0];
            law.exponent = x[1];
            break;
          case LinkKind::kelvin_voigt:
            law.stiffness = x[0];
            law.damping   = x[1];
            law.exponent  = x[2];
            break;
          case LinkKind::maxwell:
            law.stiffness = x[0];
            law.damping   = x[1];
            if (!(law.stiffness > 0 && law.damping > 0))
              return "k and c must be positive";
            return {};
          case LinkKind::elastic_plastic:
            law.stiffness   = x[0];
            law.yield_force = x[1];
            law.hardening   = x[2];
            if (!(law.stiffness > 0 && law.yield_force > 0))
              return "k and Fy must be positive";
            if (!(law.hardening >= 0 && law.hardening < 1))
              return "r must lie in [0, 1), got " + number_text(law.hardening);
            return {};
        }
      if (!(law.damping > 0) || law.stiffness < 0)
        return "c must be positive and k zero or positive";
      if (!(law.exponent > 0 && law.exponent <= 1))
        return "alpha must lie in (0, 1], got " + number_text(law.exponent);
      return {};
    }

    BuildingLink
    read_link(const InputFile &input, const Model &model, const LinkForm &form,
              const std::string &entry, const double regularization_velocity)
    {
      std::string shape = "building floor node building floor node";
      for (const char *f : form.fields)
        shape += std::string(" ") + f;
      std::istringstream fields(entry);
      const FloorNode    a = read_floor_node(input, model, fields, form.path, entry, shape);
      const FloorNode    b = read_floor_node(input, model, fields, form.path, entry, shape);
      std::vector<double> x(form.fields.size());
      std::string         rest;
      for (double &value : x)
        read_number(fields, value);
      if (!fields || (fields >> rest))
        throw InputError(input.file, input.line_of(form.path), form.path,
                         "'" + entry + "': expected '" + shape + "'");
      if (a.node == b.node)
        throw InputError(input.file, input.line_of(form.path), form.path,
                         "'" + entry + "': a link needs two different nodes");
      for (const FloorNode &at : {a, b})
        if (model.equation(Model::dof(at.node, Component::ux)) < 0)
          throw InputError(input.file, input.line_of(form.path), form.path,
                           "'" + entry + "': the ux of " + at.label + " is fixed");
      BuildingLink link;
      link.law.regularization_velocity = regularization_velocity;
      const std::string problem        = set_link_law(form, x, link.law);
      if (!problem.empty())
        throw InputError(input.file, input.line_of(form.path), form.path,
                         "'" + entry + "': " + problem);
      link.nodes     = {{a.node, b.node}};
      link.buildings = {{a.building, b.building}};
      auto place     = [&](const FloorNode &at) {
        return model.buildings[at.building].name + "_F" + std::to_string(at.floor) + "." +
               std::to_string(at.index);
      };
      link.label = place(a) + "-" + place(b) + "_" + link_kind_name(form.kind);
      link.entry = form.path;
      return link;
    }

    /// The foundation of building b, or an InputError naming the entry.
    const Foundation &
    foundation_of(const InputFile &input, const Model &model, const unsigned int b,
                  const std::string &path, const std::string &entry)
    {
      for (const Foundation &f : model.foundations)
        if (f.building == b)
          return f;
      throw InputError(input.file, input.line_of(path), path,
                       "'" + entry + "': building '" + model.buildings[b].name +
                         "' stands on a fixed base: soil coupling joins two compliant "
                         "foundations (Building <i>/Foundation)");
    }

    /// The DOF of foundation f a soil coupling acts on: its sway along x, or
    /// (`rocking`) its rotation in the x-z plane (2D: the base node's rz,
    /// 3D: θ_y, slot 2 of the rocking node).
    unsigned int
    coupled_node(const Foundation &f, const bool rocking)
    {
      return rocking && f.rocking_node >= 0 ? unsigned(f.rocking_node) : f.node;
    }

    /// 'building building k c': a Kelvin-Voigt link (alpha = 1; k, c >= 0)
    /// between the two foundations' sway DOFs or (`rocking`) their rocking
    /// DOFs (doc/theory.md §1.16).
    BuildingLink
    read_soil_coupling(const InputFile &input, const Model &model, const std::string &entry,
                       const bool rocking)
    {
      const std::string  path = rocking ? "Links/Rocking soil coupling" : "Links/Soil coupling";
      std::istringstream fields(entry);
      std::string        first, second, rest;
      double             k = 0, c = 0;
      fields >> first >> second;
      if (!read_number(read_number(fields, k), c) || (fields >> rest))
        throw InputError(input.file, input.line_of(path), path,
                         "'" + entry + "': expected 'building building k c'");
      const unsigned int a = read_building(input, model, first, path, entry);
      const unsigned int b = read_building(input, model, second, path, entry);
      if (a == b)
        throw InputError(input.file, input.line_of(path), path,
                         "'" + entry + "': soil coupling joins two different buildings");
      if (!(k >= 0 && c >= 0) || !std::isfinite(k) || !std::isfinite(c))
        throw InputError(input.file, input.line_of(path), path,
                         "'" + entry + "': k and c must be zero or positive");
      if (!(k <= largest_model_value && c <= largest_model_value))
        throw InputError(input.file, input.line_of(path), path,
                         "'" + entry + "': k and c must be at most 1e150 (beyond any soil)");
      BuildingLink link;
      link.law.kind      = LinkKind::kelvin_voigt;
      link.law.stiffness = k;
      link.law.damping   = c;
      link.law.exponent  = 1;
      link.nodes     = {{coupled_node(foundation_of(input, model, a, path, entry), rocking),
                         coupled_node(foundation_of(input, model, b, path, entry), rocking)}};
      link.component = rocking ? Component::rz : Component::ux;
      link.buildings = {{a, b}};
      link.label     = std::string(rocking ? "soil_rocking_" : "soil_") +
                   model.buildings[a].name + "-" + model.buildings[b].name;
      link.entry     = path;
      return link;
    }
  } // namespace

  void
  add_building_links(Model &model, const LinkParameters &links, const InputFile &input)
  {
    const std::vector<std::string> *entries[] = {&links.viscous, &links.kelvin_voigt,
                                                 &links.maxwell, &links.elastic_plastic};
    for (unsigned int i = 0; i < link_forms().size(); ++i)
      for (const std::string &entry : *entries[i])
        if (entry.find_first_not_of(" \t") != std::string::npos)
          model.building_links.push_back(
            read_link(input, model, link_forms()[i], entry, links.regularization_velocity));
    for (const bool rocking : {false, true})
      for (const std::string &entry : rocking ? links.rocking_soil_coupling : links.soil_coupling)
        if (entry.find_first_not_of(" \t") != std::string::npos)
          model.building_links.push_back(read_soil_coupling(input, model, entry, rocking));
  }

  void
  add_bumpers(Model &model, const BumperParameters &bumper, const InputFile &input)
  {
    model.bumper = bumper;
    if (bumper.law == BumperLaw::none)
      return;
    if (model.dimension == 3)
      input.fail("Bumpers/Law", "bumpers are for the gaps of 2D models (Model/Dimension = 2)");
    for (const Gap &gap : model.gaps)
      if (bumper.thickness > gap.initial_gap)
        input.fail("Bumpers/Thickness", "the bumper (" + number_text(bumper.thickness) +
                                          " m) is thicker than the gap " + gap.label + " (" +
                                          number_text(gap.initial_gap) + " m)");
  }
} // namespace poundfe
