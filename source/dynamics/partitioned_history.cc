// The time history of a model partitioned by building over the MPI ranks
// (dynamics/partitioned_history.h; doc/theory.md §3.5d).
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/dynamics/partitioned_history.h>

#include <poundfe/base/exceptions.h>

#include <deal.II/base/exceptions.h>

#include <exception>
#include <string>

namespace poundfe
{
  namespace
  {
    /// The partition of `model` over the ranks of `communicator`, from its
    /// elements (coupled_buildings): alike on every rank, whether its
    /// Analysis is the whole model's or its own part.
    BuildingPartition
    split(const Model &model, const std::string &file, const MPI_Comm communicator)
    {
      int n_ranks = 1;
      MPI_Comm_size(communicator, &n_ranks);
      return partition_by_building(model, n_ranks, file);
    }

    int
    rank_of(const MPI_Comm communicator)
    {
      int rank = 0;
      MPI_Comm_rank(communicator, &rank);
      return rank;
    }

    /// Bytes of `text` from rank `root` to every rank of `communicator`.
    void
    broadcast(std::string &text, const int root, const MPI_Comm communicator)
    {
      int length = text.size();
      MPI_Bcast(&length, 1, MPI_INT, root, communicator);
      text.resize(length);
      MPI_Bcast(text.data(), length, MPI_CHAR, root, communicator);
    }

  } // namespace

  void
  agree_on_error(const std::exception_ptr &error, const MPI_Comm communicator)
    {
      int rank = 0, size = 1;
      MPI_Comm_rank(communicator, &rank);
      MPI_Comm_size(communicator, &size);
      int first = error ? rank : size;
      MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, communicator);
      if (first == size)
        return;
      int         input_error = 0, line = 0;
      std::string file, parameter, problem;
      if (rank == first)
        try
          {
            std::rethrow_exception(error);
          }
        catch (const InputError &e)
          {
            input_error = 1;
            file        = e.file();
            line        = e.line();
            parameter   = e.parameter();
            problem     = e.problem();
          }
        catch (const std::exception &e)
          {
            problem = e.what();
          }
      MPI_Bcast(&input_error, 1, MPI_INT, first, communicator);
      MPI_Bcast(&line, 1, MPI_INT, first, communicator);
      for (std::string *text : {&file, &parameter, &problem})
        broadcast(*text, first, communicator);
      if (rank == first)
        std::rethrow_exception(error);
      if (input_error)
        throw InputError(file, line, parameter, problem);
      throw NumericalError(problem);
    }

  Analysis
  prepare_rank_analysis(const InputFile &input, Model model, const ModalParameters &modal,
                        const MPI_Comm communicator, const unsigned int n_building_modes)
  {
    const int          rank = rank_of(communicator);
    Analysis           analysis;
    std::exception_ptr error;
    try
      {
        const BuildingPartition parts = split(model, input.file, communicator);
        const std::array<unsigned int, 2> buildings{
          {parts.first_building[rank], parts.first_building[rank + 1]}};
        analysis = prepare_analysis_of_buildings(input, std::move(model), modal, buildings,
                                                 n_building_modes);
      }
    catch (const std::exception &)
      {
        error = std::current_exception();
      }
    agree_on_error(error, communicator);
    return analysis;
  }

  NewmarkParameters
  partitioned_newmark_parameters(const TimeIntegrationParameters &time_integration)
  {
    NewmarkParameters newmark     = time_integration.newmark;
    newmark.newton.tangent_update = TangentUpdate::refactorize;
    if (newmark.newton.nonlinear_solver == NonlinearSolver::automatic)
      newmark.newton.nonlinear_solver = NonlinearSolver::krylov_newton;
    // the block solver is ours to choose: UMFPACK where a rank's elements
    // have a nonsymmetric tangent, on that rank alone
    newmark.lu_when_nonsymmetric = true;
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
    , parts(split(analysis.model, parameters.input.file, communicator))
    , ground_and_forces(make_excitation(analysis, parameters))
    , elements(make_nonlinear_elements(analysis.model, parts.equations(rank_of(communicator))))
  {
    const std::array<unsigned int, 2> range = parts.equations(rank_of(communicator));
    for (unsigned int r = 0; r < parts.n_parts(); ++r)
      {
        gather_counts.push_back(parts.equations(r)[1] - parts.equations(r)[0]);
        gather_offsets.push_back(parts.equations(r)[0]);
      }
    ownership = std::make_unique<RankPartition>(parts, communicator, elements); // renumbers
    // this rank's M, K and C; the assembled ones go at once (a named part
    // moved in would hold them, swapped, until the end of this constructor,
    // through the factorisations: 127 MiB per rank at 1.94 M equations)
    analysis.system = owned_part(analysis.system, range, ownership->n_ghosts());
    const TimeIntegrationParameters &time_integration = parameters.time_integration;
    // a refusal or a singular block on one rank stops every rank
    std::exception_ptr error;
    try
      {
        newmark = std::make_unique<NewmarkIntegrator>(
          analysis.system, partitioned_block_solver(time_integration.linear_solver),
          partitioned_newmark_parameters(time_integration), &elements, ownership.get());
      }
    catch (const InputError &e) // the integrator names the entry, not the file
      {
        error = std::make_exception_ptr(InputError(parameters.input.file,
                                                   parameters.input.line_of(e.parameter()),
                                                   e.parameter(), e.problem()));
      }
    catch (const std::exception &)
      {
        error = std::current_exception();
      }
    agree_on_error(error, communicator);
    // Newton's messages name the model's equations, when they need one
    const Model     &model  = analysis.model;
    const unsigned int first_own = range[0], n_own = range[1] - range[0];
    newmark->set_equation_namer([&model, first_own, n_own, this](const unsigned int i) {
      return i < n_own ? equation_name(model, first_own + i) :
                         equation_name(model, ownership->ghost_equations()[i - n_own]) +
                           " (a ghost)";
    });
    // the load of the whole model (its M r), this rank's equations taken:
    // once per step, not per iteration
    whole_load.resize(parts.first_equation.back());
    const unsigned int first = range[0], n_owned = range[1] - range[0];
    load = [this, first, n_owned](const double t, Vector &p) {
      ground_and_forces.load(t, whole_load);
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
    Vector whole(rank_of(communicator) == 0 ? parts.first_equation.back() : 0);
    gather(x, whole);
    return whole;
  }

  void
  PartitionedHistory::gather(const Vector &x, Vector &whole) const
  {
    const auto [first, last] = ownership->global_range();
    Assert(rank_of(communicator) != 0 || whole.size() == parts.first_equation.back(),
           dealii::ExcDimensionMismatch(whole.size(), parts.first_equation.back()));
    MPI_Gatherv(x.data(), last - first, MPI_DOUBLE, whole.data(), gather_counts.data(),
                gather_offsets.data(), MPI_DOUBLE, 0, communicator);
  }
} // namespace poundfe
