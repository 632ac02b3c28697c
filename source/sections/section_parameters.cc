// The Sections and Moment curvature sections of a parameter file (see the
// header): declarations, the Materials list's reader, and each section
// built once when the file is read so that bad geometry is an InputError
// naming its entry before anything is written.
#include <poundfe/base/choices.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/sections/fibre_generators.h>
#include <poundfe/sections/section_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>
#include <sstream>
#include <utility>

namespace poundfe
{
  namespace Patterns = dealii::Patterns;

  namespace
  {
    void
    declare_section_geometry(dealii::ParameterHandler &prm, SectionEntry &s)
    {
      prm.add_parameter("Depth", s.depth, "[RC rectangle, steel I] Depth h along the section's y "
                        "axis (bending about z strains it). Unit: m.", Patterns::Double());
      prm.add_parameter("Width", s.width, "[RC rectangle] Width b along z. Unit: m.",
                        Patterns::Double());
      prm.add_parameter("Diameter", s.diameter, "[RC circle] Outer diameter. Unit: m.",
                        Patterns::Double());
      prm.add_parameter("Cover", s.cover, "[RC] From the concrete face to the centreline of the "
                        "stirrups or spiral (the edge of Mander's confined core). Unit: m.",
                        Patterns::Double());
      prm.add_parameter("Bars top", s.bars_top, "[RC rectangle] Bars along the +y face, corners "
                        "included. Unit: count.", Patterns::Integer(0, 1000));
      prm.add_parameter("Bars bottom", s.bars_bottom, "[RC rectangle] Bars along the -y face, "
                        "corners included. Unit: count.", Patterns::Integer(0, 1000));
      prm.add_parameter("Bars per side", s.bars_side, "[RC rectangle] Bars on each z face between "
                        "the corners: 0 (bars on the top and bottom faces only, a beam's usual "
                        "layout) or more, as many as fit between the corner bars without "
                        "overlapping. Unit: count.", Patterns::Integer(0, 1000));
      prm.add_parameter("Bars", s.bars, "[RC circle] Bars evenly round the circle, the first on "
                        "+y. Unit: count.", Patterns::Integer(0, 1000));
      prm.add_parameter("Bar diameter", s.bar_diameter, "[RC] Longitudinal bars. Unit: m.",
                        Patterns::Double());
      prm.add_parameter("Stirrup diameter", s.stirrup_diameter, "[RC] Stirrups, hoops or spiral. "
                        "Unit: m.", Patterns::Double());
      prm.add_parameter("Stirrup spacing", s.stirrup_spacing, "[RC] Centre to centre (the pitch "
                        "of a spiral). Unit: m.", Patterns::Double());
      prm.add_parameter("Stirrup legs along y", s.legs_y, "[RC rectangle] Legs running along y "
                        "(confining along y). Unit: count.", Patterns::Integer(0, 100));
      prm.add_parameter("Stirrup legs along z", s.legs_z, "[RC rectangle] Legs running along z. "
                        "Unit: count.", Patterns::Integer(0, 100));
      add_choice(prm, "Transverse", s.spiral ? "spiral" : "hoops", "[RC circle] Unit: -.",
                 {"spiral", "hoops"}, [&s](const std::string &v) { s.spiral = v == "spiral"; });
      prm.add_parameter("Flange width", s.flange_width, "[steel I] Unit: m.", Patterns::Double());
      prm.add_parameter("Flange thickness", s.flange_thickness, "[steel I] Unit: m.",
                        Patterns::Double());
      prm.add_parameter("Web thickness", s.web_thickness, "[steel I] Unit: m.", Patterns::Double());
    }

    void
    declare_section_materials(dealii::ParameterHandler &prm, SectionEntry &s)
    {
      add_choice(prm, "Concrete law", s.concrete.law, "[RC] Unit: -.", {"Concrete02", "Concrete01"});
      prm.add_parameter("Concrete strength", s.concrete.fc, "[RC] Unconfined compressive strength "
                        "f'c (positive). Unit: Pa.", Patterns::Double());
      prm.add_parameter("Peak strain", s.concrete.eps_c0, "[RC] Strain at f'c (positive). Unit: -.",
                        Patterns::Double());
      prm.add_parameter("Spalling strain", s.concrete.spalling_strain, "[RC] The cover's stress "
                        "falls linearly from f'c to zero there (> Peak strain). Unit: -.",
                        Patterns::Double());
      prm.add_parameter("Tensile ratio", s.concrete.tensile_ratio, "[RC] Concrete02's tensile "
                        "strength over f'c (softening Ets = ft / 0.002). Unit: -.", Patterns::Double());
      add_choice(prm, "Confinement", s.concrete.confined ? "Mander" : "none", "[RC] The core's "
                 "concrete: confined after Mander et al. (1988), or as the cover. Unit: -.",
                 {"Mander", "none"}, [&s](const std::string &v) { s.concrete.confined = v == "Mander"; });
      prm.add_parameter("Crushing strain", s.concrete.crushing_strain, "[RC] The core's failure "
                        "strain (positive; 0: Mander's eps_cu, or 0.0035 unconfined). Unit: -.",
                        Patterns::Double());
      add_choice(prm, "Steel law", s.steel.law, "[RC, steel I] Unit: -.",
                 {"Steel02", "Steel01", "ElasticPP"});
      prm.add_parameter("Yield stress", s.steel.fy, "[RC, steel I] Unit: Pa.", Patterns::Double());
      prm.add_parameter("Elastic modulus", s.steel.E, "[RC, steel I] Unit: Pa.", Patterns::Double());
      prm.add_parameter("Hardening ratio", s.steel.b, "[RC, steel I] Esh / E (Steel01, Steel02). "
                        "Unit: -.", Patterns::Double());
      prm.add_parameter("Ultimate strain", s.steel.ultimate_strain, "[RC, steel I] The steel's "
                        "rupture strain, a failure limit, and the stirrups' strain at their "
                        "strength for Mander's eps_cu (0: no limit). Unit: -.", Patterns::Double());
    }

    void
    declare_section_fibres(dealii::ParameterHandler &prm, SectionEntry &s)
    {
      prm.add_parameter("Fibres across depth", s.fibres_depth, "[RC rectangle] The core's fibres "
                        "along y (the cover's at the same pitch). Unit: count.",
                        Patterns::Integer(0, 10000));
      prm.add_parameter("Fibres across width", s.fibres_width, "[RC rectangle] The core's fibres "
                        "along z. Unit: count.", Patterns::Integer(0, 10000));
      prm.add_parameter("Fibres round", s.fibres_round, "[RC circle] Sectors. Unit: count.",
                        Patterns::Integer(0, 10000));
      prm.add_parameter("Fibres across radius", s.fibres_radius, "[RC circle] The core's rings. "
                        "Unit: count.", Patterns::Integer(0, 10000));
      prm.add_parameter("Fibres through flange", s.fibres_flange_thickness, "[steel I] Unit: count.",
                        Patterns::Integer(0, 10000));
      prm.add_parameter("Fibres across flange", s.fibres_flange_width, "[steel I] Unit: count.",
                        Patterns::Integer(0, 10000));
      prm.add_parameter("Fibres along web", s.fibres_web, "[steel I] Unit: count.",
                        Patterns::Integer(0, 10000));
      prm.add_parameter("Fibres", s.fibres, "[fibres] OpenSees's commands separated by ';' with "
                        "the names of Sections/Materials for tags: patch rect M nY nZ yI zI yJ zJ; "
                        "patch quad M nIJ nJK yI zI yJ zJ yK zK yL zL; patch circ M nCirc nRad yc zc "
                        "rInt rExt [a0 a1]; layer straight M n A y1 z1 y2 z2; layer circ M n A yc zc "
                        "r [a0 a1]; fiber y z A M (m, m^2, degrees). Unit: per field.", Patterns::Anything());
      prm.add_parameter("Torsional rigidity", s.torsional_rigidity, "GJ of a section in space "
                        "(elastic, uncoupled; 0: not given). Unit: N m^2.", Patterns::Double());
    }
  } // namespace

  void
  SectionEntry::declare(dealii::ParameterHandler &prm)
  {
    prm.add_parameter("Name", name, "The section's name, by which members and Moment "
                      "curvature/Section name it. Unit: -.", Patterns::Anything());
    add_choice(prm, "Type", type, "Built from engineering data, or fibre by fibre (Fibres). "
               "Unit: -.", {"RC rectangle", "RC circle", "steel I", "fibres"});
    declare_section_geometry(prm, *this);
    declare_section_materials(prm, *this);
    declare_section_fibres(prm, *this);
  }

  void
  SectionsParameters::declare_number_of_sections(dealii::ParameterHandler &prm, unsigned int &n)
  {
    prm.enter_subsection("Sections");
    prm.add_parameter("Number of sections", n, "Subsections `Section 1` .. `Section n` follow. "
                      "Unit: count.", Patterns::Integer(0, 1000));
    prm.leave_subsection();
  }

  void
  SectionsParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Sections");
    // read in the first pass into sections.size(); declared again without
    // an action so that the file's entry is known here
    prm.declare_entry("Number of sections", "0",
                      Patterns::Integer(0, 1000), "Subsections `Section 1` .. `Section n` follow. "
                      "Unit: count.");
    prm.add_parameter("Materials", materials, "The materials `fibres` sections name, separated "
                      "by ';': `name: Law key=value ...` with a law of the registry (Steel01, "
                      "Steel02, Concrete01, Concrete02, ElasticPP, Hysteretic) and its OpenSees "
                      "parameters, and optional min=, max= failure strains. Unit: per field.",
                      Patterns::Anything());
    for (unsigned int k = 0; k < sections.size(); ++k)
      {
        prm.enter_subsection("Section " + std::to_string(k + 1));
        sections[k].declare(prm);
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }

  namespace
  {
    /// "name: Law key=value ..." as a section material; throws InputError
    /// with the problem (the caller names the entry).
    SectionMaterial
    section_material_item(const std::string &item)
    {
      const std::size_t colon = item.find(':');
      SectionMaterial   m;
      m.name = trimmed(item.substr(0, colon));
      if (colon == std::string::npos || m.name.empty() || m.name.find(' ') != std::string::npos)
        throw InputError("", 0, "", "'" + trimmed(item) + "' is not 'name: Law key=value ...'");
      std::istringstream words(item.substr(colon + 1));
      if (!(words >> m.law.material))
        throw InputError("", 0, "", "material '" + m.name + "' names no law");
      material_type(m.law.material); // an unknown law: InputError listing the known
      for (std::string word; words >> word;)
        {
          const std::size_t equals = word.find('=');
          const auto value = equals == std::string::npos ? std::nullopt :
                                                           parse_number(word.substr(equals + 1));
          if (!value)
            throw InputError("", 0, "", "material '" + m.name + "': '" + word +
                                          "' is not key=number");
          const std::string key = word.substr(0, equals);
          if (key == "min" || key == "max")
            (key == "min" ? m.min_strain : m.max_strain) = *value;
          else if (m.law.values.count(key) != 0)
            throw InputError("", 0, "", "material '" + m.name + "': " + key + " given twice");
          else
            m.law.values[key] = *value;
        }
      if (!(std::isnan(m.min_strain) || m.min_strain < 0) ||
          !(std::isnan(m.max_strain) || m.max_strain > 0))
        throw InputError("", 0, "", "material '" + m.name + "': min must be < 0 and max > 0");
      make_material(m.law); // its own checks, naming its parameter
      // Elastic's own check takes a modulus of either sign; a fibre of
      // negative modulus makes the section's stiffness indefinite
      if (m.law.material == "Elastic")
        for (const char *modulus : {"E", "Eneg"})
          if (const auto given = m.law.values.find(modulus); given != m.law.values.end())
            require_non_negative("Elastic", modulus, given->second);
      return m;
    }

    /// The builder's geometry of a section entry.
    FibreGeometry
    built_geometry(const SectionEntry &s)
    {
      if (s.type == "RC rectangle")
        return rc_rectangle({s.depth, s.width, s.cover, s.bars_top, s.bars_bottom, s.bars_side,
                             s.bar_diameter, s.stirrup_diameter, s.stirrup_spacing, s.legs_y,
                             s.legs_z, s.concrete, s.steel, s.fibres_depth, s.fibres_width});
      if (s.type == "RC circle")
        return rc_circle({s.diameter, s.cover, s.bars, s.bar_diameter, s.stirrup_diameter,
                          s.stirrup_spacing, s.spiral, s.concrete, s.steel, s.fibres_round,
                          s.fibres_radius});
      return steel_i_shape({s.depth, s.flange_width, s.flange_thickness, s.web_thickness,
                            s.steel, s.fibres_flange_thickness, s.fibres_flange_width,
                            s.fibres_web});
    }
  } // namespace

  std::vector<SectionMaterial>
  SectionsParameters::material_list(const InputFile &input) const
  {
    std::vector<SectionMaterial> list;
    std::istringstream           in(materials);
    for (std::string item; std::getline(in, item, ';');)
      {
        if (trimmed(item).empty())
          continue;
        try
          {
            list.push_back(section_material_item(item));
          }
        catch (const InputError &e)
          {
            // a law's parameter leads the problem ("epscu: Concrete01: ...")
            const bool named = !e.parameter().empty() && e.parameter() != "Material";
            input.fail("Sections/Materials", (named ? e.parameter() + ": " : "") + e.problem());
          }
        for (std::size_t j = 0; j + 1 < list.size(); ++j)
          if (list[j].name == list.back().name)
            input.fail("Sections/Materials", "material '" + list.back().name + "' given twice");
      }
    return list;
  }

  FibreGeometry
  SectionsParameters::geometry(const InputFile &input, const unsigned int k) const
  {
    const SectionEntry &s    = sections[k];
    const std::string   path = "Sections/Section " + std::to_string(k + 1) + "/";
    try
      {
        if (s.type != "fibres")
          return built_geometry(s);
        FibreGeometry g;
        for (const SectionMaterial &m : material_list(input))
          g.add_material(m);
        add_fibre_commands(g, s.fibres);
        if (g.fibres.empty())
          input.fail(path + "Fibres", "the section has no fibres");
        return g;
      }
    catch (const InputError &e)
      {
        if (!e.file().empty())
          throw; // already placed
        // a builder names its entry ("Cover"); a law or Mander's confinement
        // their own parameter ("fpc", "rho_cc"), given under the section's Type
        const bool entry =
          !e.parameter().empty() && std::isupper(static_cast<unsigned char>(e.parameter()[0]));
        input.fail(path + (entry ? e.parameter() : "Type"),
                   (entry ? "" : e.parameter() + ": ") + e.problem());
      }
  }

  FibreSection
  SectionsParameters::section(const InputFile &input, const unsigned int k,
                              const unsigned int n_resultants) const
  {
    const FibreGeometry g = geometry(input, k);
    const double        gj = sections[k].torsional_rigidity;
    try
      {
        // torsion does not enter a section's bending: any positive GJ when none is given
        return FibreSection(g, n_resultants, gj > 0 ? gj : 1.0);
      }
    catch (const InputError &e)
      {
        input.fail("Sections/Section " + std::to_string(k + 1) + "/Fibres", e.problem());
      }
  }

  void
  SectionsParameters::check(const InputFile &input) const
  {
    for (unsigned int k = 0; k < sections.size(); ++k)
      {
        const std::string path = "Sections/Section " + std::to_string(k + 1) + "/";
        if (trimmed(sections[k].name).empty())
          input.fail(path + "Name", "every section needs a name");
        for (unsigned int j = 0; j < k; ++j)
          if (sections[j].name == sections[k].name)
            input.fail(path + "Name", "'" + sections[k].name + "' is also Section " +
                                        std::to_string(j + 1) + "'s name");
        if (!(std::isfinite(sections[k].torsional_rigidity) && sections[k].torsional_rigidity >= 0))
          input.fail(path + "Torsional rigidity", "must be >= 0");
        section(input, k, 2);
      }
    if (sections.empty() && !trimmed(materials).empty())
      material_list(input);
  }

  unsigned int
  SectionsParameters::find(const InputFile &input, const std::string &path,
                           const std::string &name) const
  {
    std::string known;
    for (unsigned int k = 0; k < sections.size(); ++k)
      {
        if (sections[k].name == name)
          return k;
        known += (known.empty() ? "" : ", ") + sections[k].name;
      }
    input.fail(path, "no section named '" + name + "' (Sections: " +
                       (known.empty() ? "none" : known) + ")");
  }

  namespace
  {
    /// The largest compressive (first, <= 0) and tensile (second) axial
    /// force of `section` under a uniform strain growing to +-0.1 (beyond
    /// concrete's crushing and most steels' rupture), or until a fibre
    /// refuses its strain: the squash and tension capacities.
    std::pair<double, double>
    axial_capacity(const SectionLaw &section)
    {
      constexpr unsigned int n_steps      = 200;
      constexpr double       largest_strain = 0.1;
      std::pair<double, double> capacity{0, 0};
      for (const double sign : {-1.0, 1.0})
        {
          const std::unique_ptr<SectionLaw> ramp = section.clone();
          ramp->reset();
          SectionVector strain = SectionVector::Zero(ramp->n_resultants());
          for (unsigned int i = 1; i <= n_steps; ++i)
            {
              strain[0] = sign * largest_strain * i / n_steps;
              if (!ramp->set_trial(strain))
                break;
              ramp->commit();
              capacity.first  = std::min(capacity.first, ramp->resultant()[0]);
              capacity.second = std::max(capacity.second, ramp->resultant()[0]);
            }
        }
      return capacity;
    }

    /// The target curvature within a strain of 1 (100 %) at the fibre
    /// farthest from the reference point, beyond the rupture of any concrete
    /// or steel: more is a typing error (a target of 1e200 1/m once ran to
    /// its end and reported a curve of absurd strains).
    void
    check_target_curvature(const InputFile &input, const FibreSection &fibres,
                           const double curvature)
    {
      constexpr double largest_strain = 1;
      double           reach          = 0;
      for (const Fibre &f : fibres.geometry().fibres)
        reach = std::max(reach, std::hypot(f.y - fibres.reference_y(), f.z - fibres.reference_z()));
      if (reach > 0 && curvature * reach > largest_strain)
        input.fail("Moment curvature/Target curvature",
                   "must be at most " + number_text(largest_strain / reach) +
                     " 1/m, a strain of 1 at the section's farthest fibre (" +
                     number_text(reach) + " m from the reference point), beyond the rupture "
                     "of any concrete or steel (got " + number_text(curvature) + ")");
    }

    /// The axial force within twice the section's capacity: more is a
    /// typing error (a force of 1e200 N once passed with a tolerance scaled
    /// by it); up to twice it, the analysis says whether the section
    /// carries it.
    void
    check_axial_force(const InputFile &input, const SectionLaw &section, const double force)
    {
      constexpr double margin = 2;
      const std::pair<double, double> capacity = axial_capacity(section);
      if (force < margin * capacity.first || force > margin * capacity.second)
        input.fail("Moment curvature/Axial force",
                   "must lie within [" + number_text(margin * capacity.first) + ", " +
                     number_text(margin * capacity.second) +
                     "] N, twice the section's capacity (its squash force " +
                     number_text(capacity.first) + " N and tension force " +
                     number_text(capacity.second) + " N, tension positive), got " +
                     number_text(force));
    }
  } // namespace

  void
  MomentCurvatureParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Moment curvature");
    prm.add_parameter("Section", section, "The Name of the section of `moment-curvature`. "
                      "Unit: -.", Patterns::Anything());
    prm.add_parameter("Axial force", settings.axial_force, "N held constant, tension positive "
                      "(a column's compression is negative). Unit: N.", Patterns::Double());
    prm.add_parameter("Angle", settings.angle, "Direction of the curvature from the z axis: 0 "
                      "bends about z (a plane section), any other angle a section in space, "
                      "kappa_z = kappa cos, kappa_y = kappa sin. Unit: degrees.",
                      Patterns::Double(-360, 360));
    prm.add_parameter("Target curvature", settings.target_curvature, "The last curvature. "
                      "Unit: 1/m.", Patterns::Double());
    prm.add_parameter("Steps", settings.steps, "Equal curvature increments to the target. "
                      "Unit: count.", Patterns::Integer(1, 100000));
    prm.add_parameter("Moment drop", settings.drop_fraction, "Stop when the moment falls below "
                      "this fraction of the peak (0: never). Unit: -.", Patterns::Double());
    prm.leave_subsection();
  }

  void
  MomentCurvatureParameters::check(const InputFile &input, const SectionsParameters &sections) const
  {
    // only an analysis that is asked for: every input has this section
    if (trimmed(section).empty())
      return;
    const std::string s = "Moment curvature/";
    input.positive(s + "Target curvature", settings.target_curvature);
    if (!(settings.drop_fraction >= 0 && settings.drop_fraction < 1))
      input.fail(s + "Moment drop", "must lie in [0, 1)");
    if (!std::isfinite(settings.axial_force))
      input.fail(s + "Axial force", "must be finite");
    sections.find(input, s + "Section", section);
  }

  MomentCurvatureResult
  MomentCurvatureParameters::run(const InputFile &input, const SectionsParameters &sections,
                                 unsigned int &n_fibres) const
  {
    const std::string path = "Moment curvature/Section";
    if (trimmed(section).empty())
      input.fail(path, "names no section (give a Name of Sections)");
    const unsigned int k = sections.find(input, path, section);
    FibreSection fibres  = sections.section(input, k, settings.angle == 0 ? 2 : 4);
    n_fibres             = fibres.geometry().fibres.size();
    check_axial_force(input, fibres, settings.axial_force);
    check_target_curvature(input, fibres, settings.target_curvature);
    try
      {
        return moment_curvature(fibres, settings);
      }
    catch (const InputError &e)
      {
        input.fail("Moment curvature/" + e.parameter(), e.problem());
      }
  }
} // namespace poundfe
