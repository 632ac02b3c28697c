// RC rectangle, RC circle and steel I-shape fibre sections (see the header).
// The core's concrete: Mander et al. (1988) through laws/mander_confinement
// (rectangular: every longitudinal bar restrained by a stirrup leg or tie,
// so the clear spacings w' are those between adjacent bars; legs_z legs
// along z give Asx, legs_y along y Asy); Concrete01 takes its (f'cc,
// eps_cc, f at eps_cu, eps_cu), Concrete02 the same with lambda = 0.1 (or
// fpcu / (Ec0 epscu) where that is larger: concrete02_unloading_ratio) and
// tension ft = ratio f'c, Ets = ft / 0.002. The cover: Kent–Scott–Park to
// (eps_c0, f'c), then down to zero stress at the spalling strain.
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/laws/mander_confinement.h>
#include <poundfe/sections/fibre_generators.h>
#include <poundfe/sections/material_bounds.h>
#include <poundfe/sections/section_builders.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  namespace
  {
    const double builder_pi = std::acos(-1.0);
    /// The largest steel rupture strain taken: twice the most ductile
    /// steels' (about 0.25); more is a typing error, and through Mander's
    /// eps_cu = 0.004 + 1.4 rho_s fyh eps_su / f'cc it makes the core
    /// crush at strains no concrete reaches.
    constexpr double largest_ultimate_strain = 0.5;
    /// The largest concrete strain taken for the cover's spalling: twice the
    /// most confined cores' crushing strain (Mander's eps_cu, up to about
    /// 0.05); more is a typing error (1e200 left a cover that never spalls).
    constexpr double largest_concrete_strain = 0.1;

    [[noreturn]] void
    refuse_builder(const char *parameter, const std::string &problem)
    {
      throw InputError("", 0, parameter, problem);
    }

    // sections/material_bounds.h says why
    constexpr double largest_modulus  = largest_section_modulus;
    constexpr double largest_strength = largest_section_strength;

    void
    builder_at_most(const char *parameter, const double value, const double bound,
                    const std::string &why)
    {
      if (value > bound)
        refuse_builder(parameter, "must be at most " + number_text(bound) + " Pa, " + why +
                                    " (got " + number_text(value) + ")");
    }

    void
    builder_positive(const char *parameter, const double value)
    {
      if (!(std::isfinite(value) && value > 0))
        refuse_builder(parameter, "must be positive (got " + number_text(value) + ")");
    }

    /// Concrete02's lambda: 0.1, or more where that would put the focus R
    /// of its unloading lines, eps_R = (fpcu - lambda Ec0 epscu) / (Ec0 (1 -
    /// lambda)), on the compression side (Mander's confined cores: their
    /// fpcu is high). There the reloading slope Er = (sigma_m - Ec0 eps_R) /
    /// (eps_min - eps_R) is infinite at eps_min = eps_R and negative beyond
    /// it, and the stress jumps from compression to tension as the strain
    /// leaves eps_min: a section cannot find its equilibrium across it. The
    /// smallest lambda that keeps eps_R >= 0 is fpcu / (Ec0 epscu).
    double
    concrete02_unloading_ratio(const Concrete01Parameters &k)
    {
      const double Ec0 = 2 * k.fpc / k.epsc0;
      return std::max(0.1, k.fpcu / (Ec0 * k.epscu));
    }

    /// Concrete01 or Concrete02 with the Kent–Scott–Park points `k`.
    MaterialParameters
    concrete_material(const SectionConcrete &c, const Concrete01Parameters &k)
    {
      MaterialParameters m{c.law, {{"fpc", k.fpc}, {"epsc0", k.epsc0}, {"fpcu", k.fpcu},
                                   {"epscu", k.epscu}}};
      if (c.law == "Concrete02")
        {
          const double ft = c.tensile_ratio * c.fc;
          m.values["lambda"] = concrete02_unloading_ratio(k);
          m.values["ft"]     = ft;
          m.values["Ets"]    = ft > 0 ? ft / 0.002 : c.fc; // any slope: no tension to soften
        }
      else if (c.law != "Concrete01")
        refuse_builder("Concrete law", "must be Concrete01 or Concrete02 (got '" + c.law + "')");
      return m;
    }

    void
    check_concrete(const SectionConcrete &c)
    {
      builder_positive("Concrete strength", c.fc);
      builder_at_most("Concrete strength", c.fc, largest_strength,
                      "ten times the strongest steel wires' strength");
      builder_positive("Peak strain", c.eps_c0);
      if (!(c.spalling_strain > c.eps_c0))
        refuse_builder("Spalling strain", "must exceed the peak strain " + number_text(c.eps_c0) +
                                            " (got " + number_text(c.spalling_strain) + ")");
      if (c.spalling_strain > largest_concrete_strain)
        refuse_builder("Spalling strain", "must be at most " +
                                            number_text(largest_concrete_strain) +
                                            ": no concrete, confined or not, reaches a larger "
                                            "compressive strain (got " +
                                            number_text(c.spalling_strain) + ")");
      if (!(std::isfinite(c.tensile_ratio) && c.tensile_ratio >= 0 && c.tensile_ratio < 1))
        refuse_builder("Tensile ratio", "must lie in [0, 1)");
      if (c.crushing_strain != 0 && !(c.crushing_strain > c.eps_c0))
        refuse_builder("Crushing strain", "must exceed the peak strain " + number_text(c.eps_c0) +
                                            " (got " + number_text(c.crushing_strain) + ")");
    }

    void
    check_steel(const SectionSteel &s)
    {
      builder_positive("Yield stress", s.fy);
      builder_positive("Elastic modulus", s.E);
      builder_at_most("Yield stress", s.fy, largest_strength,
                      "ten times the strongest steel wires' strength");
      builder_at_most("Elastic modulus", s.E, largest_modulus,
                      "ten times diamond's, the stiffest material");
      // b E is the slope after yield: a negative one softens (no unique
      // section response), one of E or more is no yield at all
      if (!(s.b >= 0 && s.b < 1))
        refuse_builder("Hardening ratio", "must lie in [0, 1): Esh = b E, the slope after "
                                          "yield, is not negative and below E (got " +
                                            number_text(s.b) + ")");
      if (!(std::isfinite(s.ultimate_strain) && s.ultimate_strain >= 0))
        refuse_builder("Ultimate strain", "must be >= 0");
      if (s.ultimate_strain > largest_ultimate_strain)
        refuse_builder("Ultimate strain", "must be at most " +
                                            number_text(largest_ultimate_strain) +
                                            ": reinforcing and structural steels rupture at "
                                            "0.05 to 0.25 (got " +
                                            number_text(s.ultimate_strain) + ")");
      if (s.ultimate_strain > 0 && !(s.ultimate_strain > s.fy / s.E))
        refuse_builder("Ultimate strain", "must exceed the yield strain fy / E = " +
                                            number_text(s.fy / s.E));
    }

    SectionMaterial
    cover_material(const SectionConcrete &c)
    {
      SectionMaterial m;
      m.name = "cover";
      m.law  = concrete_material(c, {-c.fc, -c.eps_c0, 0, -c.spalling_strain});
      return m;
    }

    /// The core: Mander's confined concrete, or the cover's.
    SectionMaterial
    core_material(const SectionConcrete &c, const ManderConfinement *confined)
    {
      SectionMaterial m = cover_material(c);
      m.name            = "core";
      if (confined != nullptr)
        m.law = concrete_material(c, mander_concrete01(*confined, c.fc));
      const double crushing = c.crushing_strain > 0 ? c.crushing_strain :
                              confined != nullptr   ? confined->eps_cu : 0.0035;
      m.min_strain = -crushing;
      return m;
    }

    SectionMaterial
    bar_material(const SectionSteel &s)
    {
      SectionMaterial m;
      m.name = "steel";
      m.law  = steel_material(s);
      if (s.ultimate_strain > 0)
        {
          m.min_strain = -s.ultimate_strain;
          m.max_strain = s.ultimate_strain;
        }
      return m;
    }

    /// The number of fibres across a strip of `thickness` at the core's pitch.
    unsigned int
    strip_fibres(const double thickness, const double pitch)
    {
      return std::max(1u, static_cast<unsigned int>(std::ceil(thickness / pitch - 1e-9)));
    }
  } // namespace

  MaterialParameters
  steel_material(const SectionSteel &s)
  {
    check_steel(s);
    if (s.law == "ElasticPP")
      return {s.law, {{"E", s.E}, {"epsyP", s.fy / s.E}}};
    if (s.law == "Steel01" || s.law == "Steel02")
      return {s.law, {{"fy", s.fy}, {"E0", s.E}, {"b", s.b}}};
    refuse_builder("Steel law", "must be Steel01, Steel02 or ElasticPP (got '" + s.law + "')");
  }

  namespace
  {
    /// The bars' centres' distance from the face; checks the cover.
    double
    bar_offset(const double cover, const double stirrup_diameter, const double bar_diameter,
               const double smallest_side, const char *side)
    {
      builder_positive("Cover", cover);
      builder_positive("Bar diameter", bar_diameter);
      builder_positive("Stirrup diameter", stirrup_diameter);
      if (!(cover >= stirrup_diameter / 2))
        refuse_builder("Cover", "the stirrups lie outside the concrete: the cover to their "
                                "centreline (" + number_text(cover) + " m) is less than half "
                                "their diameter");
      if (!(2 * cover < smallest_side))
        refuse_builder("Cover", "must be less than half the " + std::string(side) + " (" +
                                  number_text(smallest_side / 2) + " m): no core is left");
      const double offset = cover + stirrup_diameter / 2 + bar_diameter / 2;
      if (!(2 * offset < smallest_side))
        refuse_builder("Bar diameter", "the bars do not fit inside the stirrups");
      return offset;
    }

    ManderConfinement
    rectangle_confinement(const RcRectangle &r, const double bar_span_y, const double bar_span_z)
    {
      const double area_bar = builder_pi * r.bar_diameter * r.bar_diameter / 4;
      const double area_leg = builder_pi * r.stirrup_diameter * r.stirrup_diameter / 4;
      ManderRectangularSection m;
      m.materials = {r.concrete.fc, r.concrete.eps_c0, r.steel.fy,
                     r.steel.ultimate_strain > 0 ? r.steel.ultimate_strain : 0.1};
      m.bc      = r.width - 2 * r.cover;
      m.dc      = r.depth - 2 * r.cover;
      m.s       = r.stirrup_spacing;
      m.s_clear = r.stirrup_spacing - r.stirrup_diameter;
      m.Asx     = r.legs_z * area_leg;
      m.Asy     = r.legs_y * area_leg;
      const unsigned int n_bars = r.bars_top + r.bars_bottom + 2 * r.bars_side;
      m.rho_cc                  = n_bars * area_bar / (m.bc * m.dc);
      for (const unsigned int n : {r.bars_top, r.bars_bottom})
        for (unsigned int k = 0; k + 1 < n; ++k)
          m.w_clear.push_back(bar_span_z / (n - 1) - r.bar_diameter);
      for (unsigned int k = 0; k < 2 * (r.bars_side + 1); ++k)
        m.w_clear.push_back(bar_span_y / (r.bars_side + 1) - r.bar_diameter);
      if (!(m.s_clear > 0))
        refuse_builder("Stirrup spacing", "must exceed the stirrup diameter");
      return mander_rectangular(m);
    }

    void
    rectangle_concrete(FibreGeometry &g, const RcRectangle &r, const unsigned int core,
                       const unsigned int cover)
    {
      const double h = r.depth / 2, b = r.width / 2, c = r.cover;
      const double pitch_y = (r.depth - 2 * c) / r.fibres_y, pitch_z = (r.width - 2 * c) / r.fibres_z;
      const unsigned int ny = strip_fibres(c, pitch_y), nz = strip_fibres(c, pitch_z);
      add_rect_patch(g, core, r.fibres_y, r.fibres_z, {-(h - c), -(b - c)}, {h - c, b - c});
      // the cover: full-width strips top and bottom, strips on the sides between them
      add_rect_patch(g, cover, ny, r.fibres_z + 2 * nz, {h - c, -b}, {h, b});
      add_rect_patch(g, cover, ny, r.fibres_z + 2 * nz, {-h, -b}, {-(h - c), b});
      add_rect_patch(g, cover, r.fibres_y, nz, {-(h - c), -b}, {h - c, -(b - c)});
      add_rect_patch(g, cover, r.fibres_y, nz, {-(h - c), b - c}, {h - c, b});
    }
  } // namespace

  FibreGeometry
  rc_rectangle(const RcRectangle &r)
  {
    builder_positive("Depth", r.depth);
    builder_positive("Width", r.width);
    builder_positive("Stirrup spacing", r.stirrup_spacing);
    check_concrete(r.concrete);
    check_steel(r.steel);
    if (r.bars_top < 2 || r.bars_bottom < 2)
      refuse_builder(r.bars_top < 2 ? "Bars top" : "Bars bottom",
                     "must be at least 2 (a bar in each corner)");
    if (r.legs_y < 2 || r.legs_z < 2)
      refuse_builder(r.legs_y < 2 ? "Stirrup legs along y" : "Stirrup legs along z",
                     "must be at least 2 (a closed stirrup)");
    if (r.fibres_y < 1 || r.fibres_z < 1)
      refuse_builder(r.fibres_y < 1 ? "Fibres across depth" : "Fibres across width",
                     "must be at least 1");
    const double o  = bar_offset(r.cover, r.stirrup_diameter, r.bar_diameter,
                                 std::min(r.depth, r.width),
                                 r.depth <= r.width ? "depth" : "width");
    const double yb = r.depth / 2 - o, zb = r.width / 2 - o; // the corner bars
    const unsigned int most_across = std::max(r.bars_top, r.bars_bottom);
    if (!(2 * zb / (most_across - 1) > r.bar_diameter && 2 * yb / (r.bars_side + 1) > r.bar_diameter))
      refuse_builder("Bar diameter", "adjacent bars overlap");
    FibreGeometry g;
    const ManderConfinement confined =
      r.concrete.confined ? rectangle_confinement(r, 2 * yb, 2 * zb) : ManderConfinement{};
    const unsigned int core  = g.add_material(core_material(r.concrete, r.concrete.confined ? &confined : nullptr));
    const unsigned int cover = g.add_material(cover_material(r.concrete));
    const unsigned int steel = g.add_material(bar_material(r.steel));
    rectangle_concrete(g, r, core, cover);
    const double area = builder_pi * r.bar_diameter * r.bar_diameter / 4;
    add_straight_layer(g, steel, r.bars_top, area, {yb, -zb}, {yb, zb});
    add_straight_layer(g, steel, r.bars_bottom, area, {-yb, -zb}, {-yb, zb});
    if (r.bars_side > 0)
      {
        const double step = 2 * yb / (r.bars_side + 1);
        for (const double z : {-zb, zb})
          add_straight_layer(g, steel, r.bars_side, area, {-yb + step, z}, {yb - step, z});
      }
    return g;
  }

  FibreGeometry
  rc_circle(const RcCircle &r)
  {
    builder_positive("Diameter", r.diameter);
    builder_positive("Stirrup spacing", r.spiral_pitch);
    check_concrete(r.concrete);
    check_steel(r.steel);
    if (r.bars < 3)
      refuse_builder("Bars", "must be at least 3");
    if (r.sectors < 1 || r.rings < 1)
      refuse_builder(r.sectors < 1 ? "Fibres round" : "Fibres across", "must be at least 1");
    const double o    = bar_offset(r.cover, r.spiral_diameter, r.bar_diameter, r.diameter, "diameter");
    if (!(2 * (r.diameter / 2 - o) * std::sin(builder_pi / r.bars) > r.bar_diameter))
      refuse_builder("Bar diameter", "adjacent bars overlap");
    const double area = builder_pi * r.bar_diameter * r.bar_diameter / 4;
    FibreGeometry     g;
    ManderConfinement confined;
    if (r.concrete.confined)
      {
        ManderCircularSection m;
        m.materials = {r.concrete.fc, r.concrete.eps_c0, r.steel.fy,
                       r.steel.ultimate_strain > 0 ? r.steel.ultimate_strain : 0.1};
        m.ds      = r.diameter - 2 * r.cover;
        m.s       = r.spiral_pitch;
        m.s_clear = r.spiral_pitch - r.spiral_diameter;
        m.Asp     = builder_pi * r.spiral_diameter * r.spiral_diameter / 4;
        m.rho_cc  = r.bars * area / (builder_pi * m.ds * m.ds / 4);
        m.spiral  = r.spiral;
        if (!(m.s_clear > 0))
          refuse_builder("Stirrup spacing", "must exceed the stirrup diameter");
        confined = mander_circular(m);
      }
    const unsigned int core  = g.add_material(core_material(r.concrete, r.concrete.confined ? &confined : nullptr));
    const unsigned int cover = g.add_material(cover_material(r.concrete));
    const unsigned int steel = g.add_material(bar_material(r.steel));
    const double R = r.diameter / 2, Rc = R - r.cover;
    add_circ_patch(g, core, r.sectors, r.rings, {0, 0}, 0, Rc);
    add_circ_patch(g, cover, r.sectors, strip_fibres(r.cover, Rc / r.rings), {0, 0}, Rc, R);
    add_circ_layer(g, steel, r.bars, area, {0, 0}, R - o);
    return g;
  }

  FibreGeometry
  steel_i_shape(const SteelIShape &s)
  {
    builder_positive("Depth", s.depth);
    builder_positive("Flange width", s.flange_width);
    builder_positive("Flange thickness", s.flange_thickness);
    builder_positive("Web thickness", s.web_thickness);
    if (!(2 * s.flange_thickness < s.depth))
      refuse_builder("Flange thickness", "the flanges leave no web: 2 tf >= d");
    if (!(s.web_thickness <= s.flange_width))
      refuse_builder("Web thickness", "must not exceed the flange width");
    if (s.flange_fibres_thickness < 1 || s.flange_fibres_width < 1 || s.web_fibres < 1)
      refuse_builder("Fibres along web", "each number of fibres must be at least 1");
    FibreGeometry      g;
    SectionMaterial    m = bar_material(s.steel);
    const unsigned int steel = g.add_material(m);
    const double h = s.depth / 2, hw = h - s.flange_thickness, b = s.flange_width / 2,
                 t = s.web_thickness / 2;
    add_rect_patch(g, steel, s.flange_fibres_thickness, s.flange_fibres_width, {hw, -b}, {h, b});
    add_rect_patch(g, steel, s.flange_fibres_thickness, s.flange_fibres_width, {-h, -b}, {-hw, b});
    add_rect_patch(g, steel, s.web_fibres, 1, {-hw, -t}, {hw, t});
    return g;
  }
} // namespace poundfe
