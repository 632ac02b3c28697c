// The stepper of a run partitioned by building (dynamics/partitioned_stepper.h;
// doc/theory.md §3.5d).
#include <poundfe/dynamics/partitioned_stepper.h>
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>

#include <deal.II/base/mpi.h>

// what Utilities::MPI::gather sends of the buildings' report
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <cmath>
#include <utility>

namespace poundfe
{
  namespace
  {
    /// Rank 0's report of a partitioned run needs every building's Rayleigh
    /// coefficients, modes (their frequencies and participating masses; no
    /// shapes) and set-up warnings, which each rank has of its own
    /// buildings alone: gathered there. Collective.
    void
    gather_buildings_report(Analysis &analysis, const MPI_Comm communicator)
    {
      const unsigned int n_buildings = analysis.model.buildings.size();
      // a building's coefficients are set on its own rank and zero on the others
      std::vector<double> rayleigh;
      for (const std::array<double, 2> &c : analysis.system.rayleigh)
        rayleigh.insert(rayleigh.end(), c.begin(), c.end());
      AssertDimension(rayleigh.size(), 2 * n_buildings);
      MPI_Allreduce(MPI_IN_PLACE, rayleigh.data(), rayleigh.size(), MPI_DOUBLE, MPI_SUM,
                    communicator);
      for (unsigned int b = 0; b < n_buildings; ++b)
        analysis.system.rayleigh[b] = {{rayleigh[2 * b], rayleigh[2 * b + 1]}};
      // [building, n, n_y, omega, ratio x, ratio y, ratio rz] of each building with modes here
      std::vector<double> modes;
      for (unsigned int b = 0; b < n_buildings; ++b)
        if (const Modes &m = analysis.building_modes[b]; m.n_modes() > 0)
          {
            modes.insert(modes.end(), {double(b), double(m.n_modes()),
                                       double(m.participating_mass_ratio_y.size())});
            for (const std::vector<double> *x :
                 {&m.omega, &m.participating_mass_ratio, &m.participating_mass_ratio_y,
                  &m.participating_mass_ratio_rz})
              modes.insert(modes.end(), x->begin(), x->end());
          }
      using Gathered = std::pair<std::vector<double>, std::vector<std::string>>;
      const std::vector<Gathered> all = dealii::Utilities::MPI::gather(
        communicator, Gathered{modes, analysis.warnings}, 0);
      if (all.empty()) // not rank 0
        return;
      analysis.warnings.clear();
      for (const auto &[rank_modes, warnings] : all)
        {
          analysis.warnings.insert(analysis.warnings.end(), warnings.begin(), warnings.end());
          for (auto x = rank_modes.begin(); x != rank_modes.end();)
            {
              const unsigned int b = x[0], n = x[1], n_y = x[2];
              Modes &m = analysis.building_modes[b];
              x += 3;
              for (auto [y, size] : {std::pair{&m.omega, n}, {&m.participating_mass_ratio, n},
                                     {&m.participating_mass_ratio_y, n_y},
                                     {&m.participating_mass_ratio_rz, n_y}})
                {
                  y->assign(x, x + size);
                  x += size;
                }
            }
        }
    }

    /// What a partitioned run refuses (InputError, alike on every rank), then
    /// the buildings' report gathered to rank 0: `analysis`, ready for the run.
    Analysis &
    checked_for_partitioned_run(Analysis &analysis, const TimeHistoryParameters &time_history,
                                const MPI_Comm communicator)
    {
      const InputFile &input = time_history.input;
      if (!analysis.model.friction_surfaces.empty())
        input.fail("Time integration/Partition",
                   "buildings does not take friction surfaces (their stick-slip report needs "
                   "the whole mass matrix on rank 0)");
      if (!time_history.initial_conditions.at_rest())
        input.fail("Time integration/Partition",
                   "buildings starts from rest: leave the Initial conditions section empty");
      gather_buildings_report(analysis, communicator);
      return analysis;
    }

    /// `local` (this rank's vector: its equations, then its ghosts) into
    /// the model's numbering, in `whole`.
    void
    place_own_values(const PartitionedHistory &history, const Vector &local, Vector &whole)
    {
      const auto              range = history.owned_range();
      const unsigned int      n_own = range[1] - range[0];
      const std::vector<int> &ghost = history.ghost_equations();
      whole.segment(range[0], n_own) = local.head(n_own);
      for (unsigned int k = 0; k < ghost.size() && n_own + k < local.size(); ++k)
        whole[ghost[k]] = local[n_own + k];
    }
  } // namespace

  PartitionedStepper::PartitionedStepper(Analysis &analysis, const TimeHistoryParameters &parameters,
                                         const MPI_Comm communicator)
    : communicator(communicator)
    , part(checked_for_partitioned_run(analysis, parameters, communicator), parameters,
               communicator)
    , elements(make_nonlinear_elements(analysis.model))
    , ranks(analysis.model, part, elements, communicator)
    , replayed(elements, analysis.model.n_equations(), ranks.observed())
  {}

  std::unique_ptr<StepObserver>
  PartitionedStepper::field_recorder(const Model &model, const std::string &directory,
                                     const FieldFormat format, const unsigned int every,
                                     const bool impact_peaks)
  {
    const bool                 together = format == FieldFormat::xdmf;
    std::unique_ptr<VtuSeries> series; // every rank's, or rank 0's
    if (together)
      series = std::make_unique<VtuSeries>(model, directory, "solution", communicator);
    else if (ranks.writes_files())
      series = std::make_unique<VtuSeries>(model, directory, "solution", format);
    gap_forces_asked = impact_peaks;
    auto recorder    = std::make_unique<RankFieldRecorder>(ranks, std::move(series), every,
                                                        together,
                                                        impact_peaks ? &gap_force : nullptr);
    field         = recorder.get();
    return recorder;
  }

  void
  PartitionedStepper::set_observed(ResponseView &view) const
  {
    view.set_observed(&ranks.observed(), &ranks.buildings());
  }

  void
  PartitionedStepper::keep_failure(const std::function<void()> &action)
  {
    try
      {
        action();
      }
    catch (const OutputError &e)
      {
        stop_reason   = e.what();
        output_failed = true;
      }
    catch (const NumericalError &e) // a value rank 0 may not write (NaN): told at the next step
      {
        stop_reason = e.what();
      }
  }

  void
  PartitionedStepper::replay(const bool first)
  {
    // no gather: each rank places its own values and ghosts
    const NewmarkIntegrator      &newmark = part.integrator();
    const std::array<Vector *, 3> to      = replayed.state_to_fill();
    place_own_values(part, newmark.displacement(), *to[0]);
    place_own_values(part, newmark.velocity(), *to[1]);
    place_own_values(part, newmark.acceleration(), *to[2]);
    if (!stop_reason.empty())
      return;
    keep_failure([&]() {
      if (first)
        replayed.start();
      else
        replayed.replay(part.time(), newmark.last_step_length(), part.statistics().steps);
      replayed.set_integrator_state(part.energy(), part.max_energy_error(),
                                    part.statistics(), newmark.steps());
    });
  }

  void
  PartitionedStepper::initialize(const Vector &, const Vector &, const Vector &)
  {
    keep_failure([this]() { part.initialize(); }); // every rank stops at the first step
    replay(true);
    sum_gap_forces();
  }

  void
  PartitionedStepper::sum_gap_forces()
  {
    if (!gap_forces_asked)
      return;
    // each gap's force from the rank that observes it (x + 0 = x), then
    // summed in the elements' order as the whole-model recorder does
    gap_forces.assign(elements.size(), 0.0);
    for (unsigned int h = 0; h < elements.size(); ++h)
      if (elements[h].kind == ElementKind::gap && ranks.observed()[h])
        gap_forces[h] = std::abs(elements[h].force());
    MPI_Allreduce(MPI_IN_PLACE, gap_forces.data(), gap_forces.size(), MPI_DOUBLE, MPI_SUM,
                  communicator);
    gap_force = 0;
    for (const double f : gap_forces)
      gap_force += f;
  }

  void
  PartitionedStepper::advance(const LoadFunction &)
  {
    part.advance(); // a NumericalError on every rank
    replay(false);
    sum_gap_forces();
  }

  void
  PartitionedStepper::set_substep_callback(std::function<void()> callback)
  {
    substep_callback = std::move(callback);
    if (!substep_callback)
      return part.set_substep_callback(nullptr);
    part.set_substep_callback([this]() {
      replay(false);
      substep_callback();
    });
  }

  void
  PartitionedStepper::observe(const Observation call, const Observers &observers,
                              const ResponseView &view)
  {
    if (stop_reason.empty())
      keep_failure([&]() {
        for (StepObserver *observer : observers)
          (observer->*call)(view);
      });
    keep_failure([this]() { ranks.flush(); }); // on every rank, whether or not its observers ran
  }

  bool
  PartitionedStepper::agreed_stop(const bool interruptible, RunStatus &status)
  {
    // 0: go on; 1: interrupted; 2: a rank stopped (stop_reason); 3: rank 0
    // could not write (then every rank exits as an output failure: mpirun
    // reports the first rank's status)
    int stop = output_failed        ? 3 :
               !stop_reason.empty() ? 2 :
                                      (interruptible && interruption_requested());
    MPI_Allreduce(MPI_IN_PLACE, &stop, 1, MPI_INT, MPI_MAX, communicator);
    if (stop == 0)
      return false;
    status.kind          = stop == 1 ? RunStatus::Kind::interrupted : RunStatus::Kind::failed;
    status.output_failed = stop == 3;
    status.message       = stop_reason.empty() ? "another rank stopped the run" : stop_reason;
    return true;
  }

  bool
  PartitionedStepper::merged(const Observers &observers, ResponseView &view, RunStatus &status)
  {
    // the run ends where the history does (the replay stops with a rank)
    status.end_time = part.time();
    for (StepObserver *observer : observers)
      observer->merge(ranks);
    replayed.merge(ranks);
    if (!ranks.writes_files())
      {
        if (field)
          field->finish_together(status); // with rank 0's finish_observers
        return false;
      }
    view.set_stored_energies(&replayed.stored_energies());
    return true;
  }
} // namespace poundfe
