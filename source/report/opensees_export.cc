// A poundfe model described as an OpenSees 3.8 script (report/
// opensees_export.h says what each part becomes and why it is the same
// model). OpenSees's conventions: zeroLength's deformation is u_j - u_i
// along its direction (ZeroLength.cpp), ElasticPPGap's gap and yield force
// are negative for a gap that closes in compression (ElasticPPGap.cpp),
// uniaxialMaterial Elastic E eta's force is E e + eta de/dt
// (ElasticMaterial.cpp), UniformExcitation's load is -M r a_g.
#include <poundfe/base/exceptions.h>
#include <poundfe/report/opensees_export.h>

#include "opensees_export_parts.h"

#include <algorithm>
#include <sstream>

namespace poundfe
{
  std::string
  comment_word(const std::string &name)
  {
    if (name.find_first_of(" \t\"\\") == std::string::npos)
      return name;
    std::string quoted = "\"";
    for (const char c : name)
      quoted += (c == '"' || c == '\\' ? "\\" : "") + std::string(1, c);
    return quoted + "\"";
  }
} // namespace poundfe

namespace poundfe::opensees_export
{
  std::string
  exact_text(const double value)
  {
    std::ostringstream text;
    text.precision(17);
    text << value;
    return text.str();
  }

  std::string
  building_entry(const unsigned int b, const std::string &entry)
  {
    return "Building " + std::to_string(b + 1) + "/" + entry;
  }

  double
  node_mass(const Analysis &analysis, const unsigned int node, const Component c,
            const InputFile &input)
  {
    const int eq = analysis.model.equation(Model::dof(node, c));
    if (eq < 0)
      return 0;
    double diagonal = 0;
    for (SparseMatrix::InnerIterator it(analysis.system.mass, eq); it; ++it)
      if (it.row() == eq)
        diagonal = it.value();
      else if (it.value() != 0)
        input.fail("Model/Mass matrix", "export-opensees writes lumped masses only");
    return diagonal;
  }

  void
  add_fixed_node(const int tag, const std::string &position, const std::string &what,
                 OpenSeesExport &out)
  {
    out.model.push_back("node " + std::to_string(tag) + " " + position);
    std::string fixity = "fix " + std::to_string(tag);
    for (unsigned int c = 0; c < out.ndf; ++c)
      fixity += " 1";
    out.model.push_back(fixity + (what.empty() ? "" : " ;# " + what));
  }

  void
  describe_mass_dashpots(const Analysis &analysis, const unsigned int n,
                         const std::vector<std::pair<unsigned int, double>> &masses,
                         const std::string &position, Tags &tags, OpenSeesExport &out)
  {
    const double a0 = analysis.system.rayleigh.at(analysis.model.nodes[n].building)[0];
    std::string  materials, directions;
    for (const auto &[direction, mass] : masses)
      if (a0 != 0 && mass != 0)
        {
          out.model.push_back("uniaxialMaterial Elastic " + std::to_string(tags.material) +
                              " 0.0 " + exact_text(a0 * mass) + " ;# a0 m of the Rayleigh damping");
          materials += " " + std::to_string(tags.material++);
          directions += " " + std::to_string(direction);
        }
    if (materials.empty())
      return;
    const int ground = ++tags.node;
    add_fixed_node(ground, position, "", out);
    out.model.push_back("element zeroLength " + std::to_string(tags.element++) + " " +
                        std::to_string(ground) + " " + std::to_string(n + 1) + " -mat" +
                        materials + " -dir" + directions);
  }
} // namespace poundfe::opensees_export

namespace poundfe
{
  namespace
  {
    using namespace opensees_export;

    /// The contact laws whose equations OpenSees 3.8's gap materials have:
    /// linear (ElasticPPGap), hertz (Hertzdamp without damping), jankowski
    /// (JankowskiImpact: the same force in approach and restitution, never
    /// negative, so poundfe's clipping at zero never acts). The others differ
    /// from their OpenSees namesakes: InputError naming Contact/Law.
    void
    refuse_contact_law(const std::string &law, const InputFile &input)
    {
      if (law == "linear" || law == "hertz" || law == "jankowski")
        return;
      std::string why = "OpenSees 3.8 has no material with its equations";
      if (law == "hertz-damp")
        why = "OpenSees's Hertzdamp takes the approach velocity from the first trial in "
              "contact, poundfe from the committed state before it, and lets the force "
              "turn negative during restitution, which poundfe clips at zero";
      else if (law == "kelvin-voigt")
        why = "OpenSees's ViscoelasticGap lets the force k d + c d' turn negative during "
              "restitution, which poundfe clips at zero";
      input.fail("Contact/Law", "export-opensees writes the contact laws linear, hertz and "
                                "jankowski; '" + law + "' not: " + why);
    }

    /// The parts of the model OpenSees cannot be given the same way:
    /// InputError naming the first one's entry.
    void
    refuse_model_parts(const Analysis &analysis, const InputFile &input)
    {
      const Model &model = analysis.model;
      if (model.dimension == 3)
        refuse_3d_parts(analysis, input);
      if (model.geometric_nonlinearity != GeometricNonlinearity::none)
        input.fail("Model/Geometric nonlinearity",
                   "export-opensees writes no P-Delta: poundfe's is the geometric stiffness "
                   "of the gravity state's axial forces, held constant, OpenSees's PDelta "
                   "transformation that of each step's axial force");
      refuse_frame_parts(analysis, input);
      for (unsigned int b = 0; b < model.buildings.size(); ++b)
        {
          if (model.buildings[b].damping.is_modal())
            input.fail(building_entry(b, "Damping/Type"),
                       "modal damping has no element form in OpenSees 3.8's Tcl commands "
                       "that poundfe's export writes (Rayleigh damping: modes or coefficients)");
        }
      if (!model.springs.empty() || !model.friction_surfaces.empty())
        input.fail(model.springs.empty() ? "Friction" : "Springs",
                   "export-opensees writes no springs to the ground or friction");
      if (!model.building_links.empty())
        input.fail("Links", "export-opensees writes no links between buildings");
      if (!model.foundations.empty() || !model.constraints.empty())
        input.fail(building_entry(model.foundations.empty() ? 0 : model.foundations[0].building,
                                  "Foundation/Type"),
                   "export-opensees writes fixed bases only");
      if (model.bumper.law != BumperLaw::none)
        input.fail("Contact/Bumper/Law", "export-opensees writes bare gaps only");
      if (!model.gaps.empty())
        refuse_contact_law(model.contact.law, input);
    }

    /// The excitation and the integration OpenSees cannot be given.
    void
    refuse_excitation(const TimeHistoryParameters &parameters, const Excitation &excitation)
    {
      const InputFile &input = parameters.input;
      if (parameters.time_integration.method != TimeIntegrationMethod::newmark)
        input.fail("Time integration/Method", "export-opensees writes Newmark only");
      // a 3D model's pair: its second component none and no rotation
      if ((excitation.has_horizontal_pair() && excitation.applied_horizontal_peaks()[1] != 0) ||
          excitation.has_vertical())
        input.fail("Ground motion/Components",
                   "export-opensees writes one horizontal component, along x (in 3D: "
                   "Components = 1 and Incidence angle = 0)");
      if (!excitation.nodal_forces().empty())
        input.fail("Nodal forces/File", "export-opensees writes no nodal forces");
      if (const double a0 = excitation.ground_acceleration(0); a0 != 0)
        input.fail("Ground motion/Type",
                   "the ground motion starts at a_g(0) = " + exact_text(a0) +
                     " m/s^2: OpenSees's Newmark starts from a zero acceleration, poundfe's "
                     "from M a(0) = p(0), so the runs would differ");
      const InitialConditionParameters &initial = parameters.initial_conditions;
      if (!initial.floor_displacements.empty() || !initial.floor_velocities.empty() ||
          !initial.equation_displacements.empty() || !initial.equation_velocities.empty() ||
          !initial.state.empty())
        input.fail("Initial conditions/Floor displacements",
                   "export-opensees starts from rest only");
    }

    /// "x [y]" of `position` in the script's space.
    std::string
    position_text(const Point2 &position, const OpenSeesExport &out)
    {
      return exact_text(position.x) +
             (out.ndm == 2 ? " " + exact_text(position.y) : std::string());
    }

    std::string
    node_line(const int tag, const Point2 &position, const OpenSeesExport &out)
    {
      return "node " + std::to_string(tag) + " " + position_text(position, out);
    }

    /// The a0 M term of node n with `masses` on its DOFs (the rotation, the
    /// third, a zeroLength's direction 6).
    void
    describe_mass_dashpots(const Analysis &analysis, const unsigned int n,
                           const std::vector<double> &masses, Tags &tags, OpenSeesExport &out)
    {
      std::vector<std::pair<unsigned int, double>> on_directions;
      for (unsigned int c = 0; c < masses.size(); ++c)
        on_directions.emplace_back(c == 2 ? 6 : c + 1, masses[c]);
      describe_mass_dashpots(analysis, n, on_directions,
                             position_text(analysis.model.nodes[n].position, out), tags, out);
    }

    /// Each building's nodes (with masses and fixities) and the dashpots of
    /// its a0 M term to fixed nodes of their own.
    void
    describe_nodes(const Analysis &analysis, const InputFile &input, Tags &tags,
                   OpenSeesExport &out)
    {
      const Model     &model = analysis.model;
      std::vector<int> owner(model.n_equations(), -1); // the first node of each equation
      for (unsigned int n = 0; n < model.n_nodes(); ++n)
        {
          const Node &node = model.nodes[n];
          for (unsigned int c = out.ndf; c < n_dofs_per_node; ++c)
            if (model.equation(Model::dof(n, Component(c))) >= 0)
              input.fail(building_entry(node.building, "Type"),
                         "a shear building's node moves in uy or rz");
          std::vector<double> masses(out.ndf);
          std::string         mass_text, fixity, tied;
          int                 tied_to = -1;
          for (unsigned int c = 0; c < out.ndf; ++c)
            {
              const int eq = model.equation(Model::dof(n, Component(c)));
              if (eq >= 0 && owner[eq] >= 0) // a hinge's node: the joint's translation
                {
                  tied_to = owner[eq];
                  tied += " " + std::to_string(c + 1);
                }
              else if (eq >= 0)
                owner[eq] = n, masses[c] = node_mass(analysis, n, Component(c), input);
              mass_text += " " + exact_text(masses[c]);
              fixity += eq < 0 ? " 1" : " 0";
            }
          const bool has_mass = std::any_of(masses.begin(), masses.end(),
                                            [](const double m) { return m != 0; });
          out.model.push_back(node_line(n + 1, node.position, out) +
                              (has_mass ? " -mass" + mass_text : std::string()));
          if (fixity.find('1') != std::string::npos)
            out.model.push_back("fix " + std::to_string(n + 1) + fixity);
          if (tied_to >= 0)
            out.model.push_back("equalDOF " + std::to_string(tied_to + 1) + " " +
                                std::to_string(n + 1) + tied);
          out.tied = out.tied || tied_to >= 0;
          describe_mass_dashpots(analysis, n, masses, tags, out);
        }
    }

    /// The storeys: elastic springs with the a1 K and storey dashpots, and
    /// the floors to record.
    void
    describe_storeys(const Analysis &analysis, Tags &tags, OpenSeesExport &out)
    {
      const Model &model = analysis.model;
      if (!model.links.empty())
        out.model.push_back("# storeys: zeroLength on Elastic k eta, eta = a1 k + the storey's "
                            "dashpot");
      if (std::any_of(model.links.begin(), model.links.end(),
                      [](const StoreyLink &link) { return link.hysteretic; }))
        out.model.push_back("# a Bouc-Wen storey: a zeroLength on " + bouc_wen_comment() +
                            "; beside it a zeroLength on Elastic 0 eta");
      for (const StoreyLink &link : model.links)
        {
          const double      a1  = analysis.system.rayleigh.at(link.building)[1];
          const double      eta = a1 * link.stiffness + link.damping;
          const std::string ends =
            std::to_string(link.nodes[0] + 1) + " " + std::to_string(link.nodes[1] + 1);
          if (link.hysteretic)
            {
              const std::string label =
                comment_word(model.buildings[link.building].name) + " storey";
              out.model.push_back(bouc_wen_material(link.hysteresis, tags.material, label));
              out.model.push_back("element zeroLength " + std::to_string(tags.element++) + " " +
                                  ends + " -mat " + std::to_string(tags.material++) + " -dir 1");
              out.nonlinear = true;
            }
          out.model.push_back("uniaxialMaterial Elastic " + std::to_string(tags.material) + " " +
                              (link.hysteretic ? "0.0" : exact_text(link.stiffness)) + " " +
                              exact_text(eta));
          out.model.push_back("element zeroLength " + std::to_string(tags.element++) + " " + ends +
                              " -mat " + std::to_string(tags.material++) + " -dir 1");
        }
      for (const Building &building : model.buildings)
        for (unsigned int f = 0; f < building.floors.size(); ++f) // floor 1 up
          for (const unsigned int n : building.floors[f].nodes)
            {
              out.floor_nodes.push_back(n + 1);
              out.floor_names.push_back(building.name + "_floor" + std::to_string(f + 1) +
                                        "_disp_m");
            }
    }

    std::string
    gap_comment(const std::string &law)
    {
      if (law == "hertz")
        return "# gaps: the Hertz contact law F = k_h d^1.5 as Hertzdamp k_h 0 -gap 1.5";
      if (law == "jankowski")
        return "# gaps: Jankowski's law F = k_h d^1.5 + 2 xi sqrt(k_h d^0.5 m_e) d' (approach) "
               "as JankowskiImpact k_h xi m_e -gap 1.5";
      return "# gaps: the linear contact law F = k d as ElasticPPGap k Fy -gap, "
             "Fy beyond any impact's force";
    }

    /// The OpenSees material of a gap under the (accepted) contact law.
    std::string
    gap_material(const ContactLawParameters &law, const Gap &)
    {
      return law.law == "hertz" ? "Hertzdamp" :
             law.law == "jankowski" ? "JankowskiImpact" : "ElasticPPGap";
    }

    /// Its values after the tag, in OpenSees's order: the gap negative (a
    /// closure is a negative deformation u_j - u_i).
    std::string
    gap_material_values(const ContactLawParameters &law, const Gap &gap)
    {
      const double k = law.stiffness;
      const std::string gap_value = exact_text(-gap.initial_gap);
      if (law.law == "hertz")
        return exact_text(k) + " 0.0 " + gap_value + " 1.5";
      if (law.law == "jankowski")
        return exact_text(k) + " " + exact_text(law.damping) + " " +
               exact_text(gap.effective_mass) + " " + gap_value + " 1.5";
      return exact_text(k) + " " + exact_text(-1e6 * k) + " " + gap_value;
    }

    /// The gaps: zeroLength on a gap material from the left node to the right
    /// one, a fixed node standing for a barrier.
    void
    describe_gaps(const Analysis &analysis, Tags &tags, OpenSeesExport &out)
    {
      const Model &model = analysis.model;
      if (model.gaps.empty())
        return;
      out.model.push_back(gap_comment(model.contact.law));
      for (unsigned int g = 0; g < model.gaps.size(); ++g)
        {
          const Gap  &gap = model.gaps[g];
          std::string ends[2];
          for (unsigned int side = 0; side < 2; ++side)
            if (gap.nodes[side] >= 0)
              ends[side] = std::to_string(gap.nodes[side] + 1);
            else
              {
                const int barrier = ++tags.node;
                add_fixed_node(barrier, position_text(Point2{0.0, gap.level}, out),
                               "the barrier", out);
                ends[side] = std::to_string(barrier);
              }
          out.model.push_back("uniaxialMaterial " + gap_material(model.contact, gap) + " " +
                              std::to_string(tags.material) + " " +
                              gap_material_values(model.contact, gap) + " ;# " +
                              comment_word(gap.label));
          out.gap_elements.push_back(tags.element);
          out.gap_names.push_back(gap.label.empty() ? "gap" + std::to_string(g + 1) : gap.label);
          out.model.push_back("element zeroLength " + std::to_string(tags.element++) + " " +
                              ends[0] + " " + ends[1] + " -mat " +
                              std::to_string(tags.material++) + " -dir 1");
        }
      out.nonlinear = true;
      if (model.contact.law != "linear")
        out.test_iterations = 500; // OpenSees's tangent of the wrong sign (header)
    }
  } // namespace

  OpenSeesExport
  describe_opensees(const Analysis &analysis, const TimeHistoryParameters &parameters,
                    const Excitation &excitation)
  {
    refuse_model_parts(analysis, parameters.input);
    refuse_excitation(parameters, excitation);
    OpenSeesExport out;
    Tags           tags;
    tags.node = analysis.model.n_nodes();
    if (analysis.model.dimension == 3)
      out.ndm = 3, out.ndf = 6;
    else if (in_plane(analysis.model))
      out.ndm = 2, out.ndf = 3;
    if (out.ndm < 3)
      out.model.push_back(out.ndf == 1 ? "# nodes: a floor's ux with its mass; the base and the "
                                         "damping's ground nodes fixed" :
                                         "# nodes (x, y): M's masses on ux, uy, rz; the "
                                         "supports and the damping's ground nodes fixed");
    if (out.ndm == 3)
      describe_frames_3d(analysis, parameters.input, tags, out);
    else
      {
        describe_nodes(analysis, parameters.input, tags, out);
        describe_storeys(analysis, tags, out);
        describe_members(analysis, parameters.input, tags, out);
        describe_hinges(analysis, tags, out);
      }
    frames_stiffness_damping(analysis, tags, out);
    describe_gravity(analysis, out);
    describe_gaps(analysis, tags, out);
    const NewmarkParameters &newmark = parameters.time_integration.newmark;
    out.time_step                    = newmark.time_step;
    out.gamma                        = newmark.gamma;
    out.beta                         = newmark.beta;
    out.n_steps                      = n_steps_of(parameters, excitation);
    // one sample past the end: OpenSees's time after n steps, summed step by
    // step, may pass n dt by round-off, where a Path of n + 1 values gives 0
    out.ground_acceleration.resize(out.n_steps + 2);
    for (unsigned long i = 0; i <= out.n_steps + 1; ++i)
      out.ground_acceleration[i] = excitation.ground_acceleration(i * out.time_step);
    return out;
  }
} // namespace poundfe
