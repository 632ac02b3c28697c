// The contact law registry: a law defined only in this file, the elastic
// quadratic law F = k delta^2, is registered in one place (the registrar
// below) and is then known wherever a law name is: the input's
// Contact/Law, the model builder, the gap elements and the integrator.
// One impact of a mass m at v0 on a barrier gives one logged impact, the
// law's force at every step, and the closed form of an elastic impact with
// F = k delta^2: m v0^2 / 2 = k delta_max^3 / 3.
#include <poundfe/input/engine_parameters.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/integration/newmark.h>
#include <poundfe/laws/contact_law.h>
#include <poundfe/model/parameters.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

using namespace poundfe;

namespace
{
  class Quadratic : public ContactLaw
  {
  public:
    using ContactLaw::ContactLaw;
    Response respond(const double delta, double /*rate*/,
                     double /*approach_velocity*/) const override
    {
      return {p.stiffness * delta * delta, 2 * p.stiffness * delta, 0.0};
    }
    double elastic_energy(const double delta) const override
    {
      return p.stiffness * delta * delta * delta / 3;
    }
  };

  // The one place the law is made known.
  const ContactLawRegistrar quadratic_law(
    {"quadratic", "k d^2",
     [](const ContactLawParameters &p) { return std::make_unique<Quadratic>(p); }, {}, false});

  /// A 1000 kg mass on a negligible spring, 1 mm from a barrier on its right.
  std::string
  input_text(const std::string &law)
  {
    return "subsection Model\n  set Number of buildings = 1\nend\n"
           "subsection Building 1\n  set Name = M\n  set Type = shear\n"
           "  set Number of storeys = 1\n  set Storey heights = 1\n"
           "  set Floor masses = 1000\n  set Storey stiffnesses = 1e-3\n"
           "  subsection Damping\n    set Type = none\n  end\nend\n"
           "subsection Ground motion\n  set Type = none\nend\n"
           "subsection Contact\n  set Law = " + law + "\n  set Stiffness = 1e10\n"
           "  set Damping from = given\n  set Barriers = 1 1 right 0.001\nend\n"
           "subsection Time integration\n  set Time step = 5e-5\n  set End time = 0.06\nend\n"
           "subsection Output\n  set Number of modes = 1\nend\n";
  }

  InputParameters
  read_input(const std::string &law)
  {
    const std::string file =
      (std::filesystem::temp_directory_path() / ("poundfe-registry-" + law + ".prm")).string();
    std::ofstream(file) << input_text(law);
    InputParameters input;
    try
      {
        input = read_parameters(file);
      }
    catch (...)
      {
        std::filesystem::remove(file);
        throw;
      }
    std::filesystem::remove(file);
    return input;
  }
} // namespace

BOOST_AUTO_TEST_CASE(a_registered_law_is_known_by_name)
{
  const std::vector<std::string> names = contact_law_names();
  BOOST_TEST(names.size() == 7u); // the six built-in laws, then this one
  BOOST_TEST(names.back() == "quadratic");
  BOOST_TEST(!contact_law_is_damped("quadratic"));
  BOOST_TEST(damping_from_restitution_formula("quadratic", 0.5) == 0.0);
  BOOST_TEST(contact_law_is_damped("hertz-damp"));
  BOOST_CHECK_THROW(register_contact_law(contact_law_type("quadratic")), std::logic_error);
  BOOST_CHECK_THROW(contact_law_type("cubic"), std::invalid_argument);
  // the input accepts it, and still rejects a name nobody registered
  BOOST_TEST(read_input("quadratic").contact.law == "quadratic");
  BOOST_CHECK_THROW(read_input("cubic"), InputError);
}

BOOST_AUTO_TEST_CASE(a_registered_law_runs_through_the_integrator)
{
  const InputParameters input    = read_input("quadratic");
  const Analysis        analysis = prepare_analysis(input);
  NonlinearElements     elements = make_nonlinear_elements(analysis.model);
  BOOST_REQUIRE(elements.size() == 1u);
  NewmarkIntegrator integrator(analysis.system, "eigen-ldlt", input.time_integration.newmark,
                               &elements);
  const double m = 1000, k = 1e10, v0 = 0.5;
  const Vector zero = Vector::Zero(1);
  integrator.initialize(zero, zero, Vector::Constant(1, v0));
  double worst_force = 0, peak_force = 0;
  for (unsigned int i = 0; i < 1200; ++i)
    {
      integrator.advance(zero);
      const double delta = elements[0].history_variable(), force = elements[0].force();
      if (delta > 0)
        worst_force = std::max(worst_force, std::abs(force - k * delta * delta) / force);
      else
        BOOST_TEST(force == 0.0);
      peak_force = std::max(peak_force, force);
    }
  const std::vector<Impact> &impacts = integrator.impact_log().impacts();
  BOOST_REQUIRE(impacts.size() == 1u);
  const Impact &impact    = impacts[0];
  const double  delta_max = std::cbrt(1.5 * m * v0 * v0 / k);
  BOOST_TEST_MESSAGE("quadratic law: force against k delta^2 " << worst_force << ", delta_max "
                     << impact.max_penetration << " / " << delta_max << ", F_max "
                     << impact.peak_force << " / " << k * delta_max * delta_max
                     << ", separation " << impact.separation_velocity << " / " << v0);
  BOOST_TEST(worst_force < 1e-14);
  BOOST_TEST(impact.end_time > impact.start_time);
  BOOST_TEST(impact.start_time == 0.001 / v0, boost::test_tools::tolerance(1e-6));
  BOOST_TEST(impact.max_penetration == delta_max, boost::test_tools::tolerance(1e-3));
  BOOST_TEST(impact.peak_force == k * delta_max * delta_max, boost::test_tools::tolerance(2e-3));
  BOOST_TEST(peak_force <= impact.peak_force * (1 + 1e-12));
  BOOST_TEST(impact.separation_velocity == v0, boost::test_tools::tolerance(1e-3));
  BOOST_TEST(integrator.max_energy_error() < 1e-6);
}
