// The laws of links between buildings and the bumper against independent
// references: the linear dashpot (alpha = 1), the closed-form energy per
// harmonic cycle of a damper (pi c omega X^2; for alpha < 1 the Gamma form,
// itself checked against a Simpson quadrature written here), of a Maxwell
// element in steady state (pi X^2 k omega tau / (1 + (omega tau)^2)) and of
// a bilinear loop (4 Fy (1 - r)(X - dy)); central finite differences of
// every tangent; exact revert; a zero-thickness bumper against the bare
// contact law; the bumper's energy against a quadrature of its force.
#include <poundfe/laws/bumper.h>
#include <poundfe/laws/contact_law.h>
#include <poundfe/laws/link_laws.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <functional>
#include <memory>

using namespace poundfe;

namespace
{
  LinkLawParameters
  damper(const double c, const double alpha, const double k = 0)
  {
    LinkLawParameters p;
    p.kind      = k > 0 ? LinkKind::kelvin_voigt : LinkKind::viscous;
    p.damping   = c;
    p.exponent  = alpha;
    p.stiffness = k;
    return p;
  }

  LinkLawParameters
  maxwell_link()
  {
    LinkLawParameters p;
    p.kind      = LinkKind::maxwell;
    p.stiffness = 3e7;
    p.damping   = 1e6;
    return p;
  }

  LinkLawParameters
  plastic_link(const double hardening)
  {
    LinkLawParameters p;
    p.kind        = LinkKind::elastic_plastic;
    p.stiffness   = 1e7;
    p.yield_force = 5e4;
    p.hardening   = hardening;
    return p;
  }

  /// Drive a law along d = X sin(omega t) for `cycles` cycles of `per_cycle`
  /// steps, committing each; the work int F dd (trapezoidal) of the last cycle.
  double
  last_cycle_work(UniaxialLaw &law, const double X, const double omega, const unsigned int cycles,
                  const unsigned int per_cycle)
  {
    const double dt = 2 * M_PI / omega / per_cycle;
    double       d_old = 0, f_old = law.force(), work = 0;
    for (unsigned int i = 1; i <= cycles * per_cycle; ++i)
      {
        const double t = i * dt, d = X * std::sin(omega * t);
        law.set_trial_time(t);
        BOOST_REQUIRE(law.set_trial(d, X * omega * std::cos(omega * t)));
        if (i > (cycles - 1) * per_cycle)
          work += 0.5 * (f_old + law.force()) * (d - d_old);
        law.commit();
        d_old = d;
        f_old = law.force();
      }
    return work;
  }

  double
  simpson(const std::function<double(double)> &f, const double a, const double b,
          const unsigned int n)
  {
    const double h = (b - a) / n;
    double       s = f(a) + f(b);
    for (unsigned int i = 1; i < n; ++i)
      s += (i % 2 ? 4 : 2) * f(a + i * h);
    return s * h / 3;
  }

  /// Central difference of g at x; g must not change the committed state.
  double
  central(const std::function<double(double)> &g, const double x, const double h)
  {
    return (g(x + h) - g(x - h)) / (2 * h);
  }
} // namespace

BOOST_AUTO_TEST_SUITE(link_laws)

// alpha = 1 is the linear dashpot F = c v, dF/dv = c, to 1e-12 (the code
// path is F = c v, so equality is to round-off).
BOOST_AUTO_TEST_CASE(linear_damper_is_a_dashpot)
{
  const double c   = 3.7e6;
  auto         law = make_link_law(damper(c, 1.0));
  for (const double v : {-2.0, -1e-3, 0.0, 1e-9, 0.4, 5.0})
    {
      BOOST_REQUIRE(law->set_trial(0.01, v));
      BOOST_TEST(std::abs(law->force() - c * v) <= 1e-12 * c * std::max(std::abs(v), 1e-300));
      BOOST_TEST(std::abs(law->damping_tangent() - c) <= 1e-12 * c);
      BOOST_TEST(law->tangent() == 0.0);
    }
}

// The Gamma closed form 2^(2+a) c w^a X^(1+a) G(1+a/2)^2 / G(2+a) against
// c (X w)^(1+a)/w int_0^2pi |cos|^(1+a) by Simpson (1e5 intervals on
// [0, pi/2], where the integrand is smooth except at pi/2: error < 1e-9).
BOOST_AUTO_TEST_CASE(closed_form_energy_per_cycle)
{
  for (const double a : {0.2, 0.35, 0.5, 0.75, 1.0})
    {
      const double closed = std::pow(2.0, 2 + a) * std::pow(std::tgamma(1 + a / 2), 2) /
                            std::tgamma(2 + a);
      const double quadrature =
        4 * simpson([a](const double s) { return std::pow(std::cos(s), 1 + a); }, 0, M_PI / 2,
                    100000);
      BOOST_TEST(std::abs(closed - quadrature) <= 1e-8 * closed);
      if (a == 1.0)
        BOOST_TEST(std::abs(closed - M_PI) <= 1e-14);
    }
}

// The law driven harmonically dissipates the closed form per cycle:
// trapezoidal work on 20000 steps per cycle (error ~ (2 pi/N)^2/12 ~ 1e-8
// for alpha = 1, slower for alpha < 1 where F v ~ |cos|^(1+alpha) has a
// kink at v = 0), regularisation v_eps = 1e-6 m/s against X w = 0.5 m/s
// (relative effect ~ (v_eps/Xw)^2): tolerance 1e-6.
BOOST_AUTO_TEST_CASE(damper_energy_per_cycle)
{
  const double c = 2e6, X = 0.05, omega = 10;
  for (const double a : {0.25, 0.5, 0.8, 1.0})
    {
      auto         law    = make_link_law(damper(c, a));
      const double work   = last_cycle_work(*law, X, omega, 2, 20000);
      const double closed = std::pow(2.0, 2 + a) * c * std::pow(omega, a) *
                            std::pow(X, 1 + a) * std::pow(std::tgamma(1 + a / 2), 2) /
                            std::tgamma(2 + a);
      BOOST_TEST_MESSAGE("alpha " << a << ": work " << work << " J, closed form " << closed
                                  << " J, relative error " << std::abs(work / closed - 1));
      BOOST_TEST(std::abs(work / closed - 1) <= 1e-6);
      // Kelvin-Voigt: the spring stores and returns; the cycle's work is the damper's.
      auto kv = make_link_law(damper(c, a, 5e7));
      BOOST_TEST(std::abs(last_cycle_work(*kv, X, omega, 2, 20000) / closed - 1) <= 1e-6);
    }
}

// Maxwell in steady state: the loss modulus k w tau/(1 + (w tau)^2), tau =
// c/k, gives pi X^2 k w tau/(1 + (w tau)^2) per cycle. The transient from
// rest decays as exp(-t/tau): 30 cycles of 1 s with tau = 0.05 s leave
// exp(-600). Trapezoidal rule, 10000 steps per cycle: tolerance 1e-6.
BOOST_AUTO_TEST_CASE(maxwell_energy_per_cycle)
{
  LinkLawParameters p;
  p.kind          = LinkKind::maxwell;
  p.stiffness     = 4e7;
  p.damping       = 2e6;
  auto         law = make_link_law(p);
  const double X = 0.02, omega = 2 * M_PI, wt = omega * p.damping / p.stiffness;
  const double work   = last_cycle_work(*law, X, omega, 30, 10000);
  const double closed = M_PI * X * X * p.stiffness * wt / (1 + wt * wt);
  BOOST_TEST_MESSAGE("Maxwell: work " << work << " J, closed form " << closed << " J");
  BOOST_TEST(std::abs(work / closed - 1) <= 1e-6);
}

// A bilinear loop between +-X: area 4 Fy (1 - r)(X - dy). The kinks fall
// inside steps, where the trapezoid errs by O(h^2): 1e5 steps, 1e-6.
BOOST_AUTO_TEST_CASE(elastic_plastic_loop)
{
  for (const double r : {0.0, 0.1})
    {
      LinkLawParameters p;
      p.kind        = LinkKind::elastic_plastic;
      p.stiffness   = 1e7;
      p.yield_force = 5e4;
      p.hardening   = r;
      auto         law    = make_link_law(p);
      const double X      = 0.03, dy = p.yield_force / p.stiffness;
      const double work   = last_cycle_work(*law, X, 1.0, 3, 100000);
      const double closed = 4 * p.yield_force * (1 - r) * (X - dy);
      BOOST_TEST(std::abs(work / closed - 1) <= 1e-6);
      BOOST_TEST(law->yield_deformation() == dy);
    }
}

// Every tangent against a central difference (h = 1e-7 of the scale):
// dF/dd and dF/dv at states on every branch, after a committed history.
BOOST_AUTO_TEST_CASE(finite_difference_tangents)
{
  std::vector<LinkLawParameters> laws{damper(1e6, 0.3), damper(1e6, 0.6, 2e7), damper(1e6, 1.0),
                                      maxwell_link(), plastic_link(0.05)};
  for (const LinkLawParameters &p : laws)
    {
      auto law = make_link_law(p);
      // a committed history: 0.01 m at 0.1 s
      law->set_trial_time(0.1);
      law->set_trial(0.01, 0.2);
      law->commit();
      law->set_trial_time(0.11);
      for (const double d : {0.001, 0.004, 0.012, 0.02})
        for (const double v : {-0.5, -1e-6, 0.0, 3e-7, 0.02, 1.0})
          {
            auto of_d = [&](const double x) {
              law->set_trial(x, v);
              return law->force();
            };
            auto of_v = [&](const double x) {
              law->set_trial(d, x);
              return law->force();
            };
            const double kd = central(of_d, d, 1e-9), cv = central(of_v, v, 1e-10);
            law->set_trial(d, v);
            const double scale_k = std::max(std::abs(law->tangent()), 1e3);
            const double scale_c = std::max(std::abs(law->damping_tangent()), 1e3);
            BOOST_TEST(std::abs(kd - law->tangent()) <= 1e-5 * scale_k,
                       link_kind_name(p.kind) << " d " << d << " v " << v << ": dF/dd "
                                              << law->tangent() << " vs " << kd);
            BOOST_TEST(std::abs(cv - law->damping_tangent()) <= 1e-5 * scale_c,
                       link_kind_name(p.kind) << " alpha " << p.exponent << " v " << v
                                              << ": dF/dv " << law->damping_tangent()
                                              << " vs " << cv);
          }
    }
}

// revert() restores the committed state exactly (the next trial repeats).
BOOST_AUTO_TEST_CASE(revert_is_exact)
{
  for (const LinkLawParameters &p : {maxwell_link(), plastic_link(0)})
    {
      auto law = make_link_law(p);
      law->set_trial_time(0.01);
      law->set_trial(0.02, 1);
      law->commit();
      law->set_trial_time(0.02);
      law->set_trial(0.01, -1);
      const double f = law->force(), z = law->history_variable();
      law->set_trial(-0.05, -3); // a rejected trial
      law->revert();
      law->set_trial(0.01, -1);
      BOOST_TEST(law->force() == f);
      BOOST_TEST(law->history_variable() == z);
    }
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(bumper)

namespace
{
  ContactLawParameters
  contact(const std::string &name)
  {
    ContactLawParameters p;
    p.law            = name;
    p.stiffness      = 2e9;
    p.damping        = 0.3;
    p.effective_mass = 5e4;
    p.initial_gap    = 0.04;
    return p;
  }
} // namespace

// A bumper of zero thickness is the bare contact law: force, tangents,
// energy, penetration, phase and impact duration along a history that
// closes, penetrates and opens again, to 1e-8 relative (the arithmetic is
// the same: it agrees to the last bit).
BOOST_AUTO_TEST_CASE(zero_thickness_is_the_bare_contact)
{
  for (const std::string name : {"linear", "hertz-damp", "kelvin-voigt"})
    for (const BumperLaw kind : {BumperLaw::linear, BumperLaw::hertz, BumperLaw::table})
      {
        BumperParameters b;
        b.law       = kind;
        b.thickness = 0;
        b.stiffness = 1e8;
        b.table     = {{{0.01, 1e5}}, {{0.03, 9e5}}};
        auto bare   = make_contact_law(contact(name));
        auto padded = make_bumpered_contact(make_contact_law(contact(name)), b);
        for (unsigned int i = 0; i <= 400; ++i)
          {
            const double t = i * 1e-4, closure = 0.0401 * std::sin(M_PI * t / 0.02);
            const double rate = 0.0401 * M_PI / 0.02 * std::cos(M_PI * t / 0.02);
            BOOST_REQUIRE(bare->set_trial(closure, rate));
            BOOST_REQUIRE(padded->set_trial(closure, rate));
            auto same = [](const double x, const double y) {
              return std::abs(x - y) <= 1e-8 * std::max(std::abs(x), 1e-300);
            };
            BOOST_TEST(same(bare->force(), padded->force()));
            BOOST_TEST(same(bare->tangent(), padded->tangent()));
            BOOST_TEST(same(bare->damping_tangent(), padded->damping_tangent()));
            BOOST_TEST(same(bare->stored_energy(), padded->stored_energy()));
            BOOST_TEST(same(bare->history_variable(), padded->history_variable()));
            BOOST_TEST(bare->phase() == padded->phase());
            BOOST_TEST(same(bare->contact_duration(rate), padded->contact_duration(rate)));
            bare->commit();
            padded->commit();
          }
      }
}

// Phases along a closing gap: open, bumper only, then the structure; the
// force is the bumper's law until crushed, then F_b(t) plus the contact
// law; the tangent against a central difference, the stored energy
// against a Simpson quadrature of the force (5000 intervals; a kink of the
// force inside an interval of width h errs by ~ h^2 times the jump of the
// slope, ~1e-7 of the energy here): 1e-6 relative.
BOOST_AUTO_TEST_CASE(bumper_then_structure)
{
  const ContactLawParameters c = contact("linear");
  for (const BumperLaw kind : {BumperLaw::linear, BumperLaw::hertz, BumperLaw::table})
    {
      BumperParameters b;
      b.law       = kind;
      b.thickness = 0.02;
      b.stiffness = kind == BumperLaw::hertz ? 5e9 : 2e7;
      b.table     = {{{0.005, 5e4}}, {{0.01, 2e5}}, {{0.02, 8e5}}};
      auto law    = make_bumpered_contact(make_contact_law(c), b);
      const double face = c.initial_gap - b.thickness;
      auto force = [&](const double closure) {
        law->set_trial(closure, 0.1);
        return law->force();
      };
      BOOST_TEST(force(face - 1e-6) == 0.0);
      law->set_trial(face - 1e-6, 0.1);
      BOOST_TEST(law->phase() == open_gap);
      law->set_trial(face + 0.01, 0.1);
      BOOST_TEST(law->phase() == bumper_contact);
      BOOST_TEST(std::abs(law->force() - b.force(0.01)) <= 1e-12 * b.force(0.01));
      law->set_trial(c.initial_gap + 0.001, 0.1);
      BOOST_TEST(law->phase() == structure_contact);
      BOOST_TEST(std::abs(law->force() - (b.force(b.thickness) + c.stiffness * 0.001)) <=
                 1e-12 * law->force());
      for (const double closure : {face + 0.003, face + 0.007, face + 0.015, c.initial_gap + 0.002})
        {
          law->set_trial(closure, 0.1);
          const double k = law->tangent();
          BOOST_TEST(std::abs(central(force, closure, 1e-8) - k) <= 1e-6 * k);
          law->set_trial(closure, 0.1);
          const double energy = law->stored_energy();
          const double quadrature = simpson(force, face, closure, 5000);
          BOOST_TEST(std::abs(energy - quadrature) <= 1e-6 * energy,
                     "energy " << energy << " vs " << quadrature);
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
