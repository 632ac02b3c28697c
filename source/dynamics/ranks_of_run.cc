// Observation by rank of a run partitioned by building
// (dynamics/ranks_of_run.h; doc/theory.md §3.5d).
#include <poundfe/dynamics/ranks_of_run.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/output/floor_response.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <limits>
#include <numeric>

namespace poundfe
{
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

  RankFieldRecorder::RankFieldRecorder(RanksOfRun &ranks, std::unique_ptr<VtuSeries> series,
                                       const unsigned int every, const bool together,
                                       const double *gap_force)
    : ranks(ranks)
    , series(std::move(series))
    , together(together)
    , every(every)
    , gap_force(gap_force)
  {}

  void
  RankFieldRecorder::initialize(const ResponseView &state)
  {
    next  = 0;
    peaks = ImpactPeakRule();
    observe_step(state);
  }

  void
  RankFieldRecorder::observe_step(const ResponseView &state)
  {
    const double force = gap_force ? *gap_force : 0.0;
    if (peaks.held_was_peak(force))
      send(held);
    const bool regular = state.step() == next;
    if (regular)
      {
        next += every;
        capture(state, current);
        send(current);
      }
    if (peaks.hold(force, regular))
      capture(state, held);
  }

  void
  RankFieldRecorder::capture(const ResponseView &state, Frame &frame)
  {
    frame.time = state.time();
    frame.u    = state.displacement();
    states.evaluate(state.elements, frame.u, &ranks.observed());
    constexpr double none  = std::numeric_limits<double>::quiet_NaN();
    const double     empty = together ? none : 0.0;
    const std::vector<char> &mine = together ? ranks.available() : ranks.equations();
    for (Eigen::Index q = 0; q < frame.u.size(); ++q)
      if (!mine[q])
        frame.u[q] = empty;
    if (together)
      for (unsigned int h = 0; h < states.kinds.size(); ++h)
        if (!ranks.observed()[h])
          std::fill_n(states.values.begin() + ElementFrameStates::n_entries * h,
                      ElementFrameStates::n_entries, none);
    frame.states = states.values;
  }

  void
  RankFieldRecorder::send(const Frame &frame)
  {
    if (together)
      {
        queued.push_back(frame);
        ranks.add(*this);
        return;
      }
    row.assign(frame.u.data(), frame.u.data() + frame.u.size());
    row.insert(row.end(), frame.states.begin(), frame.states.end());
    ranks.add(*this, frame.time, row.data(), row.size(), nullptr);
  }

  void
  RankFieldRecorder::take(const double time, const std::vector<double> &row)
  {
    const std::size_t n = row.size() - states.values.size();
    u.resize(n);
    std::copy(row.begin(), row.begin() + n, u.data());
    std::copy(row.begin() + n, row.end(), states.values.begin());
    series->write(time, u, states);
  }

  void
  RankFieldRecorder::write_together()
  {
    Assert(!queued.empty(), dealii::ExcInternalError());
    const Frame frame = std::move(queued.front());
    queued.erase(queued.begin());
    states.values = frame.states;
    series->write(frame.time, frame.u, states);
  }

  void
  RankFieldRecorder::finish(const ResponseView &, const RunStatus &)
  {
    if (series)
      series->finish();
  }

  void
  RankFieldRecorder::finish_together(RunStatus &status)
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
} // namespace poundfe
