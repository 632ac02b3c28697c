// Observation by rank of a run partitioned by building (doc/theory.md
// §3.5d): what each rank owns of the whole model, the collective merges of
// base/rank_merge.h and the recorders' rows (output/recorders.h: RowSink)
// on rank 0, and the field output written from every rank's part. Used by
// the partitioned stepper (dynamics/partitioned_stepper.h).
#ifndef poundfe_dynamics_ranks_of_run_h
#define poundfe_dynamics_ranks_of_run_h

#include <poundfe/base/rank_merge.h>
#include <poundfe/dynamics/partitioned_history.h>
#include <poundfe/output/observer.h>
#include <poundfe/output/recorders.h>
#include <poundfe/output/table_writer.h>
#include <poundfe/output/vtu_series.h>

#include <deal.II/base/exceptions.h>

#include <mpi.h>

#include <array>
#include <memory>
#include <vector>

namespace poundfe
{
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

  /// The field output of a run observed by rank, at every `every`-th step
  /// and, given the gaps' total |force| of each step (`gap_force`, the
  /// same on every rank), at each impact's peak by the whole-model
  /// recorder's rule (output/vtu_series.h: ImpactPeakRule), so both write
  /// the same frames.
  /// VTU: each rank adds its own equations of u and the frame states of
  /// the elements it observes (the others zero) as one row of `ranks`; on
  /// rank 0 the sum is the whole model's frame, which `series` writes.
  /// HDF5 + XDMF (`together`): every rank's series writes its own rows of
  /// the frame into one file at the flush (NaN where it has no value).
  class RankFieldRecorder final : public StepObserver,
                                  public RanksOfRun::RowConsumer,
                                  public RanksOfRun::CollectiveWriter
  {
  public:
    /// `series`: rank 0's (nullptr on the others), or every rank's
    /// (`together`, VtuSeries's constructor for ranks). `gap_force`:
    /// nullptr for the regular frames alone.
    RankFieldRecorder(RanksOfRun &ranks, std::unique_ptr<VtuSeries> series, unsigned int every,
                      bool together, const double *gap_force = nullptr);
    void initialize(const ResponseView &state) override;
    void observe_step(const ResponseView &state) override;
    void take(double time, const std::vector<double> &row) override;
    void write_together() override;
    /// Rank 0's series at rank 0's end; collective when `together`, and
    /// then the other ranks call it too (finish_together).
    void finish(const ResponseView &, const RunStatus &) override;
    /// The other ranks' part of finish() (the ranks' file closed
    /// together); nothing for VTU.
    void finish_together(RunStatus &status);

  private:
    /// This rank's part of a frame: its u (NaN where it has no value when
    /// `together`, else zero off its own equations) and element states.
    struct Frame
    {
      double              time = 0;
      Vector              u;
      std::vector<double> states;
    };
    void capture(const ResponseView &state, Frame &frame);
    /// `frame` to the ranks' next flush.
    void send(const Frame &frame);

    RanksOfRun                &ranks;
    std::unique_ptr<VtuSeries> series;
    const bool                 together;
    const unsigned int         every;
    unsigned long              next = 0;
    const double              *gap_force;
    ImpactPeakRule             peaks;
    Frame                      current, held;
    std::vector<Frame>         queued; // the frames written together at the flush, in order
    ElementFrameStates         states; // this rank's, then (rank 0) the sums
    std::vector<double>        row;
    Vector                     u;
  };
} // namespace poundfe

#endif
