// The `Sections` section of a parameter file: numbered sections `Section 1`
// .. `Section n` (n = Sections/Number of sections, read in the first pass
// like Model/Number of buildings), each named and either built from
// engineering data (Type = RC rectangle | RC circle | steel I, see
// section_builders.h) or given fibre by fibre (Type = fibres) by OpenSees's
// own commands with material names for tags:
//   set Materials = concrete: Concrete02 fpc=-30e6 epsc0=-0.002 fpcu=-6e6 epscu=-0.006 ft=3e6 Ets=1.5e9;
//                   steel: Steel02 fy=420e6 E0=200e9 b=0.01 max=0.1
//   set Fibres    = patch rect concrete 10 10 -0.2 -0.2 0.2 0.2; layer straight steel 3 4.9e-4 ...
// A material's parameters are the registry's (OpenSees's names); `min=`
// and `max=` are its fibres' failure strains (OpenSees's MinMax). And the
// `Moment curvature` section of the `moment-curvature` command.
#ifndef poundfe_sections_section_parameters_h
#define poundfe_sections_section_parameters_h

#include <poundfe/base/input_file.h>
#include <poundfe/sections/moment_curvature.h>
#include <poundfe/sections/section_builders.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  /// One `Section <k>`: the entries of every type (each builder reads its own).
  struct SectionEntry
  {
    std::string  name;
    std::string  type = "RC rectangle";
    double       depth = 0, width = 0, diameter = 0, cover = 0.04;
    unsigned int bars_top = 3, bars_bottom = 3, bars_side = 0, bars = 8;
    double       bar_diameter = 0.02, stirrup_diameter = 0.01, stirrup_spacing = 0.1;
    unsigned int legs_y = 2, legs_z = 2;
    bool         spiral = true;
    SectionConcrete concrete;
    SectionSteel    steel;
    double       flange_width = 0, flange_thickness = 0, web_thickness = 0;
    unsigned int fibres_depth = 20, fibres_width = 10, fibres_round = 24, fibres_radius = 10;
    unsigned int fibres_flange_thickness = 4, fibres_flange_width = 8, fibres_web = 16;
    std::string  fibres;
    double       torsional_rigidity = 0;

    void declare(dealii::ParameterHandler &prm);
  };

  struct SectionsParameters
  {
    std::string               materials; // the Materials list, as written
    std::vector<SectionEntry> sections;

    /// The first pass: only the number of sections.
    static void declare_number_of_sections(dealii::ParameterHandler &prm, unsigned int &n);
    /// Declare the section (entered and left here) with sections.size() sections.
    void declare(dealii::ParameterHandler &prm);
    /// Builds every section once: InputError naming the entry for a name
    /// given twice, a material or builder value refused, no fibres.
    void check(const InputFile &input) const;

    /// The index of the section called `name`; InputError at `path` if none.
    unsigned int find(const InputFile &input, const std::string &path,
                      const std::string &name) const;
    /// Section k's fibres and materials; InputError naming its entry.
    FibreGeometry geometry(const InputFile &input, unsigned int k) const;
    /// Section k as a plane (2) or space (4) fibre section.
    FibreSection section(const InputFile &input, unsigned int k, unsigned int n_resultants) const;
    /// The materials of the Materials list (InputError at Sections/Materials).
    std::vector<SectionMaterial> material_list(const InputFile &input) const;
  };

  /// The `Moment curvature` section.
  struct MomentCurvatureParameters
  {
    std::string             section; // a section's Name
    MomentCurvatureSettings settings;

    void declare(dealii::ParameterHandler &prm);
    /// A named section must exist (an empty name is checked by run()).
    void check(const InputFile &input, const SectionsParameters &sections) const;
    /// The analysis this section asks for (the command's and Python's):
    /// its section of `sections`, plane at angle 0, else in space;
    /// InputError naming the entry if none is named or N cannot be carried.
    /// `n_fibres`: the section's number of fibres.
    MomentCurvatureResult run(const InputFile &input, const SectionsParameters &sections,
                              unsigned int &n_fibres) const;
  };
} // namespace poundfe

#endif
