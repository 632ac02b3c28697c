// Fibre sections against references written here: a steel I-shape's
// plastic moment fy Z and elastic EI in closed form; an RC rectangle's first
// yield and ultimate moments against a strain-compatibility computation
// that integrates the same concrete law exactly over the depth (Gauss
// quadrature between the kinks of the law) instead of by fibres; the
// section tangent against central differences of the resultants; revert
// and clone; a circular patch's area and second moment; a square bent at
// 45 degrees; the plane and space sections about z; OpenSees's generators
// and the refusals of bad geometry; the typed runs of Concrete02 and Steel02
// fibres against one law per fibre, bit for bit.
#include <poundfe/base/exceptions.h>
#include <poundfe/laws/opensees_dead_bands.h>
#include <poundfe/sections/fibre_generators.h>
#include <poundfe/sections/fibre_section.h>
#include <poundfe/sections/moment_curvature.h>
#include <poundfe/sections/section_builders.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <functional>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

using namespace poundfe;

namespace
{
  const double pi = std::acos(-1.0);

  SteelIShape
  i_shape()
  {
    SteelIShape s;
    s.depth            = 0.30;
    s.flange_width     = 0.15;
    s.flange_thickness = 0.0107;
    s.web_thickness    = 0.0071;
    s.steel.law        = "ElasticPP";
    s.steel.fy         = 355e6;
    s.steel.E          = 210e9;
    s.steel.ultimate_strain = 0; // no rupture limit: the plastic plateau
    return s;
  }

  SectionVector
  vector_of(std::initializer_list<double> values)
  {
    SectionVector v(values.size());
    unsigned int  i = 0;
    for (const double x : values)
      v(i++) = x;
    return v;
  }

  /// InputError of `f` names `parameter`.
  void
  refuses(const std::function<void()> &f, const std::string &parameter)
  {
    try
      {
        f();
        BOOST_ERROR("no InputError for " + parameter);
      }
    catch (const InputError &e)
      {
        BOOST_TEST(e.parameter() == parameter);
      }
  }
} // namespace

BOOST_AUTO_TEST_CASE(steel_i_shape_plastic_moment_is_fy_z_and_elastic_stiffness_ei)
{
  const SteelIShape s = i_shape();
  FibreSection      section(steel_i_shape(s), 2);
  const double      d = s.depth, bf = s.flange_width, tf = s.flange_thickness,
               tw = s.web_thickness, hw = d - 2 * tf;
  // midpoint fibres of n equal strips of a rectangle b x t: b t^3/12 (1 - 1/n^2)
  const auto strips = [](const double b, const double t, const double n) {
    return b * t * t * t / 12 * (1 - 1 / (n * n));
  };
  const double I_fibres = 2 * (strips(bf, tf, 4) + bf * tf * std::pow((d - tf) / 2, 2)) +
                          strips(tw, hw, 16);
  BOOST_TEST(section.initial_tangent()(1, 1) == s.steel.E * I_fibres,
             boost::test_tools::tolerance(1e-13));
  BOOST_TEST(section.initial_tangent()(0, 0) == s.steel.E * (2 * bf * tf + tw * hw),
             boost::test_tools::tolerance(1e-13));

  // every fibre lies wholly on one side of the neutral axis: sum |y| A is Z
  const double Z = bf * tf * (d - tf) + tw * hw * hw / 4;
  MomentCurvatureSettings settings;
  settings.target_curvature = 2.0; // 1/m: the fibre nearest the axis, y = 8.9 mm, at 0.018
  settings.steps            = 50;
  settings.drop_fraction    = 0;
  const MomentCurvatureResult r = moment_curvature(section, settings);
  BOOST_TEST(r.stop_reason == "the target curvature");
  BOOST_TEST(r.ultimate.moment == s.steel.fy * Z, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(r.ultimate.tangent == 0.0); // every fibre on its plateau
  // first yield: the outer flange fibres, at kappa = eps_y / (d/2 - tf/8)
  BOOST_TEST(r.yielded);
  BOOST_TEST(r.first_yield.curvature == s.steel.fy / s.steel.E / (d / 2 - tf / 8),
             boost::test_tools::tolerance(1e-9));
}

namespace
{
  // The RC rectangle of the yield and ultimate test: b = 0.3, h = 0.5,
  // 3 + 3 bars of 20 mm, cover 40 mm to 10 mm stirrups, Concrete01
  // unconfined (Kent–Scott–Park to fc = 30 MPa at 0.002, zero at 0.005,
  // no tension), Steel01 bilinear fy = 420 MPa, E = 200 GPa, b = 0.01.
  RcRectangle
  hand_rectangle()
  {
    RcRectangle r;
    r.depth = 0.5;
    r.width = 0.3;
    r.cover = 0.04;
    r.bars_top = r.bars_bottom = 3;
    r.bar_diameter             = 0.020;
    r.stirrup_diameter         = 0.010;
    r.stirrup_spacing          = 0.10;
    r.concrete.law             = "Concrete01";
    r.concrete.confined        = false;
    r.concrete.crushing_strain = 0.0025;
    r.steel.law                = "Steel01";
    r.fibres_y                 = 40;
    return r;
  }

  double
  hand_concrete_stress(const double strain)
  {
    const double fc = 30e6, e0 = 0.002, esp = 0.005;
    if (strain >= 0)
      return 0;
    if (strain >= -e0)
      {
        const double eta = -strain / e0;
        return -fc * (2 * eta - eta * eta);
      }
    if (strain >= -esp)
      return -fc + (strain + e0) * fc / (e0 - esp);
    return 0;
  }

  double
  hand_steel_stress(const double strain)
  {
    const double fy = 420e6, E = 200e9, b = 0.01, ey = fy / E;
    if (std::abs(strain) <= ey)
      return E * strain;
    return (strain > 0 ? 1 : -1) * (fy + b * E * (std::abs(strain) - ey));
  }

  /// (N, M) of the strain eps0 - y phi over the whole section: the
  /// concrete by 3-point Gauss–Legendre between the depths where the strain
  /// crosses 0, -0.002 and -0.005 (there the stress is a polynomial of
  /// degree <= 2 in y, so the rule is exact), the bars as points.
  std::pair<double, double>
  hand_resultants(const double eps0, const double phi)
  {
    const double h = 0.5, b = 0.3;
    std::vector<double> cuts{-h / 2, h / 2};
    for (const double strain : {0.0, -0.002, -0.005})
      {
        const double y = (eps0 - strain) / phi;
        if (y > -h / 2 && y < h / 2)
          cuts.push_back(y);
      }
    std::sort(cuts.begin(), cuts.end());
    const double g[3] = {-std::sqrt(0.6), 0, std::sqrt(0.6)}, w[3] = {5. / 9, 8. / 9, 5. / 9};
    double N = 0, M = 0;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
      {
        const double mid = (cuts[k] + cuts[k + 1]) / 2, half = (cuts[k + 1] - cuts[k]) / 2;
        for (unsigned int q = 0; q < 3; ++q)
          {
            const double y = mid + half * g[q], f = b * half * w[q] * hand_concrete_stress(eps0 - y * phi);
            N += f;
            M -= f * y;
          }
      }
    const double yb = 0.25 - 0.04 - 0.005 - 0.010, As = 3 * pi * 0.02 * 0.02 / 4;
    for (const double y : {yb, -yb})
      {
        const double f = As * hand_steel_stress(eps0 - y * phi);
        N += f;
        M -= f * y;
      }
    return {N, M};
  }

  /// The curvature at which N = `axial` with the strain `strain` held at
  /// depth y (bisection), and the moment there.
  std::pair<double, double>
  hand_state(const double axial, const double strain, const double y)
  {
    const auto excess = [&](const double phi) {
      return hand_resultants(strain + y * phi, phi).first - axial;
    };
    // the first sign change on a grid: beyond the concrete's zero stress N
    // turns back
    double     low = 1e-6, high = low;
    const bool rising = excess(low) < 0;
    while ((excess(high) < 0) == rising && high < 1)
      {
        low = high;
        high += 1e-3;
      }
    for (int it = 0; it < 200; ++it)
      {
        const double phi = (low + high) / 2;
        ((excess(phi) < 0) == rising ? low : high) = phi;
      }
    const double phi = (low + high) / 2;
    return {phi, hand_resultants(strain + y * phi, phi).second};
  }
} // namespace

BOOST_AUTO_TEST_CASE(rc_rectangle_yield_and_ultimate_moments_match_strain_compatibility)
{
  const RcRectangle r = hand_rectangle();
  FibreSection      section(rc_rectangle(r), 2);
  MomentCurvatureSettings settings;
  settings.axial_force      = -300e3; // N, compression (0.067 fc b h)
  settings.target_curvature = 0.2;
  settings.steps            = 200;
  settings.drop_fraction    = 0;
  const MomentCurvatureResult result = moment_curvature(section, settings);

  // first yield: the bottom bars (y = -0.195) at +fy/E
  const auto yield = hand_state(settings.axial_force, 420e6 / 200e9, -0.195);
  BOOST_TEST(result.yielded);
  BOOST_TEST_MESSAGE("yield: fibres " << result.first_yield.moment << " hand " << yield.second);
  BOOST_TEST(result.first_yield.curvature == yield.first, boost::test_tools::tolerance(2e-3));
  BOOST_TEST(result.first_yield.moment == yield.second, boost::test_tools::tolerance(2e-3));

  // ultimate: the core's outermost fibre (40 across 0.42 m: its centre at
  // 0.25 - 0.04 - 0.42/80) reaches the crushing strain -0.0025, before the
  // cover spalls: the moment still rises, so no bar unloads and the hand
  // computation's envelope is the fibres' path. The tolerance 2e-3 covers
  // the midpoint rule of the fibres (0.0105 m) and the fibres near the
  // neutral axis that unload from compression as it rises (measured: 1e-4).
  const auto ultimate = hand_state(settings.axial_force, -0.0025, 0.25 - 0.04 - 0.42 / 80);
  BOOST_TEST(result.stop_reason == "core reached its strain limit");
  BOOST_TEST_MESSAGE("ultimate: fibres " << result.ultimate.moment << " hand " << ultimate.second);
  BOOST_TEST(result.ultimate.curvature == ultimate.first, boost::test_tools::tolerance(2e-3));
  BOOST_TEST(result.ultimate.moment == ultimate.second, boost::test_tools::tolerance(2e-3));
  BOOST_TEST(result.ductility() == ultimate.first / yield.first, boost::test_tools::tolerance(1e-2));
  // the axial force is held
  BOOST_TEST(section.resultant()(0) == settings.axial_force, boost::test_tools::tolerance(1e-6));
}

namespace
{
  RcRectangle
  confined_rectangle()
  {
    RcRectangle r;
    r.depth = 0.5;
    r.width = 0.4;
    r.cover = 0.04;
    r.bars_top = r.bars_bottom = 4;
    r.bars_side                = 2;
    r.bar_diameter             = 0.020;
    r.stirrup_diameter         = 0.010;
    r.stirrup_spacing          = 0.10;
    r.fibres_y                 = 12;
    r.fibres_z                 = 8;
    return r; // Concrete02 core by Mander, Concrete02 cover, Steel02 bars
  }

  /// Central differences of the resultants about the committed state of
  /// `section` at e, against its tangent there.
  void
  check_tangent(FibreSection &section, const SectionVector &e)
  {
    BOOST_TEST_REQUIRE(section.set_trial(e));
    const SectionMatrix k = section.tangent();
    const SectionVector scale = vector_of({1e-3, 1e-2, 1e-2, 1e-2}).head(e.size());
    for (unsigned int j = 0; j < e.size(); ++j)
      {
        const double  h  = 1e-6 * scale(j);
        SectionVector ep = e, em = e;
        ep(j) += h;
        em(j) -= h;
        BOOST_TEST_REQUIRE(section.set_trial(ep));
        const SectionVector sp = section.resultant();
        BOOST_TEST_REQUIRE(section.set_trial(em));
        const SectionVector fd = (sp - section.resultant()) / (2 * h);
        for (unsigned int i = 0; i < e.size(); ++i)
          BOOST_TEST(std::abs(fd(i) - k(i, j)) <=
                       1e-5 * std::sqrt(std::abs(k(i, i) * k(j, j))) + 1e-9,
                     "k(" << i << "," << j << ") = " << k(i, j) << ", differences " << fd(i));
      }
    BOOST_TEST_REQUIRE(section.set_trial(e));
  }
} // namespace

BOOST_AUTO_TEST_CASE(tangent_matches_central_differences_in_loading_and_unloading)
{
  for (const unsigned int n : {2u, 4u})
    {
      FibreSection section(rc_rectangle(confined_rectangle()), n, 1e8);
      const auto   deformation = [&](const double eps0, const double kz, const double ky) {
        return n == 2 ? vector_of({eps0, kz}) : vector_of({eps0, kz, ky, 1e-3});
      };
      // loading: past the bars' yield and the concrete's peak
      check_tangent(section, deformation(-3.1e-4, 0.0123, 0.0041));
      section.commit();
      check_tangent(section, deformation(-4.3e-4, 0.0297, 0.0107));
      section.commit();
      // unloading from there, then reloading the other way
      check_tangent(section, deformation(-3.7e-4, 0.0189, 0.0063));
      section.commit();
      check_tangent(section, deformation(-1.9e-4, -0.0113, -0.0037));
    }
}

BOOST_AUTO_TEST_CASE(revert_restores_bit_for_bit_and_clone_is_virgin)
{
  FibreSection section(rc_rectangle(confined_rectangle()), 4, 1e8);
  const SectionVector e1 = vector_of({-3e-4, 0.02, 0.005, 1e-3});
  const SectionVector e2 = vector_of({-1e-4, -0.01, 0.002, 0.0});
  BOOST_TEST_REQUIRE(section.set_trial(e1));
  section.commit();
  const SectionVector committed = section.resultant();
  const SectionMatrix tangent   = section.tangent();
  BOOST_TEST_REQUIRE(section.set_trial(e2));
  const SectionVector trial = section.resultant();
  section.revert();
  BOOST_TEST((section.resultant().array() == committed.array()).all());
  BOOST_TEST((section.tangent().array() == tangent.array()).all());
  BOOST_TEST((section.deformation().array() == e1.array()).all());
  BOOST_TEST_REQUIRE(section.set_trial(e2));
  BOOST_TEST((section.resultant().array() == trial.array()).all());

  // a clone knows nothing of the history: it answers as a new section
  const std::unique_ptr<SectionLaw> copy = section.clone();
  FibreSection fresh(rc_rectangle(confined_rectangle()), 4, 1e8);
  BOOST_TEST(copy->deformation().norm() == 0.0);
  BOOST_TEST(copy->resultant().norm() == 0.0);
  BOOST_TEST((copy->tangent().array() == fresh.initial_tangent().array()).all());
  BOOST_TEST_REQUIRE(copy->set_trial(e2));
  BOOST_TEST_REQUIRE(fresh.set_trial(e2));
  BOOST_TEST((copy->resultant().array() == fresh.resultant().array()).all());
  // and the section itself is untouched by the clone's trial
  BOOST_TEST((section.resultant().array() == trial.array()).all());
  section.reset();
  BOOST_TEST(section.resultant().norm() == 0.0);

  // a strain no law takes: the section refuses and names the first fibre
  BOOST_TEST(!section.set_trial(vector_of({std::nan(""), 0.0, 0.0, 0.0})));
  const std::string why = section.failure();
  BOOST_TEST(why.find("fibre 0 at (y, z) = (") == 0u, why);
  BOOST_TEST(why.find("material 'core' (Concrete02)") != std::string::npos, why);
  BOOST_TEST(why.find("not all finite") != std::string::npos, why);
}

BOOST_AUTO_TEST_CASE(circular_patch_area_and_second_moment)
{
  FibreGeometry g;
  const unsigned int m = g.add_material({"c", {"ElasticPP", {{"E", 1.0}, {"epsyP", 1.0}}}});
  const double r = 0.5;
  add_circ_patch(g, m, 36, 10, {0.1, -0.2}, 0, r);
  double area = 0, I = 0;
  for (const Fibre &f : g.fibres)
    {
      area += f.area;
      I += f.area * (f.y - 0.1) * (f.y - 0.1);
    }
  // annular sectors: the area is exact; the second moment of each sector
  // taken at its centroid misses its own, O((r/10)^2 + (2 pi r/36)^2)
  BOOST_TEST(area == pi * r * r, boost::test_tools::tolerance(1e-13));
  BOOST_TEST(I == pi * r * r * r * r / 4, boost::test_tools::tolerance(1e-2));
  FibreSection section(g, 2);
  BOOST_TEST(section.reference_y() == 0.1, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(section.reference_z() == -0.2, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(section.initial_tangent()(1, 1) == I, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(square_bent_at_45_degrees_has_equal_moments)
{
  FibreGeometry g;
  g.add_material({"concrete", {"Concrete02", {{"fpc", -30e6}, {"epsc0", -0.002}, {"fpcu", -6e6},
                                              {"epscu", -0.006}, {"ft", 3e6}, {"Ets", 1.5e9}}}});
  g.add_material({"steel", {"Steel02", {{"fy", 420e6}, {"E0", 200e9}, {"b", 0.01}}}});
  add_fibre_commands(g, "patch rect concrete 12 12 -0.2 -0.2 0.2 0.2\n"
                        "layer straight steel 3 3.1e-4 0.16 -0.16 0.16 0.16;"
                        "layer straight steel 3 3.1e-4 -0.16 -0.16 -0.16 0.16;"
                        "layer straight steel 1 3.1e-4 0 -0.16 0 -0.16; fiber 0 0.16 3.1e-4 steel");
  BOOST_TEST(g.fibres.size() == 144u + 8u);
  FibreSection            section(g, 4, 1e7);
  MomentCurvatureSettings settings;
  settings.axial_force      = -1e6;
  settings.angle            = 45;
  settings.target_curvature = 0.05;
  settings.steps            = 50;
  const MomentCurvatureResult r = moment_curvature(section, settings);
  BOOST_TEST(r.points.size() > 10u);
  for (const MomentCurvaturePoint &p : r.points)
    BOOST_TEST(std::abs(p.moment_y - p.moment_z) <= 1e-10 * r.peak.moment);

  // the plane section and the space one about z (angle 0) agree
  FibreSection plane(g, 2), space(g, 4, 1e7);
  settings.angle = 0;
  const MomentCurvatureResult r2 = moment_curvature(plane, settings);
  const MomentCurvatureResult r3 = moment_curvature(space, settings);
  BOOST_TEST_REQUIRE(r2.points.size() == r3.points.size());
  for (std::size_t i = 0; i < r2.points.size(); ++i)
    {
      BOOST_TEST(r2.points[i].moment == r3.points[i].moment, boost::test_tools::tolerance(1e-12));
      BOOST_TEST(r3.points[i].moment_y == 0.0, boost::test_tools::tolerance(1e-6));
    }
  BOOST_TEST((plane.tangent().block(0, 0, 2, 2).array() == space.tangent().block(0, 0, 2, 2).array()).all());
}

BOOST_AUTO_TEST_CASE(generators_follow_opensees_geometry)
{
  FibreGeometry g;
  g.add_material({"s", {"ElasticPP", {{"E", 1.0}, {"epsyP", 1.0}}}});
  // patch rect: nY along y first (i inner), quadrilateral cells at their centroids
  add_fibre_commands(g, "patch rect s 2 1 -1 -0.5 1 0.5");
  BOOST_TEST_REQUIRE(g.fibres.size() == 2u);
  BOOST_TEST(g.fibres[0].y == -0.5, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(g.fibres[1].y == 0.5, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(g.fibres[0].area == 1.0, boost::test_tools::tolerance(1e-14));
  // patch quad: a trapezoid in one cell, its centroid
  add_fibre_commands(g, "patch quad s 1 1  0 0  2 0  1 1  0 1");
  BOOST_TEST(g.fibres[2].area == 1.5, boost::test_tools::tolerance(1e-14));
  // the trapezoid (0,0) (2,0) (1,1) (0,1): the square [0,1]^2 and the triangle (1,0) (2,0) (1,1)
  BOOST_TEST(g.fibres[2].y == (1 * 0.5 + 0.5 * (4.0 / 3)) / 1.5, boost::test_tools::tolerance(1e-14));
  BOOST_TEST(g.fibres[2].z == (1 * 0.5 + 0.5 * (1.0 / 3)) / 1.5, boost::test_tools::tolerance(1e-14));
  // layer circ without angles: n bars 360/n apart from 0, none twice
  FibreGeometry c;
  c.add_material({"s", {"ElasticPP", {{"E", 1.0}, {"epsyP", 1.0}}}});
  add_fibre_commands(c, "layer circ s 4 1e-4 0 0 0.3");
  BOOST_TEST_REQUIRE(c.fibres.size() == 4u);
  BOOST_TEST(c.fibres[1].y == 0.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(c.fibres[1].z == 0.3, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(c.fibres[3].z == -0.3, boost::test_tools::tolerance(1e-12));
  // with angles 0 90: the ends included
  add_fibre_commands(c, "layer circ s 3 1e-4 0 0 0.3 0 90");
  BOOST_TEST(c.fibres[6].y == 0.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(c.fibres[5].y == 0.3 * std::cos(pi / 4), boost::test_tools::tolerance(1e-12));
  // layer straight: one bar at the midpoint
  add_fibre_commands(c, "layer straight s 1 2e-4 0 0 1 1");
  BOOST_TEST(c.fibres.back().y == 0.5);
  BOOST_TEST(c.fibres.back().area == 2e-4);
}

BOOST_AUTO_TEST_CASE(bad_geometry_is_refused_naming_the_parameter)
{
  FibreGeometry g;
  g.add_material({"s", {"ElasticPP", {{"E", 1.0}, {"epsyP", 1.0}}}});
  refuses([&] { add_fibre_commands(g, "patch rect s 2 2 0 0 1 1; fiber 0 0 -1e-4 s"); }, "Fibres");
  refuses([&] { add_fibre_commands(g, "patch quad s 1 1 0 0 0 1 1 1 1 0"); }, "Fibres"); // clockwise
  refuses([&] { add_fibre_commands(g, "patch rect s 0 2 0 0 1 1"); }, "Fibres");
  refuses([&] { add_fibre_commands(g, "patch rect t 2 2 0 0 1 1"); }, "Fibres");
  refuses([&] { add_fibre_commands(g, "patch circle s 2 2 0 0 1 1"); }, "Fibres");
  refuses([&] { FibreSection(FibreGeometry{g.materials, {}}, 2); }, "Fibres");

  RcRectangle r = confined_rectangle();
  r.cover       = 0.2; // half the width
  refuses([&] { rc_rectangle(r); }, "Cover");
  r       = confined_rectangle();
  r.cover = 0.004; // the stirrups stick out of the concrete
  refuses([&] { rc_rectangle(r); }, "Cover");
  r              = confined_rectangle();
  r.bar_diameter = 0.2; // the bars do not fit
  refuses([&] { rc_rectangle(r); }, "Bar diameter");
  r       = confined_rectangle();
  r.depth = 0;
  refuses([&] { rc_rectangle(r); }, "Depth");
  r                          = confined_rectangle();
  r.concrete.crushing_strain = 0.0015;
  refuses([&] { rc_rectangle(r); }, "Crushing strain");
  r                          = confined_rectangle();
  r.concrete.spalling_strain = 0.001;
  refuses([&] { rc_rectangle(r); }, "Spalling strain");
  SteelIShape s       = i_shape();
  s.flange_thickness  = 0.2;
  refuses([&] { steel_i_shape(s); }, "Flange thickness");
  RcCircle c;
  c.diameter = 0.6;
  c.cover    = 0.05;
  c.bars     = 8;
  c.bar_diameter    = 0.02;
  c.spiral_diameter = 0.01;
  c.spiral_pitch    = 0.08;
  FibreSection circle(rc_circle(c), 2); // a sound circle builds
  BOOST_TEST(circle.geometry().area() == pi * 0.09 + 8 * pi * 1e-4, boost::test_tools::tolerance(1e-12));
  c.cover = 0.3;
  refuses([&] { rc_circle(c); }, "Cover");
}


BOOST_AUTO_TEST_CASE(rc_circle_bends_alike_in_every_direction)
{
  // a Mander-confined circle: its curve at 30 degrees in space against the
  // plane one; 24 sectors and 10 bars are not quite axisymmetric (1 %), and
  // the events located inside steps restart Newton from committed states
  RcCircle c;
  c.diameter        = 0.6;
  c.cover           = 0.04;
  c.bars            = 10;
  c.bar_diameter    = 0.02;
  c.spiral_diameter = 0.01;
  c.spiral_pitch    = 0.08;
  FibreSection            plane(rc_circle(c), 2), space(rc_circle(c), 4, 1e8);
  MomentCurvatureSettings settings;
  settings.axial_force      = -1e6;
  settings.target_curvature = 0.1;
  settings.steps            = 100;
  const MomentCurvatureResult r2 = moment_curvature(plane, settings);
  settings.angle                 = 30;
  const MomentCurvatureResult r3 = moment_curvature(space, settings);
  BOOST_TEST(r2.stop_reason == r3.stop_reason);
  BOOST_TEST(r3.first_yield.moment == r2.first_yield.moment, boost::test_tools::tolerance(1e-2));
  BOOST_TEST(r3.peak.moment == r2.peak.moment, boost::test_tools::tolerance(1e-2));
  BOOST_TEST(r3.ultimate.curvature == r2.ultimate.curvature, boost::test_tools::tolerance(2e-2));
}


BOOST_AUTO_TEST_CASE(rc_circle_with_concrete02_tension_bends_to_the_core_strain_limit)
{
  // Mander's confined core has a high fpcu: with lambda = 0.1 Concrete02's
  // focus eps_R would lie in compression and its stress jump from
  // compression to tension near eps_R, so that the section lost its
  // equilibrium at a curvature ductility of about 1.2. The builder keeps
  // eps_R >= 0, and the curve goes on to the core's crushing strain, with
  // the tension stiffening adding moment before cracking only.
  RcCircle c;
  c.diameter        = 0.6;
  c.cover           = 0.04;
  c.bars            = 12;
  c.bar_diameter    = 0.025;
  c.spiral_diameter = 0.01;
  c.spiral_pitch    = 0.1;
  const FibreGeometry g = rc_circle(c);
  for (const SectionMaterial &m : g.materials)
    if (m.law.material == "Concrete02")
      {
        const std::map<std::string, double> &v = m.law.values;
        const double Ec0 = 2 * v.at("fpc") / v.at("epsc0"), lambda = v.at("lambda");
        const double eps_R = (v.at("fpcu") - lambda * Ec0 * v.at("epscu")) / (Ec0 * (1 - lambda));
        BOOST_TEST(eps_R >= -1e-15, m.name << ": eps_R = " << eps_R << ", lambda " << lambda);
      }
  MomentCurvatureSettings settings;
  settings.axial_force      = -1.5e6;
  settings.target_curvature = 0.15;
  settings.steps            = 300;
  FibreSection                section(g, 2);
  const MomentCurvatureResult with_tension = moment_curvature(section, settings);
  BOOST_TEST(with_tension.stop_reason == "core reached its strain limit");
  c.concrete.tensile_ratio = 0;
  FibreSection                no_tension_section(rc_circle(c), 2);
  const MomentCurvatureResult no_tension = moment_curvature(no_tension_section, settings);
  BOOST_TEST(no_tension.stop_reason == with_tension.stop_reason);
  BOOST_TEST(with_tension.ultimate.curvature == no_tension.ultimate.curvature,
             boost::test_tools::tolerance(0.02));
  BOOST_TEST(with_tension.ultimate.moment == no_tension.ultimate.moment,
             boost::test_tools::tolerance(0.02));
}

namespace
{
  /// A section whose fibres run by material as the section groups them: two
  /// runs of Concrete02 apart, Steel02 with isotropic hardening, Concrete01,
  /// Steel01 and ElasticPP (one law per fibre), some fibres on the axes (a
  /// change of curvature alone leaves their strain as it was); with
  /// `dead_band` every material OpenSees's dead band where it has one (as
  /// `poundfe opensees` makes them).
  FibreGeometry
  mixed_runs(const bool dead_band)
  {
    const std::vector<MaterialParameters> laws = {
      {"Concrete02",
       {{"fpc", -30e6}, {"epsc0", -0.002}, {"fpcu", -6e6}, {"epscu", -0.006}, {"lambda", 0.1},
        {"ft", 3e6}, {"Ets", 1.5e9}}},
      {"Steel02",
       {{"fy", 420e6}, {"E0", 200e9}, {"b", 0.01}, {"R0", 20}, {"cR1", 0.925}, {"cR2", 0.15},
        {"a1", 0.04}, {"a2", 1}, {"a3", 0.04}, {"a4", 1}}},
      {"Concrete01", {{"fpc", -30e6}, {"epsc0", -0.002}, {"fpcu", -6e6}, {"epscu", -0.006}}},
      {"Steel01", {{"fy", 420e6}, {"E0", 200e9}, {"b", 0.02}}},
      {"ElasticPP", {{"E", 200e9}, {"epsyP", 0.002}}}};
    FibreGeometry g;
    for (unsigned int m = 0; m < laws.size(); ++m)
      {
        SectionMaterial material{"m" + std::to_string(m), laws[m]};
        if (dead_band)
          material.law.values[opensees_dead_band_entry] = 1;
        g.add_material(material);
      }
    // runs: 0 0 0 0 0 0 1 1 1 1 2 2 2 3 3 4 4 0 0 0 0 0 1 1 ...
    const unsigned int pattern[] = {0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 3, 3, 4, 4, 0, 0, 0,
                                    0, 0, 1, 1, 3, 2, 0, 4};
    for (unsigned int i = 0; i < std::size(pattern); ++i)
      g.fibres.push_back({(i % 7) * 0.05 - 0.15, (i % 3) * 0.1 - 0.1, 1e-3 * (1 + i % 4),
                          pattern[i]});
    return g;
  }

  /// The section's state determination written again the plain way: one
  /// law per fibre, each fibre's trial through the law's own set_trial, the
  /// sums in the fibres' order (the section before its runs).
  struct OneLawPerFibre
  {
    OneLawPerFibre(const FibreGeometry &g, const unsigned int n)
      : g(g)
      , m(n == 4 ? 3 : 2)
      , y_ref(g.centroid_y())
      , z_ref(g.centroid_z())
    {
      for (const Fibre &f : g.fibres)
        laws.push_back(make_material(g.materials[f.material].law));
    }
    bool
    set_trial(const SectionVector &e)
    {
      s = SectionVector::Zero(m);
      k = SectionMatrix::Zero(m, m);
      for (unsigned int i = 0; i < laws.size(); ++i)
        {
          const Fibre &f      = g.fibres[i];
          const double a[3]   = {1, -(f.y - y_ref), f.z - z_ref};
          double       strain = e(0) - (f.y - y_ref) * e(1);
          if (m == 3)
            strain += (f.z - z_ref) * e(2);
          if (!laws[i]->set_trial(strain, 0))
            return false;
          const double force = laws[i]->force() * f.area, stiffness = laws[i]->tangent() * f.area;
          for (unsigned int r = 0; r < m; ++r)
            {
              s(r) += force * a[r];
              for (unsigned int c = 0; c < m; ++c)
                k(r, c) += stiffness * a[r] * a[c];
            }
        }
      return true;
    }

    const FibreGeometry                       &g;
    const unsigned int                         m;
    const double                               y_ref, z_ref;
    std::vector<std::unique_ptr<UniaxialLaw>> laws;
    SectionVector                              s;
    SectionMatrix                              k;
  };
} // namespace

// The section's typed runs (Concrete02 and Steel02 fibres' states in one
// array per run, evaluated in one call) against one law per fibre, written
// in the test: the resultants, the tangent and every fibre's stress bit for
// bit (tolerance 0: the same operations in the same order) after every
// trial, commit and revert, over a walk of loading, unloading and reloading
// with trials a few round-offs from the committed state and from the last
// trial (inside OpenSees's dead bands), a first strain of 1e-16, and every
// third step reverted, plane and space, with and without the dead bands.
BOOST_AUTO_TEST_CASE(typed_runs_give_the_bits_of_one_law_per_fibre)
{
  for (const bool dead_band : {false, true})
    for (const unsigned int n : {2u, 4u})
      {
        const FibreGeometry g = mixed_runs(dead_band);
        FibreSection        section(g, n, n == 4 ? 1e6 : 0.0);
        OneLawPerFibre      reference(g, n);
        SectionVector       e = SectionVector::Zero(n), committed = e;
        const auto same_stresses = [&]() {
          for (unsigned int i = 0; i < g.fibres.size(); ++i)
            BOOST_TEST(section.fibre_stress(i) == reference.laws[i]->force());
        };
        for (unsigned int step = 0; step < 60; ++step)
          {
            const double t = 0.2 * step;
            for (unsigned int trial = 0; trial < 4; ++trial)
              {
                if (step == 0)
                  e(0) = trial * 1e-16;
                else if (trial == 0)
                  {
                    e = committed; // a few round-offs from the committed state
                    e(1) += 1e-18;
                  }
                else if (trial < 3)
                  {
                    e(0) = 4e-4 * std::sin(t) - 2e-4 + 1e-4 * trial;
                    e(1) = 0.03 * std::sin(1.3 * t) * (1 + 0.1 * trial);
                    if (n == 4)
                      e(2) = 0.02 * std::cos(0.7 * t);
                  }
                else
                  e(1) += 1e-18; // a few round-offs from the last trial
                const bool accepted = section.set_trial(e);
                BOOST_TEST_REQUIRE(accepted == reference.set_trial(e));
                for (unsigned int r = 0; r < reference.m; ++r)
                  {
                    BOOST_TEST(section.resultant()(r) == reference.s(r));
                    for (unsigned int c = 0; c < reference.m; ++c)
                      BOOST_TEST(section.tangent()(r, c) == reference.k(r, c));
                  }
                same_stresses();
              }
            if (step % 3 == 2)
              {
                section.revert();
                for (const auto &law : reference.laws)
                  law->revert();
              }
            else
              {
                section.commit();
                for (const auto &law : reference.laws)
                  law->commit();
                committed = e;
              }
            same_stresses();
          }
      }
}
