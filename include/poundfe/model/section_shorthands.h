// The section shorthands of a generated frame: `Column section` and `Beam
// section` = "rectangle b h" or "circle D" give A, I, Iz and the
// Saint-Venant torsion constant J; `Poisson ratio` gives G = E / (2 (1 + nu))
// (model/section_shorthands.cc; doc/theory.md §1.15).
#ifndef poundfe_model_section_shorthands_h
#define poundfe_model_section_shorthands_h

#include <poundfe/base/input_file.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  struct BuildingParameters;
  struct ModelParameters;

  /// A solid cross-section's properties. I is about the axis across the
  /// depth h (bending in the plane of h), Iz about the axis along h.
  struct SolidSection
  {
    double area          = 0;
    double second_moment = 0;   // I = b h^3 / 12 (rectangle)
    double second_moment_z = 0; // Iz = h b^3 / 12
    double torsion_constant = 0; // J
  };

  /// Saint-Venant torsion constant of a solid rectangle of sides a and b
  /// (either order): J = a b^3 [1/3 - (64 / pi^5) (b / a) sum over odd n of
  /// tanh(n pi a / (2 b)) / n^5], a the longer side (Timoshenko & Goodier
  /// 1970, §109; Roark's Formulas, Table 10.7 case 4): 0.1406 a^4 for a
  /// square, 0.2287 a b^3 at a = 2 b.
  double rectangle_torsion_constant(double a, double b);

  /// A rectangle of width b and depth h, or a circle of diameter D
  /// (J = pi D^4 / 32).
  SolidSection rectangle_section(double b, double h);
  SolidSection circle_section(double diameter);

  /// "rectangle b h" or "circle D" (positive, finite lengths in m), or none
  /// when the text is neither.
  std::optional<SolidSection> parse_solid_section(const std::string &text);

  /// The texts of `<section>Column section` and `Beam section` ("rectangle
  /// b h" or "circle D", one or one per storey/floor, ';' between; empty:
  /// none) into the building's A, I, Iz and J lists; an entry they give that
  /// is also written is refused. Throws InputError.
  void expand_section_shorthands(const InputFile &input, const std::string &section,
                                 const std::string &column_text, const std::string &beam_text,
                                 BuildingParameters &building);

  /// The text of `<section>Poisson ratio` (empty: none) into Column G and
  /// Beam G (one per value of Column E / Beam E); refused beside a written
  /// Column G or Beam G, and outside (-1, 0.5]. Throws InputError.
  void shear_moduli_from_poisson_ratio(const InputFile &input, const std::string &section,
                                       const std::string &text, BuildingParameters &building);

  /// Declare the unbound entries Column section and Beam section (frames)
  /// or Poisson ratio (3D frames) in the current subsection: their texts are
  /// read back from the parsed values by apply_section_shorthands.
  void declare_section_shorthands(dealii::ParameterHandler &prm);
  void declare_poisson_ratio(dealii::ParameterHandler &prm);

  /// Every frame building's shorthands, from the parsed `values` (path,
  /// text), before ModelParameters::finalize checks the lists they fill
  /// (a shorthand written for another Type is left to its refusal there).
  void apply_section_shorthands(const InputFile                                        &input,
                                const std::vector<std::pair<std::string, std::string>> &values,
                                ModelParameters                                        &model);
} // namespace poundfe

#endif
