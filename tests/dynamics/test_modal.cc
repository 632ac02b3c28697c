// Modal analysis against the closed-form three-storey shear building
// (doc/theory.md §1: 5.0085, 14.0335, 20.2789 Hz, quoted to 4 decimals, so the
// tolerance is 1e-5 relative), and a frame with very stiff beams and axially
// rigid columns, whose storey stiffness tends to n_columns * 12 EI / h^3.
#include <poundfe/input/engine_parameters.h>
#include <poundfe/dynamics/analysis.h>

#include <cmath>
#include <numeric>

#include "test_utilities.h"

using namespace poundfe;

BOOST_AUTO_TEST_CASE(three_storey_shear_building_frequencies)
{
  const Analysis a = prepare_analysis(poundfe_test::shear_building_input(3, 1000, 5e6, 0));
  const double   reference[3] = {5.0085, 14.0335, 20.2789};
  BOOST_REQUIRE(a.modes.n_modes() == 3u);
  for (unsigned int i = 0; i < 3; ++i)
    BOOST_TEST(a.modes.frequency(i) == reference[i], boost::test_tools::tolerance(1e-5));
  const double sum = std::accumulate(a.modes.participating_mass_ratio.begin(),
                                     a.modes.participating_mass_ratio.end(), 0.0);
  BOOST_TEST(sum == 1.0, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(frame_with_rigid_beams_tends_to_the_shear_building)
{
  // Two columns per storey with 2 * 12 EI / h^3 = 5e6 N/m, 1000 kg per floor.
  const double    h  = 3.0;
  const double    EI = 5e6 * h * h * h / 24;
  InputParameters p  = poundfe_test::shear_building_input(3, 1000, 5e6, 0);
  BuildingParameters &b    = p.model.buildings[0];
  b                        = BuildingParameters();
  b.name                   = "F";
  b.type                   = BuildingType::frame;
  b.n_storeys              = 3;
  b.storey_heights         = {h};
  b.column_youngs_modulus  = {1.0};
  b.column_second_moment   = {EI};
  b.column_area            = {1e6 * EI};  // axially rigid
  b.beam_youngs_modulus    = {1.0};
  b.beam_second_moment     = {1e6 * EI};  // flexurally rigid
  b.beam_area              = {1e6 * EI};
  b.floor_masses           = {1000};
  b.damping_type           = RayleighDamping::Kind::none;
  p.output.n_modes                = 3;
  const Analysis a         = prepare_analysis(p);
  const double   reference[3] = {5.0085, 14.0335, 20.2789};
  // The remaining beam and column flexibility is ~1e-6 relative; the
  // reference has 4 decimals.
  for (unsigned int i = 0; i < 3; ++i)
    BOOST_TEST(a.modes.frequency(i) == reference[i], boost::test_tools::tolerance(2e-5));
}

BOOST_AUTO_TEST_CASE(single_storey_frequency_is_sqrt_k_over_m)
{
  const Analysis a = prepare_analysis(poundfe_test::shear_building_input(1, 2500, 8e6, 0));
  BOOST_TEST(a.modes.omega[0] == std::sqrt(8e6 / 2500), boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(rigid_hinges_leave_the_modes_of_the_elastic_frame)
{
  // A hinge is a rotational spring in series with the member end: as its
  // stiffness grows the frame tends to the one without hinges.
  InputParameters hinged = read_parameters("input/three-storey-frame-hinges.prm");
  InputParameters plain  = read_parameters("input/three-storey-frame.prm");
  const Analysis  elastic = prepare_analysis(plain);
  double          previous_error = 1;
  for (const double factor : {10.0, 1e3, 1e5})
    {
      hinged.model.buildings[0].hinge_stiffness_factor = factor;
      const Analysis a = prepare_analysis(hinged);
      const double   error =
        std::abs(a.modes.frequency(0) - elastic.modes.frequency(0)) / elastic.modes.frequency(0);
      BOOST_TEST_MESSAGE("factor " << factor << ": first-mode difference " << error);
      BOOST_TEST(a.modes.frequency(0) < elastic.modes.frequency(0)); // springs soften
      BOOST_TEST(error < previous_error);
      previous_error = error;
    }
  BOOST_TEST(previous_error < 1e-4); // ~ 1/factor
}
