// The Model section's declarations leave no action that writes outside the
// parameters: ModelParameters::declare once bound Model/Number of buildings
// to a variable of its own frame, so parsing the file (after declare had
// returned) wrote the number into whatever stack lay there (found by
// tests/fuzz's fuzz_parameters: AddressSanitizer, stack-buffer-overflow in
// the entry's action). Here declare's frame is gone when a frame at the same
// depth, filled with a pattern, parses the entry: the pattern must stay.
#include <poundfe/model/parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <boost/test/unit_test.hpp>

#include <cstddef>
#include <sstream>

namespace
{
  constexpr std::size_t declaration_stack_bytes = 16384;

  __attribute__((noinline)) void
  declare_model_section(dealii::ParameterHandler &prm, poundfe::ModelParameters &model)
  {
    model.declare(prm);
  }

  /// Whether parsing `Model/Number of buildings = 7` left a pattern that
  /// covers the stack just below the caller's frame unchanged.
  __attribute__((noinline)) bool
  parse_leaves_stack_alone(dealii::ParameterHandler &prm)
  {
    volatile unsigned char stack[declaration_stack_bytes];
    for (std::size_t i = 0; i < declaration_stack_bytes; ++i)
      stack[i] = 0xab;
    std::istringstream in("subsection Model\n  set Number of buildings = 7\nend\n");
    prm.parse_input(in, "model.prm", "", true);
    for (std::size_t i = 0; i < declaration_stack_bytes; ++i)
      if (stack[i] != 0xab)
        return false;
    return true;
  }
} // namespace

BOOST_AUTO_TEST_CASE(number_of_buildings_declared_without_a_dangling_action)
{
  dealii::ParameterHandler prm;
  poundfe::ModelParameters model;
  model.buildings.resize(2);
  declare_model_section(prm, model);
  BOOST_TEST(parse_leaves_stack_alone(prm));
  BOOST_TEST(model.buildings.size() == 2u); // the first pass, not this one, sets it
  prm.enter_subsection("Model");
  BOOST_TEST(prm.get_integer("Number of buildings") == 7); // read and checked as before
  prm.leave_subsection();
}
