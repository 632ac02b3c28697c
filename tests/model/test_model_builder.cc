// Generated frames, shear buildings and placement, checked against counts
// and positions worked out by hand.
#include <poundfe/base/exceptions.h>
#include <poundfe/model/floor_mass.h>
#include <poundfe/model/model_builder.h>

#include "test_utilities.h"

using namespace poundfe;

BOOST_AUTO_TEST_CASE(frame_and_shear_building_side_by_side)
{
  InputParameters p = poundfe_test::shear_building_input(2, 1000, 5e6, 0);
  p.model.buildings.resize(2);
  BuildingParameters &frame = p.model.buildings[0];
  frame                     = BuildingParameters();
  frame.name                = "F";
  frame.type                = BuildingType::frame;
  frame.n_storeys           = 3;
  frame.n_bays              = 2;
  frame.bay_widths          = {5.0, 7.0};
  frame.storey_heights      = {4.0, 3.0, 3.0};
  frame.floor_masses        = {3000};
  BuildingParameters &shear = p.model.buildings[1];
  shear                     = poundfe_test::shear_building_input(2, 1000, 5e6, 0).model.buildings[0];
  shear.drawing_width       = 2.0;
  p.model.separations             = {0.1};
  const Model model         = build_model(p.model, p.contact, p);

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
  p.model.buildings[0]            = BuildingParameters();
  p.model.buildings[0].type       = BuildingType::frame;
  p.model.buildings[0].name       = "F";
  p.model.buildings[0].base_fixity = BaseFixity::pinned;
  const Model model = build_model(p.model, p.contact, p);
  // 2 base nodes keep rz, 2 top nodes have 3 DOFs each
  BOOST_TEST(model.n_equations() == 2u + 6u);
}

BOOST_AUTO_TEST_CASE(elements_per_member_subdivide_members)
{
  InputParameters p = poundfe_test::shear_building_input(1, 1000, 5e6, 0);
  p.model.buildings[0]                     = BuildingParameters();
  p.model.buildings[0].type                = BuildingType::frame;
  p.model.buildings[0].name                = "F";
  p.model.buildings[0].elements_per_member = 4;
  const Model model = build_model(p.model, p.contact, p);
  BOOST_TEST(model.members.size() == 12u);
  BOOST_TEST(model.n_nodes() == 4u + 9u);
  BOOST_TEST(model.buildings[0].floors[0].nodes.size() == 2u); // joints only
}

BOOST_AUTO_TEST_CASE(hinges_at_column_bases_and_beam_ends)
{
  // three-storey, one-bay frame: 2 column bases + 3 floors x 2 beam ends
  const InputParameters p = read_parameters("input/three-storey-frame-hinges.prm");
  const Model           model = build_model(p.model, p.contact, p);
  BOOST_TEST(model.hinges.size() == 8u);
  const BuildingParameters &b = p.model.buildings[0];
  for (const Hinge &h : model.hinges)
    {
      // the member-side node shares the joint's translations only
      for (const Component c : {Component::ux, Component::uy})
        BOOST_TEST(model.equation(Model::dof(h.member_node, c)) ==
                   model.equation(Model::dof(h.joint_node, c)));
      BOOST_TEST(model.equation(Model::dof(h.member_node, Component::rz)) >= 0);
      BOOST_TEST(model.equation(Model::dof(h.member_node, Component::rz)) !=
                 model.equation(Model::dof(h.joint_node, Component::rz)));
      const Member &m = model.members[h.member];
      BOOST_TEST((m.nodes[0] == h.member_node || m.nodes[1] == h.member_node));
      // k = factor 6 E I / L and theta_y = M_y / k
      const double k = b.hinge_stiffness_factor * 6 * m.section.youngs_modulus *
                       m.section.second_moment / m.member_length;
      BOOST_TEST(h.law.stiffness == k, boost::test_tools::tolerance(1e-12));
      const bool   column = m.kind == MemberKind::column;
      const double my     = column ? 200e3 : (h.label.find("_B3") != std::string::npos ? 120e3 : 150e3);
      BOOST_TEST(h.law.yield_deformation == my / k, boost::test_tools::tolerance(1e-12));
    }
  // column-base hinges sit on the clamped supports (joint rotation fixed)
  unsigned int bases = 0;
  for (const Hinge &h : model.hinges)
    if (h.label.find("_bottom") != std::string::npos)
      {
        ++bases;
        BOOST_TEST(model.equation(Model::dof(h.joint_node, Component::rz)) < 0);
      }
  BOOST_TEST(bases == 2u);
  BOOST_TEST(model.hinges[0].label.rfind("frame3_", 0) == 0u);
}

BOOST_AUTO_TEST_CASE(bouc_wen_storeys_from_yield_drifts)
{
  InputParameters p = poundfe_test::shear_building_input(3, 1000, 5e6, 0.02);
  p.model.buildings[0].storey_yield_drifts = {0.01, 0.0, 0.02};
  const Model model                 = build_model(p.model, p.contact, p);
  BOOST_TEST(model.links[0].hysteretic);
  BOOST_TEST(!model.links[1].hysteretic);
  BOOST_TEST(model.links[2].hysteresis.yield_deformation == 0.02);
  BOOST_TEST(model.links[2].hysteresis.stiffness == 5e6);
}

// A gap's effective mass from the index of masses by node (what the builder
// uses since a row of 100 frames of 290 storeys spent half its set-up
// scanning every mass per gap) against the scan of every mass (the second
// method): the same sums in the same order, so equal to the last bit, for
// every floor and every gap of frames, shear buildings and barriers.
BOOST_AUTO_TEST_CASE(floor_masses_from_the_index_equal_the_scan)
{
  for (const std::string name : {"two-buildings", "three-buildings-row", "shear-pair-pounding",
                                 "floor-to-column", "spillway-abutment"})
    {
      const InputParameters p = read_parameters("input/" + name + ".prm");
      const Model  model = build_model(p.model, p.contact, p, p.springs, p.friction);
      const MassesByNode index = masses_by_node(model);
      unsigned int       n_floors = 0;
      for (const Building &building : model.buildings)
        for (const Floor &floor : building.floors)
          {
            BOOST_TEST(floor_mass(model, floor, &index) == floor_mass(model, floor));
            n_floors += floor_mass(model, floor) > 0;
          }
      BOOST_TEST_INFO(name);
      BOOST_TEST(n_floors > 0u);
      for (const Gap &gap : model.gaps)
        BOOST_TEST(floor_effective_mass(model, gap, &index) == floor_effective_mass(model, gap));
    }
}
