// A time history with the standard observers (report/run_outputs.h): the
// observers are chosen from the Output section, attached in the order they
// must see each step (the peaks first: the recorders read the floor
// response), and the run's scalars returned.
#include <poundfe/report/run_outputs.h>
#include <poundfe/report/run_summary.h>
#include <poundfe/base/numbers.h>
#include <poundfe/base/progress.h>
#include <poundfe/output/floor_spectra.h>
#include <poundfe/output/number_text.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/peak_response.h>
#include <poundfe/output/recorders.h>
#include <poundfe/output/response_range.h>
#include <poundfe/output/vtu_series.h>

#include <poundfe/base/exceptions.h>
#include <poundfe/base/interruption.h>
#include <poundfe/assembly/nonlinear_elements.h>
#include <poundfe/dynamics/partitioned_history.h>
#include <poundfe/integration/replayed_stepper.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <numeric>
#include <chrono>
#include <iostream>
#include <limits>
#include <memory>

namespace poundfe
{
  namespace
  {
    /// Steps done, their rate and the time left, on a terminal.
    class ProgressReport : public StepObserver
    {
    public:
      explicit ProgressReport(const unsigned long n_steps)
        : progress(std::cerr, "run: steps", n_steps)
      {}
      void
      observe_step(const ResponseView &state) override
      {
        if (state.step() % 64 == 0) // the clock is read in update(): not every step
          progress.update(state.step());
      }
      void finish(const ResponseView &, const RunStatus &) override { progress.finish(); }

    private:
      Progress progress;
    };

    /// Steps between VTU frames: Output/VTU interval, widened (with a note
    /// on `console`, when given) so that a run of `n_steps` of `dt` writes
    /// at most Output/Maximum VTU frames frames.
    unsigned int
    vtu_steps_per_frame(const OutputParameters &output, const double dt,
                        const unsigned long n_steps, std::ostream *console)
    {
      const unsigned long max      = output.max_vtu_frames;
      const unsigned int  every    = steps_per_interval(output.vtu_interval, dt);
      const unsigned long n_frames = n_steps / every + 1;
      if (n_frames <= max)
        return every;
      const unsigned long wider = (n_steps + max - 2) / (max - 1); // n_steps / wider + 1 <= max
      if (console)
        *console << "poundfe: note: Output/VTU interval = " << number_text(output.vtu_interval)
                 << " s would write " << n_frames << " VTU frames, more than Output/Maximum VTU "
                 << "frames = " << max << ": writing one every " << number_text(wider * dt)
                 << " s instead\n";
      return static_cast<unsigned int>(std::min<unsigned long>(wider, 4000000000ul));
    }

  } // namespace

  namespace
  {
    /// The standard observers of a run, in the order they see each step:
    /// the peaks and the response range first (the recorders read the
    /// floor response), then with an output directory the base shears,
    /// the input's recorders, the floor spectra, the field output and the
    /// summary, the progress on a terminal, and the caller's own. With
    /// `ranks` (observation by rank) the recorders' rows go through it, the
    /// field output is `field_recorder`'s (given the steps between frames)
    /// and a rank that does not write the files has no summary and no
    /// progress.
    class StandardObservers
    {
    public:
      using FieldRecorderMaker = std::function<std::unique_ptr<StepObserver>(unsigned int)>;

      StandardObservers(const Analysis &analysis, const RunParameters &parameters,
                        const Excitation &excitation, const ResponseView &view,
                        const NonlinearElements &elements, unsigned long n_steps,
                        const std::string &solver, const std::string &tangent_update,
                        const RunOptions &options, RowSink *ranks = nullptr,
                        const FieldRecorderMaker &field_recorder = {});

      const Observers &all() const { return observers; }
      /// Observation by rank, before the observers finish: the peaks, the
      /// range and the base shears merged on rank 0. Collective.
      void merge(const RankMerge &ranks);
      /// The run's scalars after it ended with `status`.
      RunResult result(const RunStatus &status, const ResponseView &state) const;

    private:
      PeakResponse   peaks;
      ResponseRange  range;
      // observed with an output directory only, for the summary: each
      // building's peak base shear, and a 3D model's plan at the steps
      BaseShearPeaks base_shears;
      PlanResponse   plan;
      std::unique_ptr<FloorSpectra> spectra; // with floor spectra
      std::vector<std::unique_ptr<StepObserver>> outputs;
      Observers      observers;
    };

    StandardObservers::StandardObservers(const Analysis &analysis, const RunParameters &parameters,
                                         const Excitation &excitation, const ResponseView &view,
                                         const NonlinearElements &elements,
                                         const unsigned long n_steps, const std::string &solver,
                                         const std::string &tangent_update,
                                         const RunOptions &options, RowSink *ranks,
                                         const FieldRecorderMaker &field_recorder)
      : peaks(analysis.model, elements)
      , range(analysis.model, peaks, parameters.output.drift_warning,
              parameters.output.rotation_warning)
      , plan(analysis.model)
      , observers{&peaks, &range}
    {
      const OutputParameters &output    = parameters.output;
      const double            dt        = parameters.time_history.time_integration.newmark.time_step;
      const std::string      &directory = options.output_directory;
      const bool              writes    = !ranks || ranks->writes_files();
      if (!directory.empty())
        {
          observers.insert(observers.end(), {&base_shears, &plan});
          std::vector<std::string> files; // of the recorders and VTU, for summary.json
          if (options.csv) // first: it checks its input before anything is written
            {
              Recorders recorders =
                make_recorders(output.recorders, parameters.time_history.input.file, view, peaks,
                               dt, directory, ranks);
              if (options.console && writes)
                for (const TableShape &table : recorders.tables)
                  *options.console << large_table_note(table, n_steps, output.recorders.format);
              outputs = std::move(recorders.observers);
              files   = std::move(recorders.files);
            }
          else if (writes) // the recorders prepare it after checking their input
            prepare_output_directory(directory);
          if (options.csv && output.floor_spectra) // on every rank: merged by floor
            {
              spectra = std::make_unique<FloorSpectra>(
                peaks, parameters.spectrum.periods(), parameters.spectrum.damping_ratios, directory);
              observers.push_back(spectra.get());
              files.push_back(FloorSpectra::file_name);
            }
          if (options.vtu && output.vtu_interval > 0 && (writes || field_recorder))
            {
              const unsigned int every =
                vtu_steps_per_frame(output, dt, n_steps, writes ? options.console : nullptr);
              if (field_recorder) // on every rank
                outputs.push_back(field_recorder(every));
              else
                outputs.push_back(std::make_unique<VtuRecorder>(analysis.model, directory, every,
                                                                output.field_format));
              if (output.field_format == FieldFormat::xdmf)
                files.insert(files.end(), {"solution.xdmf", "solution.h5"}); // the index, the data
              else
                files.insert(files.end(), {"solution.pvd", "solution/"}); // the index, the frames
            }
          if (writes)
            outputs.push_back(std::make_unique<RunSummary>(
              analysis, parameters, excitation, peaks, range, base_shears, plan, directory,
              options.plots && output.plots, solver, tangent_update, files));
        }
      if (options.progress && writes)
        outputs.push_back(std::make_unique<ProgressReport>(n_steps));
      for (const auto &output : outputs)
        observers.push_back(output.get());
      observers.insert(observers.end(), options.observers.begin(), options.observers.end());
    }

    void
    StandardObservers::merge(const RankMerge &ranks)
    {
      peaks.merge(ranks);
      range.merge(ranks);
      base_shears.merge(ranks);
      plan.merge(ranks);
      if (spectra)
        spectra->merge(ranks);
    }

    RunResult
    StandardObservers::result(const RunStatus &status, const ResponseView &state) const
    {
      RunResult result;
      result.status               = status;
      result.statistics           = state.statistics();
      result.energy               = state.energy();
      result.max_energy_error     = state.max_energy_error();
      result.n_nonlinear_elements = state.elements.size();
      result.n_impacts            = state.impact_log().impacts().size();
      result.warnings             = range.warnings();
      return result;
    }
  } // namespace

  RunResult
  run_time_history(const Analysis &analysis, const RunParameters &parameters,
                   const Excitation &excitation, const RunOptions &options)
  {
    TimeHistory history(analysis, parameters.time_history, options.linear_solver);
    const unsigned long     n_steps = history.n_steps(excitation); // refused before any output
    const StandardObservers observers(analysis, parameters, excitation, history.state(),
                                      history.nonlinear_elements(), n_steps,
                                      history.linear_solver_name(), history.tangent_update(),
                                      options);
    const RunStatus status = history.run(excitation, observers.all(), options.interruptible);
    return observers.result(status, history.state());
  }

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

    /// The view of `stepper`'s state, told whether the ground moves
    /// vertically before the observers are made (the recorders choose
    /// their columns by it).
    ResponseView
    view_of(const Analysis &analysis, const NonlinearElements &elements,
            const TimeStepper &stepper, const bool vertical)
    {
      ResponseView view(analysis.model, analysis.system, elements, stepper);
      view.set_vertical_ground_motion(vertical);
      return view;
    }

    /// Observation by rank (theory §3.5d): what each rank owns of the
    /// whole model — its buildings, their floors and equations, and the
    /// elements it observes (those whose first equation is its own: a gap
    /// between two ranks is observed by the rank of its lower end) — and
    /// the collective merges of base/rank_merge.h and the recorders' rows
    /// (RowSink) on rank 0 over `communicator`.
    class RanksOfRun final : public RankMerge, public RowSink
    {
    public:
      RanksOfRun(const Model &model, const PartitionedHistory &history,
                 const NonlinearElements &elements, MPI_Comm communicator);

      /// observed[h]: whether this rank observes element h.
      const std::vector<char> &observed() const { return owns[int(Owner::element)]; }
      /// buildings()[b]: whether this rank owns building b.
      const std::vector<char> &buildings() const { return owns[int(Owner::building)]; }
      /// equations()[q]: whether this rank owns equation q.
      const std::vector<char> &equations() const { return owns[int(Owner::equation)]; }
      /// available()[q]: whether this rank has the value of equation q (its
      /// own equations and its ghosts).
      const std::vector<char> &available() const { return available_equations; }

      void owned(Owner kind, std::vector<double> &values) const override;
      void owned(Owner kind, std::vector<unsigned int> &values) const override;
      void owned(Owner kind, const std::vector<unsigned int> &entity_of,
                 std::vector<double> &values) const override;
      void least(double &value) const override;
      void concatenated(std::vector<double> &values) const override;

      bool writes_files() const override { return rank == 0; }
      std::unique_ptr<TableWriter> merged(std::unique_ptr<TableWriter> writer,
                                          std::vector<ColumnOwner>     owners) override;
      /// What takes a row summed over the ranks, on rank 0.
      class RowConsumer
      {
      public:
        virtual ~RowConsumer() = default;
        virtual void take(double time, const std::vector<double> &row) = 0;
      };
      /// A row for `consumer` at `time`: values[i] where mine[i] (all when
      /// nullptr), zero elsewhere; summed over the ranks by flush().
      void add(RowConsumer &consumer, double time, const double *values, std::size_t n,
               const std::vector<char> *mine);
      /// What writes with every rank at flush() (the ranks' HDF5 file).
      class CollectiveWriter
      {
      public:
        virtual ~CollectiveWriter() = default;
        /// Collective: OutputError on every rank or on none.
        virtual void write_together() = 0;
      };
      /// A write of `writer` with the other ranks at the next flush().
      void add(CollectiveWriter &writer) { together.push_back(&writer); }

      /// The writes added since the last call, together, then the rows
      /// summed over the ranks and taken on rank 0 (OutputError there).
      /// Collective: after every observation, whether or not this rank's
      /// observers ran; nothing is written unless every rank added as much.
      void flush();

    private:
      /// A table's rows, each rank's own columns (the others zero).
      class MergedTable final : public TableWriter, public RowConsumer
      {
      public:
        MergedTable(RanksOfRun &ranks, std::unique_ptr<TableWriter> writer,
                    std::vector<char> mine)
          : ranks(ranks)
          , writer(std::move(writer))
          , mine(std::move(mine))
        {}
        void add_row(const double time, const std::vector<double> &values) override
        {
          AssertDimension(values.size(), mine.size());
          ranks.add(*this, time, values.data(), values.size(), &mine);
        }
        void take(const double time, const std::vector<double> &row) override
        {
          writer->add_row(time, row);
        }
        void commit() override
        {
          if (writer)
            writer->commit();
        }

      private:
        RanksOfRun                  &ranks;
        std::unique_ptr<TableWriter> writer; // rank 0's
        std::vector<char>            mine;
      };

      /// A row waiting for flush(): its consumer, time and place in `rows`.
      struct PendingRow
      {
        RowConsumer *consumer;
        double       time;
        std::size_t  start, size;
      };

      bool owns_column(const ColumnOwner &c) const
      {
        return c.kind == Owner::root ? rank == 0 : owns[int(c.kind)][c.index] != 0;
      }

      MPI_Comm          communicator;
      int               rank = 0;
      // owns[kind][i]: whether this rank owns entity i of that kind
      std::array<std::vector<char>, 5> owns;
      std::vector<PendingRow> pending;
      std::vector<CollectiveWriter *> together;
      std::vector<char>       available_equations;
      std::vector<double>     rows, row; // reused: nothing allocated per step
      mutable std::vector<double>       sent;
      mutable std::vector<unsigned int> entities;
    };

    RanksOfRun::RanksOfRun(const Model &model, const PartitionedHistory &history,
                           const NonlinearElements &elements, const MPI_Comm communicator)
      : communicator(communicator)
    {
      MPI_Comm_rank(communicator, &rank);
      const BuildingPartition          &parts = history.partition();
      const std::array<unsigned int, 2> mine  = parts.equations(rank);
      auto own_equation = [&](const int q) { return q >= int(mine[0]) && q < int(mine[1]); };
      std::vector<char> &buildings = owns[int(Owner::building)];
      for (unsigned int b = 0; b < model.buildings.size(); ++b)
        buildings.push_back(b >= parts.first_building[rank] && b < parts.first_building[rank + 1]);
      const FloorResponse floor_numbering(model);
      owns[int(Owner::floor)].assign(floor_numbering.n_floors(), 0);
      for (unsigned int b = 0; b < model.buildings.size(); ++b)
        for (unsigned int f = 0; f < model.buildings[b].floors.size(); ++f)
          owns[int(Owner::floor)][floor_numbering.index(b, f)] = buildings[b];
      for (unsigned int q = 0; q < model.n_equations(); ++q)
        owns[int(Owner::equation)].push_back(own_equation(q));
      available_equations = owns[int(Owner::equation)];
      for (const int q : history.ghost_equations())
        available_equations[q] = 1;
      for (const NonlinearElement &e : elements)
        {
          int first = -1;
          for (const int q : e.equations())
            if (q >= 0 && (first < 0 || q < first))
              first = q;
          owns[int(Owner::element)].push_back(own_equation(first));
        }
    }

    void
    RanksOfRun::owned(const Owner kind, std::vector<double> &values) const
    {
      AssertDimension(values.size(), kind == Owner::root ? values.size() : owns[int(kind)].size());
      std::vector<unsigned int> &each = entities;
      each.resize(values.size());
      std::iota(each.begin(), each.end(), 0u);
      owned(kind, each, values);
    }

    void
    RanksOfRun::owned(const Owner kind, const std::vector<unsigned int> &entity_of,
                      std::vector<double> &values) const
    {
      AssertDimension(values.size(), entity_of.size());
      const std::vector<char> &mine = owns[int(kind)];
      sent.resize(values.size());
      for (std::size_t i = 0; i < values.size(); ++i)
        sent[i] = (kind == Owner::root ? rank == 0 : mine[entity_of[i]] != 0) ? values[i] : 0.0;
      // x + 0 = x: the owner's value exactly
      MPI_Reduce(sent.data(), values.data(), values.size(), MPI_DOUBLE, MPI_SUM, 0, communicator);
      if (rank != 0)
        std::copy(sent.begin(), sent.end(), values.begin()); // unchanged where owned
    }

    void
    RanksOfRun::owned(const Owner kind, std::vector<unsigned int> &values) const
    {
      std::vector<double> exact(values.begin(), values.end()); // below 2^53
      owned(kind, exact);
      if (rank == 0)
        std::transform(exact.begin(), exact.end(), values.begin(),
                       [](const double x) { return static_cast<unsigned int>(x); });
    }

    void
    RanksOfRun::least(double &value) const
    {
      double mine = value;
      MPI_Reduce(&mine, &value, 1, MPI_DOUBLE, MPI_MIN, 0, communicator);
      if (rank != 0)
        value = mine;
    }

    void
    RanksOfRun::concatenated(std::vector<double> &values) const
    {
      const std::vector<std::vector<double>> all =
        dealii::Utilities::MPI::gather(communicator, values, 0);
      if (rank != 0)
        return;
      values.clear();
      for (const std::vector<double> &part : all)
        values.insert(values.end(), part.begin(), part.end());
    }

    std::unique_ptr<TableWriter>
    RanksOfRun::merged(std::unique_ptr<TableWriter> writer, std::vector<ColumnOwner> owners)
    {
      std::vector<char> mine;
      for (const ColumnOwner &c : owners)
        mine.push_back(owns_column(c));
      return std::make_unique<MergedTable>(*this, std::move(writer), std::move(mine));
    }

    void
    RanksOfRun::add(RowConsumer &consumer, const double time, const double *values,
                    const std::size_t n, const std::vector<char> *mine)
    {
      const std::size_t start = rows.size();
      for (std::size_t i = 0; i < n; ++i)
        rows.push_back(!mine || (*mine)[i] ? values[i] : 0.0);
      pending.push_back({&consumer, time, start, n});
    }

    void
    RanksOfRun::flush()
    {
      // a rank whose observers stopped (rank 0 could not write) adds fewer
      // rows: then none is written, and the run stops at the next step
      long counts[4] = {long(rows.size()), -long(rows.size()), long(together.size()),
                        -long(together.size())};
      MPI_Allreduce(MPI_IN_PLACE, counts, 4, MPI_LONG, MPI_MAX, communicator);
      const bool agreed = counts[0] == -counts[1] && counts[2] == -counts[3];
      if (agreed && !rows.empty())
        MPI_Reduce(rank == 0 ? MPI_IN_PLACE : rows.data(), rows.data(), rows.size(), MPI_DOUBLE,
                   MPI_SUM, 0, communicator);
      try
        {
          // the writes together first: rank 0's rows may fail on rank 0 alone
          for (CollectiveWriter *writer : together)
            if (agreed)
              writer->write_together();
          if (rank == 0 && agreed)
            for (const PendingRow &p : pending)
              {
                row.assign(rows.begin() + p.start, rows.begin() + p.start + p.size);
                p.consumer->take(p.time, row);
              }
        }
      catch (const std::exception &) // OutputError, or a NaN (NumericalError) on rank 0
        {
          pending.clear();
          together.clear();
          rows.clear();
          throw;
        }
      pending.clear();
      together.clear();
      rows.clear();
    }

    /// The field output of a run observed by rank, at every `every`-th step.
    /// VTU: each rank adds its own equations of u and the frame states of
    /// the elements it observes (the others zero) as one row of `ranks`; on
    /// rank 0 the sum is the whole model's frame, which `series` writes.
    /// HDF5 + XDMF (`together`): every rank's series writes its own rows of
    /// the frame into one file at the flush (NaN where it has no value).
    class RankFieldRecorder final : public PeriodicObserver,
                                    public RanksOfRun::RowConsumer,
                                    public RanksOfRun::CollectiveWriter
    {
    public:
      /// `series`: rank 0's (nullptr on the others), or every rank's
      /// (`together`, VtuSeries's constructor for ranks).
      RankFieldRecorder(RanksOfRun &ranks, std::unique_ptr<VtuSeries> series,
                        const unsigned int every, const bool together)
        : PeriodicObserver(every)
        , ranks(ranks)
        , series(std::move(series))
        , together(together)
      {}
      void
      write(const ResponseView &state) override
      {
        const Vector &u = state.displacement();
        states.evaluate(state.elements, u, &ranks.observed());
        if (together)
          {
            constexpr double none = std::numeric_limits<double>::quiet_NaN();
            time                  = state.time();
            this->u               = u;
            for (Eigen::Index q = 0; q < u.size(); ++q)
              if (!ranks.available()[q])
                this->u[q] = none;
            for (unsigned int h = 0; h < states.kinds.size(); ++h)
              if (!ranks.observed()[h])
                std::fill_n(states.values.begin() + ElementFrameStates::n_entries * h,
                            ElementFrameStates::n_entries, none);
            ranks.add(*this);
            return;
          }
        frame.resize(u.size() + states.values.size());
        for (Eigen::Index q = 0; q < u.size(); ++q)
          frame[q] = ranks.equations()[q] ? u[q] : 0.0;
        std::copy(states.values.begin(), states.values.end(), frame.begin() + u.size());
        ranks.add(*this, state.time(), frame.data(), frame.size(), nullptr);
      }
      void
      take(const double time, const std::vector<double> &row) override
      {
        const std::size_t n = row.size() - states.values.size();
        u.resize(n);
        std::copy(row.begin(), row.begin() + n, u.data());
        std::copy(row.begin() + n, row.end(), states.values.begin());
        series->write(time, u, states);
      }
      void write_together() override { series->write(time, u, states); }
      /// Rank 0's series at rank 0's end; collective when `together`, and
      /// then the other ranks call it too (finish_together).
      void
      finish(const ResponseView &, const RunStatus &) override
      {
        if (series)
          series->finish();
      }
      /// The other ranks' part of finish() (the ranks' file closed
      /// together); nothing for VTU.
      void
      finish_together(RunStatus &status)
      {
        if (!together)
          return;
        try
          {
            series->finish();
          }
        catch (const OutputError &) // rank 0 reports it
          {
            status.kind          = RunStatus::Kind::failed;
            status.output_failed = true;
          }
      }

    private:
      RanksOfRun                &ranks;
      std::unique_ptr<VtuSeries> series;
      const bool                 together;
      ElementFrameStates         states; // this rank's, then (rank 0) the sums
      std::vector<double>        frame;
      Vector                     u;
      double                     time = 0; // of the frame written together
    };
  } // namespace

  namespace
  {
    /// One rank's view of a partitioned run observed by rank: the whole
    /// model's nonlinear elements, of which this rank replays those it
    /// observes through its own and ghost values (the rest of the model
    /// stays at rest here), and the standard observers on them.
    struct RankRunView
    {
      RankRunView(const Analysis &analysis, const RunParameters &parameters,
                  const PartitionedHistory &history, unsigned long n_steps,
                  const RunOptions &options, MPI_Comm communicator)
        : elements(make_nonlinear_elements(analysis.model))
        , ranks(analysis.model, history, elements, communicator)
        , stepper(elements, analysis.model.n_equations(), ranks.observed())
        , view(observed_view(analysis, elements, stepper,
                             parameters.time_history.ground_motion.has_vertical(), ranks))
        , observers(analysis, parameters, history.excitation(), view, elements, n_steps,
                    history.linear_solver_name(), "refactorize", options, &ranks,
                    [&](const unsigned int every) {
                      const FieldFormat format   = parameters.output.field_format;
                      const bool        together = format == FieldFormat::xdmf;
                      const std::string &directory = options.output_directory;
                      std::unique_ptr<VtuSeries> series; // every rank's, or rank 0's
                      if (together)
                        series = std::make_unique<VtuSeries>(analysis.model, directory,
                                                             "solution", communicator);
                      else if (ranks.writes_files())
                        series =
                          std::make_unique<VtuSeries>(analysis.model, directory, "solution", format);
                      auto recorder = std::make_unique<RankFieldRecorder>(ranks, std::move(series),
                                                                          every, together);
                      field = recorder.get();
                      return recorder;
                    })
      {}

      static ResponseView
      observed_view(const Analysis &analysis, const NonlinearElements &elements,
                    const TimeStepper &stepper, const bool vertical, const RanksOfRun &ranks)
      {
        ResponseView view = view_of(analysis, elements, stepper, vertical);
        view.set_observed(&ranks.observed(), &ranks.buildings());
        return view;
      }

      /// `local` (this rank's vector: its equations, then its ghosts)
      /// into the model's numbering, in `whole`.
      static void
      place(const PartitionedHistory &history, const Vector &local, Vector &whole)
      {
        const auto             range  = history.owned_range();
        const unsigned int     n_own  = range[1] - range[0];
        const std::vector<int> &ghost = history.ghost_equations();
        whole.segment(range[0], n_own) = local.head(n_own);
        for (unsigned int k = 0; k < ghost.size() && n_own + k < local.size(); ++k)
          whole[ghost[k]] = local[n_own + k];
      }

      NonlinearElements  elements;
      RanksOfRun         ranks;
      ReplayedStepper    stepper;
      ResponseView       view;
      RankFieldRecorder *field = nullptr; // of the observers, when there is a field output
      StandardObservers  observers;
    };

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

    /// A run over the ranks of a communicator (run_partitioned_time_history):
    /// the ranks' lockstep history, each rank's view of its own part with
    /// the standard observers, merged on rank 0 (observation by rank).
    class PartitionedRun
    {
    public:
      /// Collective; an error on a rank's observers (a recorder's bad
      /// entry) is thrown on every rank.
      PartitionedRun(Analysis &analysis, const RunParameters &parameters,
                     const RunOptions &options, MPI_Comm communicator);

      /// From rest to the end time, or to a stop agreed by the ranks.
      RunStatus run();
      /// On rank 0 the observers finish and the run's scalars; on the
      /// others the status and the integrator's figures.
      RunResult result(RunStatus status);

    private:
      using Call = void (StepObserver::*)(const ResponseView &);
      /// Each rank's own values placed in its view, its elements replayed
      /// to them (or started, `first`), `call` of its observers at time
      /// `t`, then the rows merged on rank 0. Collective.
      void observe(Call call, double t, bool first);
      /// This rank's elements replayed to the state placed in its view (or
      /// started, `first`), then `call` of every observer; an output or
      /// numerical error is kept in stop_reason. Not collective.
      void replay_and_observe(Call call, double t, bool first);
      /// 0: go on; 1: interrupted; 2: a rank stopped (stop_reason); 3:
      /// rank 0 could not write (then every rank exits as an output
      /// failure: mpirun reports the first rank's status). Collective.
      int agreed_stop() const;

      const RunOptions             &options;
      const MPI_Comm                communicator;
      PartitionedHistory            history;
      const unsigned long           n_steps;
      const double                  dt;
      std::unique_ptr<RankRunView>  own; // this rank's view and observers
      unsigned long                 step = 0;
      // why this rank cannot go on (rank 0 could not write, or a replay
      // failed), told to the others at the start of the next step
      std::string stop_reason;
      bool        output_failed = false;
    };

    PartitionedRun::PartitionedRun(Analysis &analysis, const RunParameters &parameters,
                                   const RunOptions &options, const MPI_Comm communicator)
      : options(options)
      , communicator(communicator)
      , history(checked_for_partitioned_run(analysis, parameters.time_history, communicator),
                parameters.time_history, communicator)
      , n_steps(n_steps_of(parameters.time_history, history.excitation()))
      , dt(parameters.time_history.time_integration.newmark.time_step)
    {
      int rank = 0;
      MPI_Comm_rank(communicator, &rank);
      // a caller's observers would see only this rank's part
      AssertThrow(options.observers.empty(), dealii::ExcNotImplemented());
      std::exception_ptr error;
      try
        {
          own = std::make_unique<RankRunView>(analysis, parameters, history, n_steps, options,
                                              communicator);
        }
      catch (const std::exception &)
        {
          error = std::current_exception();
        }
      agree_on_error(error, communicator);
    }

    void
    PartitionedRun::observe(const Call call, const double t, const bool first)
    {
      // no gather: each rank places its own values and ghosts
      const NewmarkIntegrator      &newmark = history.integrator();
      const std::array<Vector *, 3> to      = own->stepper.state_to_fill();
      RankRunView::place(history, newmark.displacement(), *to[0]);
      RankRunView::place(history, newmark.velocity(), *to[1]);
      RankRunView::place(history, newmark.acceleration(), *to[2]);
      replay_and_observe(call, t, first);
      try
        {
          own->ranks.flush(); // on every rank, whether or not its observers ran
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
    PartitionedRun::replay_and_observe(const Call call, const double t, const bool first)
    {
      if (!stop_reason.empty())
        return;
      const NewmarkIntegrator &newmark = history.integrator();
      ReplayedStepper         &stepper = own->stepper;
      ResponseView            &view    = own->view;
      try
        {
          if (first)
            stepper.start();
          else
            stepper.replay(t, newmark.last_step_length(), history.statistics().steps);
          stepper.set_integrator_state(history.energy(), history.max_energy_error(),
                                       history.statistics(), newmark.steps());
          view.set_step(step, history.excitation().ground_acceleration_vector(t));
          for (StepObserver *observer : own->observers.all())
            (observer->*call)(view);
        }
      catch (const OutputError &e)
        {
          stop_reason   = e.what();
          output_failed = true;
        }
      catch (const NumericalError &e)
        {
          stop_reason = e.what();
        }
    }

    int
    PartitionedRun::agreed_stop() const
    {
      int stop = output_failed          ? 3 :
                 !stop_reason.empty()   ? 2 :
                                          (options.interruptible && interruption_requested());
      MPI_Allreduce(MPI_IN_PLACE, &stop, 1, MPI_INT, MPI_MAX, communicator);
      return stop;
    }

    RunStatus
    PartitionedRun::run()
    {
      RunStatus  status;
      const auto start = std::chrono::steady_clock::now();
      try
        {
          history.initialize();
          observe(&StepObserver::initialize, 0, true);
          history.set_substep_callback(
            [this]() { observe(&StepObserver::observe_substep, history.time(), false); });
          for (step = 1;; ++step)
            {
              if (const int stop = agreed_stop(); stop > 0)
                {
                  status.kind = stop == 1 ? RunStatus::Kind::interrupted : RunStatus::Kind::failed;
                  status.output_failed = stop == 3;
                  status.message = stop_reason.empty() ? "another rank stopped the run" : stop_reason;
                  break;
                }
              if (step > n_steps)
                break;
              history.advance();
              observe(&StepObserver::observe_step, step * dt, false);
            }
        }
      catch (const NumericalError &e) // on every rank
        {
          status.kind    = RunStatus::Kind::failed;
          status.message = e.what();
        }
      history.set_substep_callback(nullptr);
      status.wall_time =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      status.steps    = history.integrator().steps();
      status.end_time = history.time();
      return status;
    }

    RunResult
    PartitionedRun::result(RunStatus status)
    {
      // the ranks' observations merged on rank 0, where they finish
      own->observers.merge(own->ranks);
      own->stepper.merge(own->ranks);
      if (!own->ranks.writes_files() && own->field)
        own->field->finish_together(status); // with rank 0's finish_observers
      if (!own->ranks.writes_files())
        return {status, history.statistics(), history.energy(), history.max_energy_error(),
                history.n_local_elements(), 0, {}};
      own->view.set_stored_energies(&own->stepper.stored_energies());
      finish_observers(own->observers.all(), own->view, status);
      return own->observers.result(status, own->view);
    }
  } // namespace

  RunResult
  run_partitioned_time_history(Analysis &analysis, const RunParameters &parameters,
                               const RunOptions &options, const MPI_Comm communicator)
  {
    PartitionedRun run(analysis, parameters, options, communicator);
    return run.result(run.run());
  }
} // namespace poundfe
