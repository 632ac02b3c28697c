// A time history of one model spread over the MPI ranks by building
// (doc/theory.md §3.5d): every rank reads the input and builds the model,
// then keeps only its part — M, K, C and K_eff of its buildings' equations,
// the nonlinear elements on them, their history variables — and steps it
// with the other ranks in lockstep (NewmarkIntegrator with a RankOwnership,
// assembly/rank_ownership.h). Per Newton iteration the ranks exchange
// the ghost values of the elements between their buildings and a few sums
// (norms, inner products, the Krylov subspace's R factors); nothing of size
// N is gathered while stepping. gather() brings a vector to rank 0 on
// request (a result, not a step's need).
#ifndef poundfe_dynamics_partitioned_history_h
#define poundfe_dynamics_partitioned_history_h

#include <poundfe/assembly/partition.h>
#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/excitation/excitation.h>
#include <poundfe/integration/newmark.h>

#include <mpi.h>

#include <exception>
#include <memory>
#include <string>

namespace poundfe
{
  /// This rank's Analysis of a model partitioned by building over
  /// `communicator`: `model` (built whole, alike on every rank) split by
  /// partition_by_building(model, ranks), then M, K, C and the damping
  /// modes of this rank's buildings only (prepare_analysis_of_buildings):
  /// no rank assembles the whole model. Collective: an error on any rank
  /// (bad input, a mechanism in one of its buildings, more ranks than
  /// separable buildings) is thrown on every rank, the first failing
  /// rank's. Each building's modes: at least `n_building_modes`.
  Analysis prepare_rank_analysis(const InputFile &input, Model model,
                                 const ModalParameters &modal, MPI_Comm communicator,
                                 unsigned int n_building_modes = 0);

  /// Collective: when `error` is set on some rank, every rank throws the
  /// error of the first such rank (an InputError stays one, naming its
  /// entry; anything else is a NumericalError with its message), so that
  /// no rank goes on alone into a collective call.
  void agree_on_error(const std::exception_ptr &error, MPI_Comm communicator);

  /// The integrator's parameters of a partitioned run: the tangent
  /// assembled (Tangent update = refactorize: the Woodbury update would
  /// couple the ranks' blocks densely) and auto as Krylov-Newton (full
  /// Newton would refactorise, at every iteration, a block that leaves out
  /// the couplings between ranks).
  NewmarkParameters partitioned_newmark_parameters(const TimeIntegrationParameters &time_integration);
  /// The one-process solver each rank factorises its block with: the
  /// input's when it is one (eigen-ldlt, umfpack), else eigen-ldlt.
  std::string partitioned_block_solver(const std::string &linear_solver);

  /// The whole model stepped on one process with the integrator's
  /// parameters and solver of a partitioned run, from rest: what a
  /// partitioned run is compared with (tests, poundfe-bench --serial).
  class WholeModelHistory
  {
  public:
    /// `analysis` must outlive this object.
    WholeModelHistory(const Analysis &analysis, const TimeHistoryParameters &parameters);
    void advance();
    const NewmarkIntegrator &integrator() const { return newmark; }
    const NonlinearElements &nonlinear_elements() const { return elements; }

  private:
    Excitation        excitation;
    NonlinearElements elements;
    NewmarkIntegrator newmark;
  };

  class PartitionedHistory
  {
  public:
    /// Collective over `communicator`. `analysis` is this rank's part
    /// (prepare_rank_analysis) or a copy of the whole model: its system
    /// becomes this rank's block (the whole M, K and C are freed); it must
    /// outlive this object. The input's nonlinear solver must reuse its
    /// factorisation (auto is krylov-newton here); its tangent is assembled
    /// (Tangent update is refactorize whatever the input says) and each
    /// rank factorises its block with the input's Linear solver when that
    /// is a one-process solver (eigen-ldlt, umfpack), else with eigen-ldlt.
    /// InputError (the input, or more ranks than separable buildings). The
    /// integrator's parameters and solver: the two functions above.
    PartitionedHistory(Analysis &analysis, const TimeHistoryParameters &parameters,
                       MPI_Comm communicator);

    /// From rest at t = 0.
    void initialize();
    /// One step of Time step (cut and refined inside as the integrator
    /// decides, alike on every rank). NumericalError on every rank if the
    /// step fails.
    void advance();
    /// Called on every rank after each accepted sub-step of a cut step
    /// (alike on every rank: it may be collective).
    void set_substep_callback(std::function<void()> callback)
    {
      newmark->set_substep_callback(std::move(callback));
    }
    /// The ground motion and nodal forces (alike on every rank).
    const Excitation &excitation() const { return ground_and_forces; }

    /// This rank's integrator: its state in the local numbering
    /// (partition.h), its statistics (alike on every rank), its energy
    /// balance (summed over the ranks).
    const NewmarkIntegrator   &integrator() const { return *newmark; }
    double                     time() const { return newmark->time(); }
    const IterationStatistics &statistics() const { return newmark->statistics(); }
    EnergyBalance              energy() const { return newmark->energy(); }
    double max_energy_error() const { return newmark->max_energy_error(); }
    const Vector &displacement() const { return newmark->displacement(); }

    /// Every rank's own entries of `x` (a vector of this rank's part, in
    /// its local numbering) in one vector of the whole model on rank 0;
    /// empty on the others. Collective.
    Vector gather(const Vector &x) const;
    /// The same into `whole` (sized by the caller on rank 0: no allocation).
    void gather(const Vector &x, Vector &whole) const;

    const BuildingPartition &partition() const { return parts; }
    /// This rank's equations in the model's numbering.
    std::array<unsigned int, 2> owned_range() const { return ownership->global_range(); }
    unsigned int n_local_elements() const { return elements.size(); }
    unsigned int n_ghosts() const { return ownership->n_ghosts(); }
    /// The ghosts in the model's numbering (local owned_range()[1] -
    /// owned_range()[0] + k is ghost k).
    const std::vector<int> &ghost_equations() const { return ownership->ghost_equations(); }
    std::string  linear_solver_name() const { return newmark->linear_solver_name(); }

  private:
    MPI_Comm                           communicator;
    BuildingPartition                  parts;
    Excitation                         ground_and_forces;
    NonlinearElements                  elements;
    std::unique_ptr<RankPartition>     ownership;
    std::unique_ptr<NewmarkIntegrator> newmark;
    LoadFunction                       load;
    Vector                             whole_load; // p of the whole model
    std::vector<int>                   gather_counts, gather_offsets; // MPI_Gatherv's, by rank
  };
} // namespace poundfe

#endif
