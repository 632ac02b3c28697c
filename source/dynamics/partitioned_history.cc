// The time history of a model partitioned by building over the MPI ranks
// (dynamics/partitioned_history.h; doc/theory.md §3.5d).
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/dynamics/partitioned_history.h>

#include <deal.II/base/exceptions.h>

namespace poundfe
{
  namespace
  {
    /// The partition of `analysis` over the ranks of `communicator`.
    BuildingPartition
    split(const Analysis &analysis, const TimeHistoryParameters &parameters,
          const MPI_Comm communicator)
    {
      int n_ranks = 1;
      MPI_Comm_size(communicator, &n_ranks);
      return partition_by_building(analysis.model, analysis.system, n_ranks,
                                   parameters.input.file);
    }

  } // namespace

  NewmarkParameters
  partitioned_newmark_parameters(const TimeIntegrationParameters &time_integration)
  {
    NewmarkParameters newmark     = time_integration.newmark;
    newmark.newton.tangent_update = TangentUpdate::refactorize;
    if (newmark.newton.nonlinear_solver == NonlinearSolver::automatic)
      newmark.newton.nonlinear_solver = NonlinearSolver::krylov_newton;
    return newmark;
  }

  std::string
  partitioned_block_solver(const std::string &linear_solver)
  {
    return (linear_solver == "eigen-ldlt" || linear_solver == "umfpack") ? linear_solver :
                                                                           "eigen-ldlt";
  }

  WholeModelHistory::WholeModelHistory(const Analysis              &analysis,
                                       const TimeHistoryParameters &parameters)
    : excitation(make_excitation(analysis, parameters))
    , elements(make_nonlinear_elements(analysis.model))
    , newmark(analysis.system, partitioned_block_solver(parameters.time_integration.linear_solver),
              partitioned_newmark_parameters(parameters.time_integration), &elements)
  {
    Vector p0(analysis.system.n_equations());
    excitation.load(0, p0);
    newmark.initialize(p0);
  }

  void
  WholeModelHistory::advance()
  {
    newmark.advance([this](const double t, Vector &p) { excitation.load(t, p); });
  }

  PartitionedHistory::PartitionedHistory(Analysis                    &analysis,
                                         const TimeHistoryParameters &parameters,
                                         const MPI_Comm               communicator)
    : communicator(communicator)
    , parts(split(analysis, parameters, communicator))
    , excitation(make_excitation(analysis, parameters))
    , elements(make_nonlinear_elements(analysis.model))
  {
    int rank = 0;
    MPI_Comm_rank(communicator, &rank);
    const std::array<unsigned int, 2> range = parts.equations(rank);
    keep_elements_on(elements, range);
    ownership = std::make_unique<RankPartition>(parts, communicator, elements); // renumbers
    // this rank's M, K and C; the whole model's go
    LinearSystem part = owned_part(analysis.system, range, ownership->n_ghosts());
    analysis.system   = std::move(part);
    const TimeIntegrationParameters &time_integration = parameters.time_integration;
    try
      {
        newmark = std::make_unique<NewmarkIntegrator>(
          analysis.system, partitioned_block_solver(time_integration.linear_solver),
          partitioned_newmark_parameters(time_integration), &elements, ownership.get());
      }
    catch (const InputError &e) // the integrator names the entry, not the file
      {
        throw InputError(parameters.input.file, parameters.input.line_of(e.parameter()),
                         e.parameter(), e.problem());
      }
    // Newton's messages name the model's equations
    const std::vector<std::string> names = equation_names(analysis.model);
    std::vector<std::string>       local_names(names.begin() + range[0], names.begin() + range[1]);
    for (const int g : ownership->ghost_equations())
      local_names.push_back(names[g] + " (a ghost)");
    newmark->set_equation_names(std::move(local_names));
    // the load of the whole model (its M r), this rank's equations taken:
    // once per step, not per iteration
    whole_load.resize(parts.first_equation.back());
    const unsigned int first = range[0], n_owned = range[1] - range[0];
    load = [this, first, n_owned](const double t, Vector &p) {
      excitation.load(t, whole_load);
      p.head(n_owned) = whole_load.segment(first, n_owned);
      p.tail(p.size() - n_owned).setZero();
    };
  }

  void
  PartitionedHistory::initialize()
  {
    Vector p0(newmark->displacement().size());
    load(0, p0);
    newmark->initialize(p0);
  }

  void
  PartitionedHistory::advance()
  {
    newmark->advance(load);
  }

  Vector
  PartitionedHistory::gather(const Vector &x) const
  {
    int rank = 0;
    MPI_Comm_rank(communicator, &rank);
    const auto [first, last] = ownership->global_range();
    std::vector<int> counts, offsets;
    for (unsigned int r = 0; r < parts.n_parts(); ++r)
      {
        const auto [f, l] = parts.equations(r);
        counts.push_back(l - f);
        offsets.push_back(f);
      }
    Vector whole(rank == 0 ? parts.first_equation.back() : 0);
    MPI_Gatherv(x.data(), last - first, MPI_DOUBLE, whole.data(), counts.data(),
                offsets.data(), MPI_DOUBLE, 0, communicator);
    return whole;
  }
} // namespace poundfe
