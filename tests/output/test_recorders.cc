// User-chosen recorders (Output/Recorders): base shear, storey shear,
// residual drift and a member's end forces, checked against horizontal
// equilibrium of the building (doc/theory.md §10):
//   sum_x M a_abs + sum_x C u' + V_base = 0,
// where the sums run over the building's ux equations and V_base is the
// recorded base shear (element forces).
//  - Shear building with yielding Bouc-Wen storeys, storey dashpots and no
//    Rayleigh damping: C u' is inside the storey forces, so
//    sum_j>=i m_j a_abs,j = -V_i for every storey i. The equations hold to
//    the Newton tolerance: with the default 1e-8 of a step's first residual
//    the balance closes to 1.7e-9 of the peak base shear, so the input asks
//    for 1e-11 and the check is 1e-9.
//  - Frame with Rayleigh damping and hinges: V_base differs from -sum M a_abs
//    by the damping share sum_x C u' exactly (1e-9 of the peak), and so by
//    no more than that share.
//  - The member end forces satisfy the member's own equilibrium
//    (N1 + N2 = 0, V1 + V2 = 0, M1 + M2 = L V1) and sum, over the base
//    columns, to the base shear; residual drift equals the last row of the
//    drift recorder.
#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/report/run_outputs.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/output/peak_response.h>
#include <poundfe/output/recorders.h>

#include "output_test_files.h"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

using namespace poundfe;

namespace
{
  using poundfe_test::read_csv;
  using poundfe_test::Table;

  std::string
  write_input(const std::string &name, const std::string &text)
  {
    const std::string file = std::filesystem::temp_directory_path() / ("poundfe-" + name + ".prm");
    std::ofstream(file) << text;
    return file;
  }

  const char *shear_building = R"(
subsection Model
  set Number of buildings = 1
end
subsection Building 1
  set Name               = S
  set Type               = shear
  set Number of storeys  = 3
  set Storey heights     = 3.0
  set Floor masses       = 20000, 20000, 15000
  set Storey stiffnesses = 3e7, 2.5e7, 2e7
  set Storey damping     = 4e4
  set Storey yield drifts = 0.02, 0.02, 0.02
  subsection Damping
    set Type = none
  end
end
subsection Ground motion
  set Type = kanai-tajimi
  subsection Stochastic
    set Target PGA = 0.5
    set Duration   = 6
    set Seed       = 3
  end
end
subsection Time integration
  set Time step                 = 0.002
  set Newton residual tolerance = 1e-11
end
subsection Output
  set VTU interval = 0
  set Plots        = false
  subsection Recorders
    set Default files = false
    set Record = base shear; storey shear; floor acceleration; storey drift ratio every 0.1; residual drift
  end
end
)";

  const char *frame = R"(
subsection Model
  set Number of buildings = 1
  set Mass matrix         = lumped
end
subsection Building 1
  set Name              = F
  set Type              = frame
  set Number of storeys = 2
  set Number of bays    = 2
  set Storey heights    = 3.5, 3.0
  set Bay widths        = 6.0
  set Column A          = 0.16
  set Column I          = 2.1333e-3
  set Beam A            = 0.15
  set Beam I            = 3.125e-3
  set Floor masses      = 40000, 30000
  subsection Hinges
    set Locations    = column bases, beam ends
    set Yield moment = 150e3
  end
  subsection Damping
    set Type          = modes
    set Damping ratio = 0.05
    set Modes         = 1, 2
  end
end
subsection Ground motion
  set Type = kanai-tajimi
  subsection Stochastic
    set Target PGA = 0.4
    set Duration   = 6
    set Seed       = 5
  end
end
subsection Time integration
  set Time step = 0.002
end
subsection Output
  set VTU interval = 0
  set Plots        = false
  subsection Recorders
    set Record = base shear; storey shear; residual drift; member end forces of F_C1.1, F_C1.2, F_C1.3, F_B2.1
  end
end
)";

  /// sum over the building's ux equations of M a_abs and of C u' at every step.
  class EquilibriumTerms : public StepObserver
  {
  public:
    void
    observe_step(const ResponseView &s) override
    {
      const Vector absolute = s.acceleration() + s.system.influence * s.ground_acceleration();
      inertia.push_back(s.system.influence.dot(s.system.mass * absolute));
      damping.push_back(s.system.influence.dot(s.system.damping * s.velocity()));
    }
    std::vector<double> inertia, damping;
  };
} // namespace

BOOST_AUTO_TEST_CASE(shear_building_storey_shears_balance_the_floor_inertia)
{
  const InputParameters input      = read_parameters(write_input("shear", shear_building));
  const Analysis        analysis   = prepare_analysis(input);
  const Excitation      excitation = make_excitation(analysis, input);
  const std::string dir = std::filesystem::temp_directory_path() / "poundfe-recorders-shear";
  std::filesystem::remove_all(dir);
  RunOptions options;
  options.output_directory = dir;
  const RunResult result   = run_time_history(analysis, run_parameters(input), excitation, options);
  BOOST_REQUIRE(result.status.completed());
  BOOST_TEST(result.n_nonlinear_elements == 3u); // the storeys yield: a nonlinear check

  // only what was asked for
  for (const char *absent : {"floor_displacement.csv", "energy.csv", "hinges.csv", "ground_motion.csv"})
    BOOST_TEST(!std::filesystem::exists(dir + "/" + absent));
  const Table base = read_csv(dir + "/base_shear.csv"), storey = read_csv(dir + "/storey_shear.csv"),
              accel = read_csv(dir + "/floor_acceleration.csv");
  BOOST_TEST(base.header.at(1) == "S_base_shear_N");
  BOOST_TEST(storey.header.at(2) == "S_storey2_shear_N");
  BOOST_TEST(accel.header.at(3) == "S_floor3_acc_m_s2");
  BOOST_REQUIRE(base.rows.size() == 3001u);

  const double masses[] = {20000, 20000, 15000};
  double       peak = 0, worst = 0, peak_ductility_drift = 0;
  for (const auto &row : base.rows)
    peak = std::max(peak, std::abs(row[1]));
  for (unsigned int k = 0; k < base.rows.size(); ++k)
    {
      BOOST_TEST(base.rows[k][1] == storey.rows[k][1]); // V_base is V_1
      double above = 0;                                 // sum of m a_abs above the cut
      for (int i = 2; i >= 0; --i)
        {
          above += masses[i] * accel.rows[k][1 + i];
          worst = std::max(worst, std::abs(above + storey.rows[k][1 + i]));
        }
    }
  BOOST_TEST_MESSAGE("shear building: peak base shear " << peak << " N, largest |sum m a_abs + V_i| "
                                                        << worst << " N (" << worst / peak
                                                        << " relative)");
  BOOST_TEST(worst <= 1e-9 * peak);

  // residual drift: the last drift, also in summary.json
  const Table drift = read_csv(dir + "/drift.csv");
  BOOST_TEST(drift.rows.size() == 61u); // every 0.1 s, not every step
  std::ifstream residual(dir + "/residual_drift.csv");
  std::string   line;
  std::getline(residual, line);
  BOOST_TEST(line == "building,storey,residual_drift_ratio,residual_floor_disp_m");
  for (unsigned int i = 0; i < 3; ++i)
    {
      std::getline(residual, line);
      std::istringstream s(line);
      std::string        building, storey_number, value;
      std::getline(s, building, ',');
      std::getline(s, storey_number, ',');
      std::getline(s, value, ',');
      BOOST_TEST(building == "S");
      BOOST_TEST(std::stod(value) == drift.rows.back()[1 + i]);
      peak_ductility_drift = std::max(peak_ductility_drift, std::abs(std::stod(value)));
    }
  BOOST_TEST_MESSAGE("largest residual drift ratio " << peak_ductility_drift);
}

BOOST_AUTO_TEST_CASE(frame_base_shear_differs_from_inertia_by_the_damping_share)
{
  const InputParameters input      = read_parameters(write_input("frame", frame));
  const Analysis        analysis   = prepare_analysis(input);
  const Excitation      excitation = make_excitation(analysis, input);
  const std::string dir = std::filesystem::temp_directory_path() / "poundfe-recorders-frame";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);

  // The time loop with the input's recorders and a test observer.
  TimeHistory      history(analysis, time_history_parameters(input));
  PeakResponse     peaks(analysis.model, history.nonlinear_elements());
  EquilibriumTerms terms;
  auto recorders = make_recorders(input.output.recorders, input.file, history.state(),
                                  peaks, input.time_integration.newmark.time_step, dir);
  Observers observers{&peaks, &terms};
  for (const auto &r : recorders.observers)
    observers.push_back(r.get());
  const RunStatus status = history.run(excitation, observers);
  BOOST_REQUIRE(status.completed());
  // defaults are kept next to the requested files
  for (const char *file : {"drift.csv", "floor_acceleration.csv", "hinges.csv", "energy.csv",
                           "member_forces.csv", "residual_drift.csv"})
    BOOST_TEST(std::filesystem::exists(dir + "/" + file), file);

  const Table base = read_csv(dir + "/base_shear.csv"), members = read_csv(dir + "/member_forces.csv");
  BOOST_REQUIRE(base.rows.size() == terms.inertia.size());
  double peak = 0, worst_balance = 0, largest_share = 0, worst_members = 0, worst_member_equilibrium = 0;
  for (const auto &row : base.rows)
    peak = std::max(peak, std::abs(row[1]));
  const double L = 3.5; // ground-storey columns
  for (unsigned int k = 0; k < base.rows.size(); ++k)
    {
      const double V = base.rows[k][1];
      worst_balance  = std::max(worst_balance, std::abs(terms.inertia[k] + terms.damping[k] + V));
      // |V + sum M a_abs| is the damping share, up to the Newton tolerance
      BOOST_TEST(std::abs(V + terms.inertia[k]) <= std::abs(terms.damping[k]) + 1e-9 * peak);
      largest_share = std::max(largest_share, std::abs(terms.damping[k]));
      // the base columns' shears (local V1, columns point up) add up to V_base
      double sum = 0;
      for (const char *column : {"F_C1.1", "F_C1.2", "F_C1.3"})
        {
          const auto  &r  = members.rows[k];
          const double N1 = r[members.column(std::string(column) + "_N1_N")];
          const double V1 = r[members.column(std::string(column) + "_V1_N")];
          const double M1 = r[members.column(std::string(column) + "_M1_N_m")];
          const double N2 = r[members.column(std::string(column) + "_N2_N")];
          const double V2 = r[members.column(std::string(column) + "_V2_N")];
          const double M2 = r[members.column(std::string(column) + "_M2_N_m")];
          worst_member_equilibrium =
            std::max({worst_member_equilibrium, std::abs(N1 + N2), std::abs(V1 + V2),
                      std::abs(M1 + M2 - L * V1) / L});
          sum += V1;
        }
      worst_members = std::max(worst_members, std::abs(sum - V));
    }
  BOOST_TEST_MESSAGE("frame: peak base shear " << peak << " N; largest damping share "
                                               << largest_share << " N; largest |sum M a_abs + "
                                                  "sum C v + V_base| "
                                               << worst_balance << " N (" << worst_balance / peak
                                               << " relative)");
  BOOST_TEST(largest_share > 1e-3 * peak); // the damping share is not negligible here
  BOOST_TEST(worst_balance <= 1e-9 * peak);
  BOOST_TEST(worst_members <= 1e-12 * peak);
  BOOST_TEST(worst_member_equilibrium <= 1e-9 * peak);
}

BOOST_AUTO_TEST_CASE(recorder_input_errors)
{
  BOOST_CHECK_THROW(RecorderParameters::parse("base shears"), std::invalid_argument);
  BOOST_CHECK_THROW(RecorderParameters::parse("member end forces"), std::invalid_argument);
  BOOST_CHECK_THROW(RecorderParameters::parse("base shear of A"), std::invalid_argument);
  BOOST_CHECK_THROW(RecorderParameters::parse("base shear every -1"), std::invalid_argument);
  BOOST_CHECK_THROW(RecorderParameters::parse("base shear every x"), std::invalid_argument);
  BOOST_CHECK_THROW(RecorderParameters::parse("base shear; base shear"), std::invalid_argument);
  const auto r = RecorderParameters::parse(" base shear every 0.01 ; member end forces of A_C1.1, A_B1.1; none");
  BOOST_REQUIRE(r.size() == 2u);
  BOOST_TEST(r[0].interval == 0.01);
  BOOST_TEST(r[1].labels.size() == 2u);
  BOOST_TEST(r[1].labels[1] == "A_B1.1");
  BOOST_TEST(r[1].interval < 0);
  // an unknown member is an input error naming the parameter
  std::string text = frame;
  text.replace(text.find("F_B2.1"), 6, "F_B9.9");
  const InputParameters input    = read_parameters(write_input("bad-member", text));
  const Analysis        analysis = prepare_analysis(input);
  RunOptions            options;
  options.output_directory = std::filesystem::temp_directory_path() / "poundfe-recorders-bad";
  BOOST_CHECK_THROW(run_time_history(analysis, run_parameters(input),
                                     make_excitation(analysis, input), options),
                    InputError);
  BOOST_TEST(!std::filesystem::exists(options.output_directory)); // nothing written
}

// 'hinge states of ...' and 'gap states of ...' (large models record a few):
// input/three-buildings-row.prm (A3, B2, C4; hinges and gaps) run with all of
// them (the default) and with 'hinge states of B2, A3_C1.2_bottom; gap states
// of C4'. Reference: the columns the test picks from the full run's header by
// their labels' text (a hinge of B2 starts with "B2_"; a gap "X-Y@level"
// touches C4 when X or Y is C4), in its order; their values to the bit (the
// recorders do not change the run). A label that names nothing is an
// InputError naming the entry, before any file is written.
BOOST_AUTO_TEST_CASE(hinge_and_gap_states_of_chosen_labels_are_those_columns_of_the_full_ones)
{
  const auto run = [](const std::string &name, const std::string &record) {
    std::ifstream in("input/three-buildings-row.prm");
    std::string   text((std::istreambuf_iterator<char>(in)), {});
    const std::size_t output = text.find("subsection Output\n");
    BOOST_REQUIRE(output != std::string::npos);
    text.insert(output + 18, "  set Plots = false\n  subsection Recorders\n    set Record = " +
                               record + "\n  end\n");
    const InputParameters input    = read_parameters(write_input(name, text));
    const Analysis        analysis = prepare_analysis(input);
    RunOptions            options;
    options.output_directory = poundfe_test::fresh_directory(name);
    run_time_history(analysis, run_parameters(input), make_excitation(analysis, input), options);
    return options.output_directory;
  };
  const std::string all    = run("states-all", "");
  const std::string chosen = run("states-chosen", "hinge states of B2, A3_C1.2_bottom; gap states of C4");
  const auto check = [&](const std::string &file, const std::function<bool(const std::string &)> &wanted) {
    const Table full = read_csv(all + "/" + file), part = read_csv(chosen + "/" + file);
    std::vector<std::string> expected{"time_s"};
    for (const std::string &name : full.header)
      if (name != "time_s" && wanted(name))
        expected.push_back(name);
    BOOST_REQUIRE_GT(expected.size(), 1u);
    BOOST_REQUIRE_LT(expected.size(), full.header.size());
    BOOST_REQUIRE(part.header == expected);
    BOOST_REQUIRE_EQUAL(part.rows.size(), full.rows.size());
    for (unsigned int c = 0; c < expected.size(); ++c)
      for (unsigned int r = 0; r < full.rows.size(); ++r)
        BOOST_CHECK_EQUAL(part.rows[r][c], full.rows[r][full.column(expected[c])]);
  };
  check("hinges.csv", [](const std::string &name) {
    return name.rfind("B2_", 0) == 0 || name.rfind("A3_C1.2_bottom_", 0) == 0;
  });
  check("contact_force.csv", [](const std::string &name) {
    const std::string pair = name.substr(0, name.find('@')); // "X-Y"
    return pair.rfind("C4-", 0) == 0 || (pair.size() >= 3 && pair.substr(pair.size() - 3) == "-C4");
  });
  // a label that names nothing
  BOOST_CHECK_THROW(run("states-bad", "hinge states of B2_C9.9_bottom"), InputError);
  BOOST_TEST(!std::filesystem::exists(std::filesystem::temp_directory_path() / "poundfe-states-bad"));
  BOOST_CHECK_THROW(RecorderParameters::parse("gap states of"), std::invalid_argument);
  BOOST_CHECK_THROW(RecorderParameters::parse("energy of A3"), std::invalid_argument);
}

// The console's note on a table that would pass 1 GB: the city block's
// hinges.csv (29,197 columns) every step of 2,000 is 21 bytes x 29,197 x
// 2,001 = 1.23 GB in CSV; in .npy (8 bytes a number) 0.47 GB and a row every
// 10 steps 0.12 GB: no note. A quantity that takes no labels is told 'every'.
BOOST_AUTO_TEST_CASE(a_table_past_a_gigabyte_is_noted_with_how_to_record_less)
{
  const TableShape hinges{RecordedQuantity::hinge_states, "hinges.csv", 29197, 1};
  BOOST_CHECK_EQUAL(large_table_note(hinges, 2000, OutputFormat::csv),
                    "poundfe: note: hinges.csv will be about 1.2 GB (29197 columns, 2001 rows); "
                    "Output/Recorders/Record = 'hinge states of <labels or buildings>' or 'hinge "
                    "states every <s>' records less\n");
  BOOST_CHECK_EQUAL(large_table_note(hinges, 2000, OutputFormat::npy), "");
  BOOST_CHECK_EQUAL(large_table_note({RecordedQuantity::hinge_states, "hinges.csv", 29197, 10}, 2000,
                                     OutputFormat::csv),
                    "");
  BOOST_CHECK_EQUAL(large_table_note({RecordedQuantity::floor_acceleration, "floor_acceleration.csv",
                                      4801, 1},
                                     20000000, OutputFormat::csv),
                    "poundfe: note: floor_acceleration.csv will be about 2016.4 GB (4801 columns, "
                    "20000001 rows); Output/Recorders/Record = 'floor acceleration every <s>' "
                    "records less\n");
}
