// Partition by building (assembly/partition.h) and the partitioned time
// history (dynamics/partitioned_history.h): the blocks that M, K and C leave
// separable, the balance of the runs, the refusal of too many ranks, and
// the trajectory of a pounding row of buildings stepped over the ranks
// against the whole model stepped on one process (the second method).
// The suite runs on any number of ranks up to four: ctest runs it on one
// (unit/assembly) and on two and three (mpi/partition).
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/assembly/partition.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/dynamics/partitioned_history.h>
#include <poundfe/input/engine_parameters.h>
#include <poundfe/input/input_parameters.h>
#include <poundfe/model/model_builder.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include "test_utilities.h"

using namespace poundfe;

namespace
{
  /// A shear building of `storeys` Bouc-Wen storeys (the text of its section).
  std::string
  shear_building(const unsigned int index, const unsigned int storeys, const double mass,
                 const double stiffness)
  {
    std::string masses, stiffnesses;
    for (unsigned int s = 0; s < storeys; ++s)
      {
        masses += (s ? ", " : "") + std::to_string(mass);
        stiffnesses += (s ? ", " : "") + std::to_string(stiffness * (1 - 0.1 * s));
      }
    return "subsection Building " + std::to_string(index) + "\n  set Name = S" +
           std::to_string(index) + "\n  set Type = shear\n  set Number of storeys = " +
           std::to_string(storeys) + "\n  set Storey heights = 3.0\n  set Floor masses = " +
           masses + "\n  set Storey stiffnesses = " + stiffnesses +
           "\n  set Storey yield drifts = 0.004\n"
           "  subsection Bouc-Wen\n    set alpha = 0.05\n  end\n"
           "  subsection Damping\n    set Type = modes\n    set Damping ratio = 0.03\n"
           "    set Modes = 1, 2\n  end\nend\n";
  }

  /// Four shear buildings of 3, 4, 3 and 2 storeys in a row, 3 mm apart,
  /// pounding (Hertz-damp) under 1.2 s of a Kanai-Tajimi motion of 0.6 g:
  /// made for this test, not one of the examples.
  const std::string row_of_buildings =
    "subsection Model\n  set Number of buildings = 4\n  set Separations = 0.003\nend\n" +
    shear_building(1, 3, 30000, 3e7) + shear_building(2, 4, 35000, 2.5e7) +
    shear_building(3, 3, 25000, 4e7) + shear_building(4, 2, 20000, 5e7) +
    "subsection Ground motion\n  set Type = kanai-tajimi\n  subsection Stochastic\n"
    "    set Soil = soft\n    set Target PGA = 0.6\n    set Duration = 4\n    set Seed = 77\n"
    "  end\nend\n"
    "subsection Contact\n  set Law = hertz-damp\n  set Stiffness = 2e9\n"
    "  set Damping from = calibrated\n  set Coefficient of restitution = 0.6\nend\n"
    "subsection Time integration\n  set Time step = 0.002\n  set End time = 1.2\n"
    "  set Newton residual tolerance = 1e-11\nend\n";

  unsigned int
  n_ranks()
  {
    return dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  }

  /// `text` in a temporary file of this rank's own (the ranks write at once).
  std::string
  rank_file(const std::string &name, const std::string &text)
  {
    const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    return poundfe_test::temporary_file("partition-" + name + "-" + std::to_string(rank) + ".prm",
                                        text);
  }
  /// The input's model stepped two ways from rest: whole on this process
  /// (the reference), and over every rank, each assembling its own
  /// buildings (prepare_rank_analysis).
  struct WholeAndPartitioned
  {
    explicit WholeAndPartitioned(const InputParameters &input)
      : parameters(time_history_parameters(input))
      , whole(prepare_analysis(input))
      , serial(whole, parameters)
      , mine(prepare_rank_analysis(input, MPI_COMM_WORLD))
      , partitioned(mine, parameters, MPI_COMM_WORLD)
    {
      partitioned.initialize();
    }

    const TimeHistoryParameters parameters;
    Analysis                    whole;
    WholeModelHistory           serial;
    Analysis                    mine;
    PartitionedHistory          partitioned;
  };

  /// Both runs `n_steps` steps on; then the largest difference of the final
  /// displacements relative to the whole model's largest (on rank 0; 0 on
  /// the others).
  double
  final_difference(WholeModelHistory &serial, PartitionedHistory &partitioned,
                   const unsigned int n_steps)
  {
    for (unsigned int step = 0; step < n_steps; ++step)
      {
        serial.advance();
        partitioned.advance();
      }
    const Vector u = partitioned.gather(partitioned.displacement());
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return 0;
    const Vector &reference = serial.integrator().displacement();
    return (u - reference).lpNorm<Eigen::Infinity>() / reference.lpNorm<Eigen::Infinity>();
  }
} // namespace

BOOST_AUTO_TEST_SUITE(partition)

// Buildings 1 and 3 of five joined by a (made-up) stiffness entry: buildings
// 1-3 become one block, whatever lies between; 0 and 4 stay alone. The
// cut nearest to N/2 on these blocks is checked against all cuts.
BOOST_AUTO_TEST_CASE(blocks_follow_the_couplings_of_m_k_and_c)
{
  std::string text = "subsection Model\n  set Number of buildings = 5\n  set Separations = 0.01\nend\n";
  const unsigned int storeys[] = {3, 2, 4, 3, 5};
  for (unsigned int b = 0; b < 5; ++b)
    text += shear_building(b + 1, storeys[b], 30000, 3e7);
  text += "subsection Ground motion\n  set Type = none\nend\n";
  const InputParameters input    = read_parameters(rank_file("five", text));
  Analysis              analysis = prepare_analysis(input);
  BOOST_TEST(partition_by_building(analysis.model, analysis.system, 5, "five.prm").n_blocks == 5u);

  const unsigned int i = analysis.model.equation_range(1)[0], j = analysis.model.equation_range(3)[0];
  analysis.system.stiffness.coeffRef(i, j) += 1.0;
  analysis.system.stiffness.coeffRef(j, i) += 1.0;
  const BuildingPartition two = partition_by_building(analysis.model, analysis.system, 2, "five.prm");
  BOOST_TEST(two.n_blocks == 3u);
  // blocks: {0} 3 equations, {1,2,3} 9, {4} 5; N = 17: the cut after {0}
  // leaves 3 | 14, after {1,2,3} 12 | 5; |12 - 8.5| < |3 - 8.5|
  BOOST_TEST(two.first_building == std::vector<unsigned int>({0, 4, 5}), boost::test_tools::per_element());
  BOOST_TEST(two.first_equation == std::vector<unsigned int>({0, 12, 17}), boost::test_tools::per_element());
  const BuildingPartition three = partition_by_building(analysis.model, analysis.system, 3, "five.prm");
  BOOST_TEST(three.first_building == std::vector<unsigned int>({0, 1, 4, 5}), boost::test_tools::per_element());

  try
    {
      partition_by_building(analysis.model, analysis.system, 4, "five.prm");
      BOOST_FAIL("four ranks for three blocks were accepted");
    }
  catch (const InputError &e)
    {
      BOOST_TEST(e.parameter() == "the number of MPI ranks");
      BOOST_TEST(std::string(e.what()).find("3 parts only") != std::string::npos);
      BOOST_TEST(std::string(e.what()).find("at most 3 ranks") != std::string::npos);
    }
}

// The couplings a partition keeps, from the model's elements
// (coupled_buildings, nothing assembled), against those of the whole
// model's assembled M, K and C (the second method): the same blocks for
// every shipped model of several buildings (frames, shear and 3D buildings,
// compliant foundations, links, P-Delta). None of them joins two buildings
// by a linear term; a storey link made up between buildings 2 and 4 of five
// must be found, keep 2-4 together, and stop the assembly of building 2
// alone (an entry across the part's edge).
BOOST_AUTO_TEST_CASE(couplings_from_the_elements_are_those_of_the_matrices)
{
  for (const std::string name :
       {"3d-setback-vertical", "3d-torsional-pair", "3d-torsional-shear-pair", "floor-to-column",
        "linked-shear-pair", "mitigation-shear-pair", "soil-frame-pair", "soil-shear-pair",
        "three-buildings-row", "two-buildings"})
    for (const bool p_delta : {false, true})
      {
        InputParameters input = read_parameters("input/" + name + ".prm");
        if (p_delta)
          input.model.geometric_nonlinearity = GeometricNonlinearity::p_delta;
        const Analysis          whole = prepare_analysis(input);
        const BuildingPartition from_model =
          partition_by_building(whole.model, 1, input.file);
        const BuildingPartition from_matrices =
          partition_by_building(whole.model, whole.system, 1, input.file);
        BOOST_TEST_INFO(name << (p_delta ? " with P-Delta" : ""));
        BOOST_TEST(from_model.n_blocks == from_matrices.n_blocks);
        BOOST_TEST(from_model.n_blocks == whole.model.buildings.size());
      }

  std::string text = "subsection Model\n  set Number of buildings = 5\n  set Separations = 0.01\nend\n";
  for (unsigned int b = 0; b < 5; ++b)
    text += shear_building(b + 1, 3, 30000, 3e7);
  text += "subsection Ground motion\n  set Type = none\nend\n";
  const InputParameters input = read_parameters(rank_file("linked", text));
  Model model = build_model(input.model, input.contact, input, input.springs, input.friction);
  StoreyLink link;
  link.nodes     = {{model.buildings[1].first_node + 1, model.buildings[3].first_node + 2}};
  link.stiffness = 1e6;
  link.building  = 1;
  model.links.push_back(link);
  const std::vector<std::array<unsigned int, 2>> joined = coupled_buildings(model);
  BOOST_TEST_REQUIRE(joined.size() == 1u);
  BOOST_TEST(joined[0][0] == 1u);
  BOOST_TEST(joined[0][1] == 3u);
  BOOST_TEST(partition_by_building(model, 1, input.file).n_blocks == 3u);
  BOOST_TEST(partition_by_building(model, assemble_mass_and_stiffness(model), 1, input.file)
               .n_blocks == 3u);
  BOOST_CHECK_THROW(assemble_mass_and_stiffness(model, model.equation_range(1)), std::exception);
}

// A rank's part (prepare_analysis_of_buildings of one building) against the
// whole model's analysis: M, K, C, the foundations' M and K and K_G equal
// on the building's block, and nothing outside it. M, K and C come from
// the same element terms and the same building eigenproblem, so they must
// be equal to the last bit; K_G comes from the building's own gravity
// analysis (a Cholesky factor of its block, not of the whole K), equal to
// round-off: 1e-12 of its largest entry.
BOOST_AUTO_TEST_CASE(a_rank_part_is_the_block_of_the_whole_model)
{
  for (const std::string name : {"3d-torsional-pair", "soil-frame-pair", "soil-shear-pair",
                                 "three-buildings-row", "two-buildings", "3d-setback-vertical"})
    for (const bool p_delta : {false, true})
      {
        InputParameters input = read_parameters("input/" + name + ".prm");
        input.output.n_modes  = 0;
        if (p_delta)
          input.model.geometric_nonlinearity = GeometricNonlinearity::p_delta;
        const Analysis whole = prepare_analysis(input);
        for (unsigned int b = 0; b < whole.model.buildings.size(); ++b)
          {
            const Analysis part = prepare_analysis_of_buildings(
              input, build_model(input.model, input.contact, input, input.springs, input.friction),
              input.modal, {{b, b + 1}}, 0);
            const auto range = whole.model.equation_range(b);
            for (const auto &[matrix, of_whole, tolerance] :
                 {std::tuple{&part.system.mass, &whole.system.mass, 0.0},
                  std::tuple{&part.system.stiffness, &whole.system.stiffness, p_delta ? 1e-12 : 0.0},
                  std::tuple{&part.system.damping, &whole.system.damping, p_delta ? 1e-12 : 0.0},
                  std::tuple{&part.system.structure_mass, &whole.system.structure_mass, 0.0},
                  std::tuple{&part.system.structure_stiffness, &whole.system.structure_stiffness,
                             p_delta ? 1e-12 : 0.0},
                  std::tuple{&part.system.geometric_stiffness, &whole.system.geometric_stiffness,
                             1e-12}})
              {
                BOOST_TEST_INFO(name << (p_delta ? " with P-Delta" : "") << ", building " << b);
                BOOST_TEST_REQUIRE(matrix->rows() == of_whole->rows());
                if (matrix->rows() == 0)
                  continue;
                const SparseMatrix mine = block(*matrix, range), theirs = block(*of_whole, range);
                const double scale = Eigen::MatrixXd(theirs).lpNorm<Eigen::Infinity>();
                BOOST_TEST(Eigen::MatrixXd(mine - theirs).lpNorm<Eigen::Infinity>() <=
                           tolerance * scale);
                // nothing outside the block
                BOOST_TEST(matrix->nonZeros() == mine.nonZeros());
              }
            BOOST_TEST(part.building_modes[b].n_modes() == whole.building_modes[b].n_modes());
          }
      }
}

// The part of a rank: its block of M, K, C numbered from 0, then empty ghost
// rows; the influence vector cut alike.
BOOST_AUTO_TEST_CASE(owned_part_is_the_block_with_empty_ghost_rows)
{
  const InputParameters input =
    read_parameters(rank_file("row", row_of_buildings));
  const Analysis     analysis = prepare_analysis(input);
  const auto         range    = analysis.model.equation_range(1); // building 2: 4 storeys
  const LinearSystem part     = owned_part(analysis.system, range, 3);
  BOOST_TEST(part.n_equations() == 4u + 3u);
  const Eigen::MatrixXd whole(analysis.system.stiffness);
  const Eigen::MatrixXd mine(part.stiffness);
  BOOST_TEST((mine.topLeftCorner(4, 4) - whole.block(range[0], range[0], 4, 4)).norm() == 0.0);
  BOOST_TEST(mine.bottomRows(3).norm() == 0.0);
  BOOST_TEST(Eigen::MatrixXd(part.damping).rightCols(3).norm() == 0.0);
  BOOST_TEST(part.influence.head(4).sum() == 4.0);
  BOOST_TEST(part.influence.tail(3).norm() == 0.0);
}

// The row of buildings stepped over every rank of MPI_COMM_WORLD against the
// whole model stepped here on one process, with each method that reuses a
// factorisation: every step's displacements (gathered to rank 0) within
// 1e-8 of the peak. The two iterate alike while no frozen tangent holds a
// closed gap between two ranks' buildings; after one does, they stop at
// different iterates within the Newton tolerance (1e-11 of the first
// residual), which the trajectory carries at most about 1e3 times larger.
// Gaps between two ranks' buildings must close (buildings 2 and 3 pound,
// and the cut for two or three ranks runs between them), and the energy summed over
// the ranks must balance as the whole model's does.
BOOST_AUTO_TEST_CASE(partitioned_run_follows_the_whole_model)
{
  const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  BOOST_TEST_REQUIRE(n_ranks() <= 4u);
  const std::string file = rank_file("row", row_of_buildings);
  for (const NonlinearSolver method :
       {NonlinearSolver::krylov_newton, NonlinearSolver::modified_newton, NonlinearSolver::bfgs})
    {
      InputParameters input = read_parameters(file);
      input.time_integration.newmark.newton.nonlinear_solver = method;
      const TimeHistoryParameters parameters = time_history_parameters(input);
      const std::string name = nonlinear_solver_names().name(method);

      // the whole model, here
      Analysis                 whole = prepare_analysis(input);
      WholeModelHistory        serial(whole, parameters);
      const NewmarkIntegrator &reference = serial.integrator();

      // the same over the ranks, each assembling its own buildings only
      Analysis           mine = prepare_rank_analysis(input, MPI_COMM_WORLD);
      PartitionedHistory partitioned(mine, parameters, MPI_COMM_WORLD);
      partitioned.initialize();
      const std::vector<unsigned int> &first = partitioned.partition().first_equation;
      const auto owner = [&first](const int i) {
        return std::upper_bound(first.begin(), first.end(), (unsigned int)i) - first.begin();
      };

      double       peak = 0, difference = 0;
      unsigned int cross_contacts = 0;
      const unsigned long n_steps = std::lround(1.2 / 0.002);
      for (unsigned long step = 0; step < n_steps; ++step)
        {
          serial.advance();
          partitioned.advance();
          const Vector u = partitioned.gather(partitioned.displacement());
          if (rank == 0)
            {
              peak       = std::max(peak, reference.displacement().lpNorm<Eigen::Infinity>());
              difference = std::max(difference, (u - reference.displacement()).lpNorm<Eigen::Infinity>());
            }
          // a gap between two ranks, closed
          for (const NonlinearElement &e : serial.nonlinear_elements())
            if (e.kind == ElementKind::gap && e.is_active() &&
                owner(e.equations()[0]) != owner(e.equations()[1]))
              ++cross_contacts;
        }
      BOOST_TEST_MESSAGE(name << " on " << n_ranks() << " rank(s): largest difference "
                              << difference / std::max(peak, 1e-300) << " of the peak "
                              << peak << " m; " << cross_contacts
                              << " steps with a gap between two ranks closed; energy error "
                              << partitioned.max_energy_error() << " (whole model "
                              << reference.max_energy_error() << ")");
      if (rank == 0)
        BOOST_TEST(difference <= 1e-8 * peak);
      if (n_ranks() > 1)
        BOOST_TEST(cross_contacts > 0u);
      BOOST_TEST(partitioned.energy().contact > 0.0);
      BOOST_TEST(partitioned.energy().contact == reference.energy().contact,
                 boost::test_tools::tolerance(1e-6));
      BOOST_TEST(partitioned.energy().hysteretic == reference.energy().hysteretic,
                 boost::test_tools::tolerance(1e-6));
      BOOST_TEST(partitioned.max_energy_error() < 1e-6);
      BOOST_TEST(partitioned.statistics().steps == reference.statistics().steps);
    }
}

// Buildings 2 and 3 elastic and no contact law: with two or three ranks some
// rank owns no nonlinear element, and must still take part in every sum of
// the others' Newton iterations (it would wait for ever otherwise).
BOOST_AUTO_TEST_CASE(a_rank_without_nonlinear_elements_steps_with_the_others)
{
  std::string text = "subsection Model\n  set Number of buildings = 3\n  set Separations = 0.01\nend\n" +
                     shear_building(1, 3, 30000, 3e7);
  for (const unsigned int b : {2u, 3u})
    text += "subsection Building " + std::to_string(b) +
            "\n  set Type = shear\n  set Number of storeys = " + std::to_string(b) +
            "\n  set Storey heights = 3.0\n  set Floor masses = 20000\n"
            "  set Storey stiffnesses = 4e7\nend\n";
  text += "subsection Ground motion\n  set Type = kanai-tajimi\n  subsection Stochastic\n"
          "    set Target PGA = 0.4\n    set Duration = 2\n    set Seed = 5\n  end\nend\n"
          "subsection Contact\n  set Law = none\nend\n"
          "subsection Time integration\n  set Time step = 0.005\n  set End time = 0.5\n"
          "  set Nonlinear solver = modified-newton\n  set Newton residual tolerance = 1e-11\nend\n";
  const InputParameters input = read_parameters(rank_file("elastic", text));
  WholeAndPartitioned   runs(input);
  if (n_ranks() > 1)
    BOOST_TEST(dealii::Utilities::MPI::min(runs.partitioned.n_local_elements(), MPI_COMM_WORLD) ==
               0u);
  BOOST_TEST(final_difference(runs.serial, runs.partitioned, 100) <= 1e-10);
}

// A 3D pair with plan contact (a nonsymmetric tangent) and a Linear solver
// that is not a one-process direct solver: each rank factorises its block with
// UMFPACK, and the run follows the whole model's. On three ranks the pair is
// refused on every rank.
BOOST_AUTO_TEST_CASE(nonsymmetric_tangents_get_an_lu_block_solver)
{
  InputParameters input = read_parameters("input/3d-torsional-pair.prm");
  input.time_integration.linear_solver                  = "petsc";
  input.time_integration.newmark.newton.nonlinear_solver = NonlinearSolver::krylov_newton;
  const TimeHistoryParameters parameters = time_history_parameters(input);
  Analysis                    whole      = prepare_analysis(input);
  WholeModelHistory           serial(whole, parameters);
  if (n_ranks() > 2) // two buildings: every rank refuses alike
    {
      BOOST_CHECK_THROW(prepare_rank_analysis(input, MPI_COMM_WORLD), InputError);
      return;
    }
  Analysis           mine = prepare_rank_analysis(input, MPI_COMM_WORLD);
  PartitionedHistory partitioned(mine, parameters, MPI_COMM_WORLD);
  partitioned.initialize();
  BOOST_TEST(partitioned.linear_solver_name() == "umfpack");
  BOOST_TEST(final_difference(serial, partitioned, 200) <= 1e-8);
}

// The secant line search and Steps per shortest period over ranks: the
// line search's inner products and refusals are sums and agreements, the
// highest-frequency bound the largest of the ranks' (their rows are the
// model's), so the ranks search and sub-step alike and follow the whole
// model on one process. The row of buildings at 60 steps per shortest
// period sub-steps every step (asserted), and the line search must change
// some step (asserted), so that neither passes by doing nothing.
BOOST_AUTO_TEST_CASE(line_search_and_steps_per_period_follow_the_whole_model)
{
  for (const bool line_search : {true, false})
    {
      InputParameters input = read_parameters(rank_file("row", row_of_buildings));
      NewmarkParameters &newmark = input.time_integration.newmark;
      newmark.newton.nonlinear_solver = NonlinearSolver::modified_newton;
      newmark.newton.line_search      = line_search;
      // a tolerance that the frozen tangent misses during contact
      newmark.newton.line_search_parameters.tolerance = 0.1;
      // the bound on the shortest period is 0.065 s (building 4's top floor:
      // 32 steps of 2 ms): 60 per period halves every step
      newmark.steps_per_period = line_search ? 0 : 60;
      WholeAndPartitioned        runs(input);
      const double               difference = final_difference(runs.serial, runs.partitioned, 600);
      const IterationStatistics &s          = runs.partitioned.statistics();
      const IterationStatistics &reference  = runs.serial.integrator().statistics();
      BOOST_TEST_MESSAGE((line_search ? "line search" : "60 steps per shortest period")
                         << " on " << n_ranks() << " rank(s): final difference " << difference
                         << " of the peak; " << s.line_searches << " line searches, "
                         << s.accuracy_refinements << " steps sub-stepped for accuracy, "
                         << s.steps << " (sub-)steps");
      BOOST_TEST(difference <= 1e-8);
      BOOST_TEST(s.steps == reference.steps);
      BOOST_TEST(s.line_searches == reference.line_searches);
      BOOST_TEST(s.accuracy_refinements == reference.accuracy_refinements);
      if (line_search)
        BOOST_TEST(s.line_searches > 0u);
      else
        BOOST_TEST(s.accuracy_refinements >= 600u);
    }
}

// Modal damping over ranks: U diag(w) Uᵀ is block diagonal by building, so
// each rank keeps its own buildings' columns (owned_modal_damping) and
// solves K_eff + c U D Uᵀ of its block by Woodbury; the row of buildings
// with two modal damping ratios per building must follow the whole model,
// with the damping energy alike (the eight columns asserted on both sides).
BOOST_AUTO_TEST_CASE(modal_damping_follows_the_whole_model)
{
  std::string text = row_of_buildings;
  const std::string rayleigh = "    set Type = modes\n    set Damping ratio = 0.03\n    set Modes = 1, 2\n";
  for (std::size_t at = text.find(rayleigh); at != std::string::npos; at = text.find(rayleigh))
    text.replace(at, rayleigh.size(), "    set Type = modal\n    set Modal ratios = 0.05, 0.08\n");
  InputParameters input = read_parameters(rank_file("modal", text));
  input.time_integration.newmark.newton.nonlinear_solver = NonlinearSolver::krylov_newton;
  WholeAndPartitioned runs(input);
  const WholeModelHistory  &serial      = runs.serial;
  PartitionedHistory       &partitioned = runs.partitioned;
  BOOST_TEST_REQUIRE(runs.whole.system.modal_damping.factor.cols() == 8);
  const unsigned int n_columns =
    dealii::Utilities::MPI::sum(runs.mine.system.modal_damping.factor.cols(), MPI_COMM_WORLD);
  BOOST_TEST(n_columns == 8u); // two modes of each of four buildings, each on one rank
  const double difference = final_difference(runs.serial, partitioned, 600);
  BOOST_TEST_MESSAGE("modal damping on " << n_ranks() << " rank(s): final difference "
                                         << difference << " of the peak; energy error "
                                         << partitioned.max_energy_error());
  BOOST_TEST(difference <= 1e-8);
  BOOST_TEST(partitioned.statistics().steps == serial.integrator().statistics().steps);
  BOOST_TEST(partitioned.energy().damping == serial.integrator().energy().damping,
             boost::test_tools::tolerance(1e-6));
  BOOST_TEST(partitioned.max_energy_error() < 1e-6);
}

// Full Newton would refactorise a block that leaves out the couplings
// between ranks at every iteration: refused with the entry named.
BOOST_AUTO_TEST_CASE(full_newton_is_refused_over_ranks)
{
  InputParameters input = read_parameters(rank_file("row", row_of_buildings));
  input.time_integration.newmark.newton.nonlinear_solver = NonlinearSolver::newton;
  Analysis analysis = prepare_analysis(input);
  try
    {
      PartitionedHistory history(analysis, time_history_parameters(input), MPI_COMM_WORLD);
      BOOST_FAIL("full Newton was accepted");
    }
  catch (const InputError &e)
    {
      BOOST_TEST(e.parameter() == "Time integration/Nonlinear solver");
      BOOST_TEST(std::string(e.what()).find("krylov-newton") != std::string::npos);
    }
}

BOOST_AUTO_TEST_SUITE_END()
