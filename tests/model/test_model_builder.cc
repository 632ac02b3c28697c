// Generated frames, shear buildings and placement, checked against counts
// and positions worked out by hand.
#define BOOST_TEST_MODULE model
#include <poundfe/base/exceptions.h>
#include <poundfe/model/model_builder.h>

#include "test_utilities.h"

using namespace poundfe;

BOOST_AUTO_TEST_CASE(frame_and_shear_building_side_by_side)
{
  InputParameters p = poundfe_test::shear_building_input(2, 1000, 5e6, 0);
  p.buildings.resize(2);
  BuildingParameters &frame = p.buildings[0];
  frame                     = BuildingParameters();
  frame.name                = "F";
  frame.type                = "frame";
  frame.n_storeys           = 3;
  frame.n_bays              = 2;
  frame.bay_widths          = {5.0, 7.0};
  frame.storey_heights      = {4.0, 3.0, 3.0};
  frame.floor_masses        = {3000};
  BuildingParameters &shear = p.buildings[1];
  shear                     = poundfe_test::shear_building_input(2, 1000, 5e6, 0).buildings[0];
  shear.drawing_width       = 2.0;
  p.separations             = {0.1};
  const Model model         = build_model(p);

  BOOST_TEST(model.buildings.size() == 2u);
  // frame: 3 lines x 4 levels; shear: base + 2 floors
  BOOST_TEST(model.buildings[0].n_nodes == 12u);
  BOOST_TEST(model.buildings[1].n_nodes == 3u);
  BOOST_TEST(model.members.size() == 3u * 3u + 2u * 3u);
  BOOST_TEST(model.links.size() == 2u);
  BOOST_TEST(model.buildings[0].right == 12.0);
  BOOST_TEST(model.buildings[1].left == 12.1, boost::test_tools::tolerance(1e-12));
  // equations: frame 9 free nodes x 3, shear 2 floors x ux
  BOOST_TEST(model.n_equations() == 27u + 2u);
  BOOST_TEST(model.buildings[0].floors[0].storey_height == 4.0);
  BOOST_TEST(model.buildings[0].floors[2].level == 10.0);
  BOOST_TEST(model.total_mass(0) == 9000.0);
  BOOST_TEST(model.total_mass(1) == 2000.0);
  const auto range = model.equation_range(1);
  BOOST_TEST(range[0] == 27u);
  BOOST_TEST(range[1] == 29u);
}

BOOST_AUTO_TEST_CASE(pinned_base_frees_base_rotations)
{
  InputParameters p = poundfe_test::shear_building_input(1, 1000, 5e6, 0);
  p.buildings[0]            = BuildingParameters();
  p.buildings[0].type       = "frame";
  p.buildings[0].name       = "F";
  p.buildings[0].base_fixity = "pinned";
  const Model model = build_model(p);
  // 2 base nodes keep rz, 2 top nodes have 3 DOFs each
  BOOST_TEST(model.n_equations() == 2u + 6u);
}

BOOST_AUTO_TEST_CASE(elements_per_member_subdivide_members)
{
  InputParameters p = poundfe_test::shear_building_input(1, 1000, 5e6, 0);
  p.buildings[0]                     = BuildingParameters();
  p.buildings[0].type                = "frame";
  p.buildings[0].name                = "F";
  p.buildings[0].elements_per_member = 4;
  const Model model = build_model(p);
  BOOST_TEST(model.members.size() == 12u);
  BOOST_TEST(model.n_nodes() == 4u + 9u);
  BOOST_TEST(model.buildings[0].floors[0].nodes.size() == 2u); // joints only
}
