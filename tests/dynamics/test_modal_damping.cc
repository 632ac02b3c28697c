// Modal damping C = M Phi diag(2 zeta_i omega_i) Phi^T M (issue 25 item 4;
// Chopra, Dynamics of Structures, 4th ed., §11.4): each mode of a linear
// shear building, started in its shape, decays with its own ratio
// (logarithmic decrement, Chopra eq. 2.2.11 and §2.2.4) and stays in it;
// Rayleigh damping and modal damping with the ratios Rayleigh gives each
// mode are the same C, and the same response, also with pounding (the
// Woodbury update of the contact elements on top of the modal term, and
// the refactorised tangent); frequency bands pick the modes they contain.
#include <poundfe/assembly/modal_damping.h>
#include <poundfe/base/numbers.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>

#include <cmath>
#include <string>
#include <vector>

#include "time_history_helpers.h"

using namespace poundfe;
using poundfe_test::input_of;
using Recorder = poundfe_test::StepRecorder;

namespace
{
  constexpr unsigned int n_storeys = 3;
  constexpr double       mass = 1000, stiffness = 5e6;

  /// The building of the tests: 3 equal storeys, given Damping lines.
  std::string
  building(const unsigned int number, const std::string &name, const std::string &damping)
  {
    return "subsection Building " + std::to_string(number) + "\n  set Name = " + name +
           "\n  set Type = shear\n  set Number of storeys = 3\n  set Storey heights = 3\n"
           "  set Floor masses = 1000\n  set Storey stiffnesses = 5e6\n  subsection Damping\n" +
           damping + "\n  end\nend\n";
  }

  std::string
  one_building(const std::string &damping, const std::string &initial, const double dt,
               const double end, const std::string &extra = "")
  {
    return "subsection Model\n  set Number of buildings = 1\nend\n" + building(1, "S", damping) +
           "subsection Ground motion\n  set Type = none\nend\n"
           "subsection Initial conditions\n" + initial + "\nend\n"
           "subsection Time integration\n  set Time step = " + number_text(dt) +
           "\n  set End time = " + number_text(end) + "\nend\n" + extra;
  }


  /// The building's modes, computed here: M = m I, K tridiagonal;
  /// phi mass-normalised.
  struct ReferenceModes : poundfe_test::ShearBuildingModes
  {
    ReferenceModes()
      : ShearBuildingModes(n_storeys, mass, stiffness)
    {}
  };



  /// C as a dense matrix: the sparse part plus U D U^T.
  Eigen::MatrixXd
  dense_damping(const LinearSystem &system)
  {
    Eigen::MatrixXd C = Eigen::MatrixXd(system.damping);
    const LowRankDamping &modal = system.modal_damping;
    if (!modal.empty())
      C += modal.factor * modal.weights.asDiagonal() * modal.factor.transpose();
    return C;
  }

  std::string
  floor_list(const Eigen::VectorXd &x)
  {
    std::string text;
    for (Eigen::Index i = 0; i < x.size(); ++i)
      text += " " + number_text(x[i]);
    return text;
  }

  /// Damping lines of Rayleigh zeta = 0.05 at modes 1 and 3, and of modal
  /// damping with the ratios it gives: 0.05, zeta_2, 0.05, zeta_2 =
  /// a0/(2 w_2) + a1 w_2/2 (Chopra eq. 11.4.8) from the reference modes.
  std::pair<std::string, std::string>
  equivalent_damping()
  {
    const ReferenceModes ref;
    const double zeta = 0.05, w1 = ref.omega[0], w2 = ref.omega[1], w3 = ref.omega[2];
    const double a0 = 2 * zeta * w1 * w3 / (w1 + w3), a1 = 2 * zeta / (w1 + w3);
    return {"    set Type = modes\n    set Damping ratio = 0.05\n    set Modes = 1, 3",
            "    set Type = modal\n    set Modal ratios = 0.05, " +
              number_text(a0 / (2 * w2) + a1 * w2 / 2) + ", 0.05"};
  }

  double
  max_difference(const Recorder &a, const Recorder &b)
  {
    BOOST_REQUIRE(a.u.size() == b.u.size());
    double worst = 0, scale = 0;
    for (std::size_t i = 0; i < a.u.size(); ++i)
      {
        worst = std::max(worst, (a.u[i] - b.u[i]).cwiseAbs().maxCoeff());
        scale = std::max(scale, a.u[i].cwiseAbs().maxCoeff());
      }
    return worst / scale;
  }
} // namespace

BOOST_AUTO_TEST_CASE(each_mode_decays_with_its_own_ratio)
{
  const ReferenceModes      ref;
  const std::vector<double> zeta{0.02, 0.05, 0.1};
  for (unsigned int i = 0; i < n_storeys; ++i)
    {
      const double     period = 2 * M_PI / ref.omega[i], dt = period / 400;
      const unsigned   cycles = 6;
      const Eigen::VectorXd shape = 0.01 * ref.phi.col(i) / ref.phi.col(i).cwiseAbs().maxCoeff();
      const InputParameters p     = input_of(
        "modal_decay", one_building("    set Type = modal\n    set Modal ratios = 0.02, 0.05, 0.1",
                                    "  set Floor displacements = S:" + floor_list(shape), dt,
                                    cycles * period));
      const Analysis analysis = prepare_analysis(p);
      const Recorder r        = poundfe_test::recorded_run(analysis, p);
      // the modal coordinate q_i = phi_i^T M u, and what leaks into the others
      std::vector<double> q, peaks;
      double              leak = 0;
      for (const Vector &u : r.u)
        {
          q.push_back(ref.phi.col(i).dot(mass * u));
          for (unsigned int j = 0; j < n_storeys; ++j)
            if (j != i)
              leak = std::max(leak, std::abs(ref.phi.col(j).dot(mass * u)));
        }
      for (std::size_t s = 1; s + 1 < q.size(); ++s)
        if (q[s] > q[s - 1] && q[s] >= q[s + 1] && q[s] > 0)
          peaks.push_back(q[s]);
      BOOST_REQUIRE(peaks.size() >= cycles - 1);
      const double delta    = std::log(peaks.front() / peaks.back()) / (peaks.size() - 1);
      const double measured = delta / std::sqrt(4 * M_PI * M_PI + delta * delta);
      BOOST_TEST_MESSAGE("mode " << i + 1 << ": zeta " << zeta[i] << ", measured " << measured
                                 << " (relative error " << measured / zeta[i] - 1
                                 << "), largest other modal coordinate "
                                 << leak / std::abs(q.front()) << " of q_i(0)");
      // Newmark's period and amplitude errors ~ (w dt)^2/12 = 2e-5 and the
      // sampled peaks ~ (w dt)^2/8 = 3e-5 of the amplitude over a decay of
      // 2 pi zeta (cycles - 1) >= 0.6: 1e-3 relative is far above them and
      // far below the next ratio.
      BOOST_TEST(measured == zeta[i], boost::test_tools::tolerance(1e-3));
      BOOST_TEST(leak <= 1e-10 * std::abs(q.front())); // C is diagonal in the modes
    }
}

BOOST_AUTO_TEST_CASE(rayleigh_is_modal_damping_with_its_own_ratios)
{
  const auto [rayleigh, modal] = equivalent_damping();
  const std::string initial = "  set Floor displacements = S: 0.01 0.02 0.04\n"
                              "  set Floor velocities = S: all -0.2";
  const std::string forces = "subsection Nodal forces\n  set Harmonic = 1 3 0 ux 2e4 30 0\nend\n";
  const InputParameters pr = input_of("rayleigh", one_building(rayleigh, initial, 1e-3, 2, forces));
  const InputParameters pm = input_of("modal", one_building(modal, initial, 1e-3, 2, forces));
  const Analysis        ar = prepare_analysis(pr), am = prepare_analysis(pm);
  BOOST_TEST(am.system.damping.nonZeros() == 0); // no storey dashpots: all modal
  BOOST_TEST(am.system.modal_damping.weights.size() == 3);
  const Eigen::MatrixXd Cr = dense_damping(ar.system), Cm = dense_damping(am.system);
  const double          c_error = (Cr - Cm).norm() / Cr.norm();
  const double          u_error = max_difference(poundfe_test::recorded_run(ar, pr), poundfe_test::recorded_run(am, pm));
  BOOST_TEST_MESSAGE("Rayleigh vs modal: |C_R - C_m|/|C_R| = "
                     << c_error << ", response " << u_error);
  BOOST_TEST(c_error <= 1e-12); // round-off of the eigenvectors
  BOOST_TEST(u_error <= 1e-10); // and of the Woodbury solve
}

BOOST_AUTO_TEST_CASE(pounding_with_modal_damping_matches_rayleigh)
{
  // Two buildings pound; the contact elements' Woodbury update (or the
  // refactorised tangent) sits on the modal term's.
  const auto [rayleigh, modal] = equivalent_damping();
  const auto text = [&](const std::string &damping, const std::string &update) {
    return "subsection Model\n  set Number of buildings = 2\n  set Separations = 0.005\nend\n" +
           building(1, "A", damping) + building(2, "B", damping) +
           "subsection Ground motion\n  set Type = none\nend\n"
           "subsection Contact\n  set Law = hertz-damp\n  set Stiffness = 5e9\nend\n"
           "subsection Initial conditions\n  set Floor velocities = A: all 0.3; B: all -0.2\nend\n"
           "subsection Time integration\n  set Time step = 1e-3\n  set End time = 1\n"
           "  set Tangent update = " + update + "\nend\n";
  };
  for (const std::string update : {"woodbury", "refactorize", "hybrid"})
    {
      const InputParameters pr = input_of("pound_r", text(rayleigh, update));
      const InputParameters pm = input_of("pound_m", text(modal, update));
      const Analysis        ar = prepare_analysis(pr), am = prepare_analysis(pm);
      const double error = max_difference(poundfe_test::recorded_run(ar, pr), poundfe_test::recorded_run(am, pm));
      BOOST_TEST_MESSAGE("pounding, " << update << ": Rayleigh vs modal " << error);
      // The same C and the same iterations: round-off apart (measured
      // ~1e-12); 1e-9 leaves room for an iteration count that differs.
      BOOST_TEST(error <= 1e-9);
    }
}

BOOST_AUTO_TEST_CASE(bands_damp_the_modes_whose_frequency_they_contain)
{
  const ReferenceModes ref;
  const double         f1 = ref.omega[0] / (2 * M_PI), f2 = ref.omega[1] / (2 * M_PI);
  // band 1 holds mode 1 only; band 2 modes 2 (and 3, which is not damped:
  // Damped modes = 2)
  const std::string damping = "    set Type = bands\n    set Bands = 0 " +
                              number_text(0.5 * (f1 + f2)) + " 0.03; " +
                              number_text(0.5 * (f1 + f2)) + " 1000 0.07\n"
                              "    set Damped modes = 2";
  const InputParameters p = input_of("bands", one_building(damping, "", 0.01, 0.1));
  const Analysis        a = prepare_analysis(p);
  const Eigen::MatrixXd C = dense_damping(a.system);
  const Eigen::MatrixXd modal = ref.phi.transpose() * C * ref.phi;
  const double          scale = modal.cwiseAbs().maxCoeff();
  BOOST_TEST(modal(0, 0) / (2 * ref.omega[0]) == 0.03, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(modal(1, 1) / (2 * ref.omega[1]) == 0.07, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(std::abs(modal(2, 2)) <= 1e-12 * scale);
  BOOST_TEST(std::abs(modal(0, 1)) <= 1e-12 * scale);
}

BOOST_AUTO_TEST_CASE(bad_modal_damping_names_the_entry)
{
  const auto error_of = [](const std::string &damping) {
    return poundfe_test::input_error_of(
      [&]() { prepare_analysis(input_of("modal_bad", one_building(damping, "", 0.01, 0.1))); });
  };
  BOOST_TEST(error_of("    set Type = modal\n    set Modal ratios = 0.05, 1")
               .find("must lie in [0, 1), got 1") != std::string::npos);
  BOOST_TEST(error_of("    set Type = modal\n    set Modal ratios = -0.05")
               .find("got -0.05") != std::string::npos);
  BOOST_TEST(error_of("    set Type = modal\n    set Modal ratios = 0.05, 0.05, 0.05, 0.05")
               .find("has only 3 modes") != std::string::npos);
  BOOST_TEST(error_of("    set Type = modal").find("needs a damping ratio per mode") !=
             std::string::npos);
  BOOST_TEST(error_of("    set Type = bands\n    set Bands = 0 10 0.05\n    set Damped modes = 4")
               .find("has only 3 modes") != std::string::npos);
  BOOST_TEST(error_of("    set Type = bands\n    set Bands = 0 10 0.05; 5 20 0.02\n"
                      "    set Damped modes = 2")
               .find("overlaps") != std::string::npos);
  BOOST_TEST(error_of("    set Type = bands\n    set Bands = 10 5 0.05\n    set Damped modes = 2")
               .find("needs 0 <= low < high") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_large_building_keeps_c_low_rank)
{
  // 2000 storeys, 5 damped modes: C is the n x 5 factor U and 5 weights
  // (a dense C would be 4e6 entries); a run from a leaning start balances.
  const std::string text =
    "subsection Model\n  set Number of buildings = 1\nend\n"
    "subsection Building 1\n  set Name = S\n  set Type = shear\n  set Number of storeys = 2000\n"
    "  set Storey heights = 3\n  set Floor masses = 1000\n  set Storey stiffnesses = 5e9\n"
    "  subsection Damping\n    set Type = modal\n    set Modal ratios = 0.05, 0.05, 0.05, 0.05, 0.05\n"
    "  end\nend\nsubsection Ground motion\n  set Type = none\nend\n"
    "subsection Initial conditions\n  set Floor velocities = S: all 0.1\nend\n"
    "subsection Time integration\n  set Time step = 0.01\n  set End time = 0.5\nend\n";
  const InputParameters p = input_of("large_modal", text);
  const Analysis        a = prepare_analysis(p);
  BOOST_TEST(a.system.modal_damping.factor.rows() == 2000);
  BOOST_TEST(a.system.modal_damping.factor.cols() == 5);
  BOOST_TEST(a.system.damping.nonZeros() == 0);
  const Recorder r = poundfe_test::recorded_run(a, p);
  BOOST_TEST_MESSAGE("2000 storeys, 5 modal ratios: energy error " << r.max_energy_error
                                                                   << ", damping " << r.energy.damping
                                                                   << " J");
  BOOST_TEST(r.energy.damping > 0);
  BOOST_TEST(r.max_energy_error <= 1e-8);
}
