// Fibre sections from engineering data: a reinforced concrete rectangle and
// circle (confined core after Mander, Priestley & Park 1988, unconfined
// cover, longitudinal bars) and a steel I-shape. Each makes the patches and
// layers an OpenSees user would write (fibre_generators.h) and the
// materials by the registry's names (laws/material_registry.h).
// Axes: y along the depth (Mz bends it: a fibre's strain is -y kappa_z),
// z along the width; the section's centre at the origin.
// The cover is measured from the concrete face to the centreline of the
// stirrups or spiral: the confined core of Mander's model ends there, and
// the longitudinal bars' centres lie a half stirrup and a half bar further
// in. As in OpenSees's own fibre sections, the bars' area is added to the
// concrete's (the concrete they displace is not taken out).
#ifndef poundfe_sections_section_builders_h
#define poundfe_sections_section_builders_h

#include <poundfe/sections/fibre_section.h>

#include <string>

namespace poundfe
{
  /// The concrete of an RC section (strengths as positive magnitudes, Pa).
  struct SectionConcrete
  {
    std::string law             = "Concrete02"; // or Concrete01
    double      fc              = 30e6;         // unconfined strength
    double      eps_c0          = 0.002;        // strain at fc
    double      spalling_strain = 0.005; // the cover's stress reaches zero there (> eps_c0)
    /// Concrete02's tension: ft = ratio fc, Ets = ft / 0.002 (OpenSees's examples).
    double tensile_ratio = 0.14;
    /// Mander's confined core; false: the core is cover concrete.
    bool confined = true;
    /// The core's crushing strain (a fibre limit); 0: Mander's eps_cu when
    /// confined, 0.0035 when not.
    double crushing_strain = 0;
  };

  /// The steel of bars, stirrups or a steel section (Pa).
  struct SectionSteel
  {
    std::string law = "Steel02"; // Steel01, Steel02 or ElasticPP
    double      fy  = 420e6;
    double      E   = 200e9;
    double      b   = 0.01; // hardening ratio (not ElasticPP)
    /// Strain at the ultimate stress: the bars' rupture limit and Mander's
    /// eps_su of the stirrups; 0: no rupture limit.
    double ultimate_strain = 0.1;
  };

  struct RcRectangle
  {
    double       depth = 0, width = 0; // h along y, b along z (m)
    double       cover = 0;            // face to the stirrups' centreline (m)
    unsigned int bars_top = 0, bars_bottom = 0, bars_side = 0; // bars on +y, -y, each z face
    double       bar_diameter      = 0; // m
    double       stirrup_diameter  = 0; // m
    double       stirrup_spacing   = 0; // centre to centre (m)
    unsigned int legs_y = 2, legs_z = 2; // stirrup legs running along y and along z
    SectionConcrete concrete;
    SectionSteel    steel;
    unsigned int    fibres_y = 20, fibres_z = 10; // the core's fibres across the depth, width
  };

  struct RcCircle
  {
    double       diameter = 0, cover = 0; // cover: face to the spiral's centreline (m)
    unsigned int bars             = 0;
    double       bar_diameter     = 0;
    double       spiral_diameter  = 0;
    double       spiral_pitch     = 0; // centre to centre (m)
    bool         spiral           = true; // false: circular hoops
    SectionConcrete concrete;
    SectionSteel    steel;
    unsigned int    sectors = 24, rings = 10; // the core's fibres round and across
  };

  struct SteelIShape
  {
    double       depth = 0, flange_width = 0, flange_thickness = 0, web_thickness = 0; // m
    SectionSteel steel;
    unsigned int flange_fibres_thickness = 4, flange_fibres_width = 8, web_fibres = 16;
  };

  /// InputError naming the builder's parameter ("Cover", "Bar diameter",
  /// ...) for a dimension <= 0, a cover >= half a side, bars or stirrups
  /// outside the concrete, a crushing strain within the peak strain.
  FibreGeometry rc_rectangle(const RcRectangle &section);
  FibreGeometry rc_circle(const RcCircle &section);
  FibreGeometry steel_i_shape(const SteelIShape &section);

  /// The steel's law by the registry's parameter names.
  MaterialParameters steel_material(const SectionSteel &steel);
} // namespace poundfe

#endif
