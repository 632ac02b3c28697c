// The limit states of fibre sections (output/section_limits.h) against
// closed forms written here:
//   - an RC rectangle under an imposed curvature ramp kappa(t) = r t at
//     eps0 = 0: by strain compatibility a bar at y_b (from the section's
//     centre: half the depth less the cover, half a stirrup and half a bar)
//     strains -y_b kappa, so the bars yield at t_y = (fy / E) / (y_b r) and
//     reach 0.6 eps_su at t_f = 0.6 eps_su / (y_b r); the extreme concrete
//     fibre (at its fibre's centroid y_c) reaches -0.004 at 0.004 / (y_c r);
//     the ratios at the end are the strains over the limits;
//   - two ElasticPP bars at +-0.2 m: at N = 0 the neutral axis is the
//     centre by symmetry, so the first yield curvature is (fy / E) / 0.2
//     either way;
//   - the curvature ductility against yield curvatures that change between
//     the states observed (a pushover following the axial force): each
//     state's curvature over the yield curvature set when it was observed,
//     the largest of them, not the peak curvature over the last one;
//   - the Section limits entries: a wrong sign, zero or a word is refused
//     naming the entry;
//   - a moment-curvature stopped at the yield strain holds the whole
//     curve's first points exactly (the yield curvature read from them is
//     the same), and the yield curvature moves with N no more than the
//     elastic bound of SectionLimitStates' tolerance (stated there).
#include <poundfe/base/exceptions.h>
#include <poundfe/output/section_limit_states.h>
#include <poundfe/output/section_limits.h>
#include <poundfe/sections/moment_curvature.h>
#include <poundfe/sections/section_builders.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <string>

using namespace poundfe;

namespace
{
  RcRectangle
  column()
  {
    RcRectangle r;
    r.depth = r.width = 0.4;
    r.cover            = 0.04;
    r.bars_top = r.bars_bottom = 3;
    r.bar_diameter             = 0.02;
    r.stirrup_diameter         = 0.01;
    r.stirrup_spacing          = 0.1;
    r.concrete.fc              = 30e6;
    r.steel.fy                 = 450e6;
    r.steel.E                  = 200e9;
    r.steel.ultimate_strain    = 0.1;
    r.fibres_y                 = 10;
    r.fibres_z                 = 2;
    return r;
  }

  SectionVector
  curvature(const double kappa)
  {
    SectionVector e(2);
    e << 0, kappa;
    return e;
  }
} // namespace

BOOST_AUTO_TEST_CASE(bar_yield_spalling_and_fracture_of_an_imposed_curvature)
{
  FibreSection           section(rc_rectangle(column()), 2);
  SectionLimitParameters parameters; // Priestley et al.'s defaults
  SectionLimitTracker    tracker(section, section_strain_limits(section, parameters));
  const double yb = 0.2 - 0.04 - 0.005 - 0.01; // the bars' centres from the middle
  double       yc = 0;                          // the extreme concrete fibre's centroid
  const FibreGeometry &g = section.geometry();
  for (unsigned int i = 0; i < g.fibres.size(); ++i)
    if (g.materials[g.fibres[i].material].role() == MaterialRole::concrete)
      yc = std::max(yc, g.fibres[i].y - section.reference_y());
  const double rate = 0.1, dt = 0.013; // 1/m per s; steps that do not land on the events
  for (double t = 0; t < 4.5; t += dt)
    {
      BOOST_REQUIRE(section.set_trial(curvature(rate * t)));
      section.commit();
      tracker.observe(section, t);
    }
  const double ey = 450e6 / 200e9;
  BOOST_CHECK_CLOSE(tracker.limits().strain[unsigned(SectionLimit::bar_yield)], ey, 1e-12);
  BOOST_CHECK_CLOSE(tracker.first_time(SectionLimit::bar_yield), ey / (yb * rate), 1e-6);
  BOOST_CHECK_CLOSE(tracker.first_time(SectionLimit::spalling), 0.004 / (yc * rate), 1e-6);
  BOOST_CHECK_CLOSE(tracker.limits().strain[unsigned(SectionLimit::bar_fracture)], 0.06, 1e-12);
  BOOST_CHECK_CLOSE(tracker.first_time(SectionLimit::bar_fracture), 0.06 / (yb * rate), 1e-6);
  const double kappa = tracker.peak_curvature_positive();
  BOOST_CHECK_CLOSE(tracker.ratio(SectionLimit::bar_yield), yb * kappa / ey, 1e-6);
  BOOST_CHECK_CLOSE(tracker.ratio(SectionLimit::spalling), yc * kappa / 0.004, 1e-6);
  // fracture is the worst of the limits reached
  BOOST_CHECK_EQUAL(std::string(damage_state_name(tracker.worst_limit())), "fracture");
}

BOOST_AUTO_TEST_CASE(ductility_against_the_yield_curvature_of_each_state)
{
  FibreSection           section(rc_rectangle(column()), 2);
  SectionLimitParameters parameters;
  SectionLimitTracker    tracker(section, section_strain_limits(section, parameters));
  const auto at = [&](const double kappa, const double yield_up, const double yield_down,
                      const double t) {
    tracker.set_yield_curvatures(yield_up, yield_down);
    BOOST_REQUIRE(section.set_trial(curvature(kappa)));
    section.commit();
    tracker.observe(section, t);
  };
  // kappa / kappa_y of each state: 0.5, 1.5 (bending the other way), 1.2
  // (the peak curvature), 2.2 (the largest), 0.04; measured against the
  // last yield curvatures alone it would be max(0.012, 0.006) / 0.05 = 0.24
  at(0.010, 0.020, 0.015, 0);
  at(-0.006, 0.020, 0.004, 1);
  at(0.012, 0.010, 0.004, 2);
  at(0.011, 0.005, 0.004, 3);
  at(0.002, 0.050, 0.050, 4);
  BOOST_CHECK_CLOSE(tracker.curvature_ductility(), 0.011 / 0.005, 1e-12);
  BOOST_CHECK_EQUAL(tracker.peak_curvature_positive(), 0.012);
  BOOST_CHECK_EQUAL(tracker.limits().yield_curvature_positive, 0.05);
}

BOOST_AUTO_TEST_CASE(a_given_crushing_strain_applies_to_concrete_without_a_core)
{
  // Concrete01 fibres without min= (no core) at +-0.2 m: with Crushing
  // strain = -0.01 the fibre at +0.2 m reaches it at kappa = 0.05, t = 0.5 s
  FibreGeometry   g;
  SectionMaterial concrete;
  concrete.name = "concrete";
  concrete.law  = {"Concrete01", {{"fpc", -30e6}, {"epsc0", -0.002}, {"fpcu", -6e6},
                                  {"epscu", -0.006}}};
  g.add_material(concrete);
  g.fibres = {{0.2, 0, 0.01, 0}, {-0.2, 0, 0.01, 0}};
  FibreSection section(g, 2);
  InputFile    input;
  SectionLimitParameters parameters;
  BOOST_CHECK(std::isnan(section_strain_limits(section, parameters)
                           .strain[unsigned(SectionLimit::crushing)])); // nothing to check
  parameters.crushing_text = "-0.01";
  parameters.finalize(input);
  SectionLimitTracker tracker(section, section_strain_limits(section, parameters));
  for (double t = 0; t < 0.8; t += 0.013)
    {
      BOOST_REQUIRE(section.set_trial(curvature(0.1 * t)));
      section.commit();
      tracker.observe(section, t);
    }
  BOOST_CHECK_CLOSE(tracker.first_time(SectionLimit::crushing), 0.5, 1e-6);
  BOOST_CHECK(std::isnan(tracker.ratio(SectionLimit::bar_yield))); // no bars
  BOOST_CHECK(std::isnan(tracker.curvature_ductility()));
}

BOOST_AUTO_TEST_CASE(first_yield_curvature_of_symmetric_bars)
{
  FibreGeometry   g;
  SectionMaterial steel;
  steel.name = "steel";
  steel.law  = {"ElasticPP", {{"E", 200e9}, {"epsyP", 450e6 / 200e9}}};
  g.add_material(steel);
  g.fibres = {{0.2, 0, 1e-3, 0}, {-0.2, 0, 1e-3, 0}};
  const FibreSection section(g, 2);
  const double       ey = 450e6 / 200e9;
  for (const int sense : {+1, -1})
    BOOST_CHECK_CLOSE(section_yield_curvature(section, 0, ey, sense), ey / 0.2, 1e-6);
}

BOOST_AUTO_TEST_CASE(a_curve_stopped_at_the_yield_strain_is_the_whole_curves_start)
{
  // section_yield_curvature reads kappa_y from the points up to the first
  // one past eps_y: a curve stopped there must hold exactly those points
  const double ey = 450e6 / 200e9;
  FibreSection full_section(rc_rectangle(column()), 2), stopped_section(rc_rectangle(column()), 2);
  MomentCurvatureSettings settings;
  settings.axial_force      = -4e5;
  settings.target_curvature = 10 * 2.1 * ey / 0.4;
  settings.steps            = 400;
  settings.drop_fraction    = 0;
  const MomentCurvatureResult full = moment_curvature(full_section, settings);
  settings.stop_steel_strain       = ey;
  const MomentCurvatureResult stopped = moment_curvature(stopped_section, settings);
  const auto steel = [](const MomentCurvaturePoint &p) {
    return std::max(p.steel_strain_max, -p.steel_strain_min);
  };
  const auto &p = stopped.points;
  BOOST_REQUIRE(p.size() >= 2 && p.size() < full.points.size() / 4);
  BOOST_CHECK(steel(p.back()) >= ey && steel(p[p.size() - 2]) < ey);
  for (unsigned int k = 0; k < p.size(); ++k)
    {
      BOOST_CHECK_EQUAL(p[k].curvature, full.points[k].curvature);
      BOOST_CHECK_EQUAL(p[k].moment, full.points[k].moment);
      BOOST_CHECK_EQUAL(steel(p[k]), steel(full.points[k]));
    }
}

BOOST_AUTO_TEST_CASE(yield_curvature_moves_less_than_the_axial_force_tolerance)
{
  // SectionLimitStates finds kappa_y again once N has moved by more than
  // d = yield_force_tolerance x EA eps_y, so that kappa_y stays within 1e-3
  // of the current N's. An uncracked elastic section's kappa_y = (eps_y - N
  // / EA) / y_s moves by d / (EA eps_y - N) of itself; the RC column,
  // cracked at yield, from high compression to tension, more (measured up
  // to 5.3 times): within 1e-3 all the same
  const double       ey = 450e6 / 200e9;
  const FibreSection section(rc_rectangle(column()), 2);
  const double       ea = section_axial_stiffness(section);
  const double       d  = SectionLimitStates::yield_force_tolerance * ea * ey;
  double             worst = 0;
  for (const double n : {-1.5e6, -8e5, -4e5, -1e5, 0.0, 1e5})
    for (const int sense : {+1, -1})
      {
        const double at    = section_yield_curvature(section, n, ey, sense);
        const double moved = section_yield_curvature(section, n - d, ey, sense);
        const double bound = d / (ea * ey - n);
        worst              = std::max(worst, std::abs(moved / at - 1) / bound);
        BOOST_CHECK_LE(std::abs(moved / at - 1), 1e-3);
      }
  BOOST_TEST_MESSAGE("largest change of kappa_y over its elastic bound: " << worst);
  BOOST_CHECK_LE(worst, 10); // the sensitivity the tolerance was chosen for
}

BOOST_AUTO_TEST_CASE(limits_of_the_wrong_sign_are_refused)
{
  InputFile input;
  input.file = "limits.prm";
  const auto refused = [&](SectionLimitParameters p, const std::string &entry) {
    try
      {
        p.finalize(input);
        BOOST_ERROR("no InputError for " + entry);
      }
    catch (const InputError &e)
      {
        BOOST_CHECK_EQUAL(e.parameter(), "Section limits/" + entry);
      }
  };
  SectionLimitParameters p;
  p.spalling_strain = 0.004;
  refused(p, "Spalling strain");
  p = {};
  p.crushing_text = "0.02";
  refused(p, "Crushing strain");
  p = {};
  p.yield_text = "0";
  refused(p, "Bar yield strain");
  p = {};
  p.fracture_text = "-0.05";
  refused(p, "Bar fracture strain");
  p = {};
  p.fracture_text = "big";
  refused(p, "Bar fracture strain");
  p = {};
  p.crushing_text = "-0.018";
  p.finalize(input);
  BOOST_CHECK_EQUAL(p.crushing_strain, -0.018);
}

BOOST_AUTO_TEST_CASE(first_yield_curvatures_about_both_axes_in_space)
{
  // four ElasticPP bars at (y, z) = (+-0.2, +-0.15): at N = 0 the neutral
  // axes are the centre's by symmetry, so a bar first yields at kappa_z =
  // (fy / E) / 0.2 bending about z and at kappa_y = (fy / E) / 0.15 about
  // y, either way; a section read about the wrong axis gives the other
  FibreGeometry   g;
  SectionMaterial steel;
  steel.name = "steel";
  steel.law  = {"ElasticPP", {{"E", 200e9}, {"epsyP", 450e6 / 200e9}}};
  g.add_material(steel);
  g.fibres = {{0.2, 0.15, 1e-3, 0}, {-0.2, 0.15, 1e-3, 0}, {0.2, -0.15, 1e-3, 0},
              {-0.2, -0.15, 1e-3, 0}};
  const FibreSection section(g, 4, 1e6);
  const double       ey = 450e6 / 200e9;
  for (const int sense : {+1, -1})
    {
      BOOST_CHECK_CLOSE(section_yield_curvature(section, 0, ey, sense), ey / 0.2, 1e-6);
      BOOST_CHECK_CLOSE(section_yield_curvature(section, 0, ey, sense, BendingAxis::y), ey / 0.15,
                        1e-6);
    }
}

BOOST_AUTO_TEST_CASE(yield_curvature_about_y_of_an_rc_section_turned_a_quarter)
{
  // the beam's RC rectangle (4 bars on top, 3 below: its yield curvatures
  // differ with the sense) turned a quarter about the member axis, each
  // fibre (y, z) to (y', z') = (z, -y): its strain under kappa_y, eps0 +
  // z' kappa_y = eps0 - y kappa_y, is the original's under kappa_z = kappa_y,
  // so its first yield about y, either way, is the original's about z, at
  // any N (the moment-curvature engine finds both)
  RcRectangle beam = column();
  beam.depth       = 0.5;
  beam.width       = 0.3;
  beam.bars_top    = 4;
  beam.bars_bottom = 3;
  const FibreGeometry g = rc_rectangle(beam);
  FibreGeometry       turned = g;
  for (Fibre &f : turned.fibres)
    f = {f.z, -f.y, f.area, f.material};
  const FibreSection section(g, 4, 1e6), quarter(turned, 4, 1e6);
  const double       ey = 450e6 / 200e9;
  for (const double n : {-8e5, 0.0})
    {
      const double up   = section_yield_curvature(section, n, ey, +1);
      const double down = section_yield_curvature(section, n, ey, -1);
      BOOST_CHECK_GT(std::abs(up / down - 1), 1e-3); // the two senses differ
      BOOST_CHECK_CLOSE(section_yield_curvature(quarter, n, ey, +1, BendingAxis::y), up, 1e-9);
      BOOST_CHECK_CLOSE(section_yield_curvature(quarter, n, ey, -1, BendingAxis::y), down, 1e-9);
    }
}

BOOST_AUTO_TEST_CASE(ductility_about_each_axis_of_a_section_in_space)
{
  // an imposed (eps0, kappa_z, kappa_y, theta) path on a section in space:
  // the tracker's peaks about y are the path's, its ductility about y the
  // largest kappa_y / kappa_y+ or -kappa_y / kappa_y-, about z likewise, and
  // its curvature ductility the larger of the two
  FibreSection        section(rc_rectangle(column()), 4, 1e6);
  SectionLimitTracker tracker(section, section_strain_limits(section, SectionLimitParameters()));
  BOOST_CHECK(tracker.in_space());
  tracker.set_yield_curvatures(0.010, 0.012);
  tracker.set_yield_curvatures_y(0.008, 0.009);
  const double path[][2] = {{0.002, -0.004}, {-0.006, 0.012}, {0.009, -0.018}, {0.001, 0.0}};
  for (unsigned int k = 0; k < 4; ++k)
    {
      SectionVector e(4);
      e << 0, path[k][0], path[k][1], 0;
      BOOST_REQUIRE(section.set_trial(e));
      section.commit();
      tracker.observe(section, k);
    }
  BOOST_CHECK_EQUAL(tracker.peak_curvature_y_positive(), 0.012);
  BOOST_CHECK_EQUAL(tracker.peak_curvature_y_negative(), -0.018);
  BOOST_CHECK_CLOSE(tracker.curvature_ductility_z(), std::max(0.009 / 0.010, 0.006 / 0.012), 1e-12);
  BOOST_CHECK_CLOSE(tracker.curvature_ductility_y(), std::max(0.012 / 0.008, 0.018 / 0.009), 1e-12);
  BOOST_CHECK_CLOSE(tracker.curvature_ductility(), 0.018 / 0.009, 1e-12);
}
