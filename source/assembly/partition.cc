// Partition by building (assembly/partition.h; doc/theory.md §3.5d):
// union-find of the buildings over the pairs that M, K and C join (from the
// model's elements, coupled_buildings, or from assembled matrices),
// each group widened to the interval of buildings it spans and overlapping
// intervals merged (a rank's equations must stay contiguous), then the
// blocks cut into runs whose equation counts are nearest to N/P each.
#include <poundfe/assembly/partition.h>
#include <poundfe/base/exceptions.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>

namespace poundfe
{
  namespace
  {
    unsigned int
    building_root(std::vector<unsigned int> &parent, unsigned int b)
    {
      while (parent[b] != b)
        b = parent[b] = parent[parent[b]];
      return b;
    }

    /// The first equation of each building and, last, the number of equations.
    std::vector<unsigned int>
    first_equations(const Model &model)
    {
      std::vector<unsigned int> first;
      for (unsigned int b = 0; b < model.buildings.size(); ++b)
        first.push_back(model.equation_range(b)[0]);
      first.push_back(model.buildings.empty() ? 0 : model.equation_range(model.buildings.size() - 1)[1]);
      return first;
    }

    /// The pairs of buildings (a < b) that an entry of M, K or C joins.
    std::vector<std::array<unsigned int, 2>>
    joined_by_matrices(const Model &model, const LinearSystem &system)
    {
      AssertThrow(system.n_equations() == model.n_equations(),
                  dealii::ExcMessage("the whole model's matrices"));
      const std::vector<unsigned int>       building_of = building_of_equations(model);
      std::set<std::array<unsigned int, 2>> joined;
      for (const SparseMatrix *matrix : {&system.mass, &system.stiffness, &system.damping})
        for (Eigen::Index column = 0; column < matrix->outerSize(); ++column)
          for (SparseMatrix::InnerIterator it(*matrix, column); it; ++it)
            {
              const unsigned int a = building_of[it.row()], b = building_of[it.col()];
              if (it.value() != 0 && a != b)
                joined.insert(std::array<unsigned int, 2>{{std::min(a, b), std::max(a, b)}});
            }
      return {joined.begin(), joined.end()};
    }

    /// [first, last) of each block of buildings that the pairs `joined` join.
    std::vector<std::array<unsigned int, 2>>
    inseparable_building_blocks(const unsigned int                              n_buildings,
                                const std::vector<std::array<unsigned int, 2>> &joined)
    {
      std::vector<unsigned int> parent(n_buildings);
      std::iota(parent.begin(), parent.end(), 0u);
      for (const auto &[a_building, b_building] : joined)
        {
          const unsigned int a = building_root(parent, a_building);
          const unsigned int b = building_root(parent, b_building);
          if (a != b)
            parent[std::max(a, b)] = std::min(a, b);
        }
      // each group's last building; a block ends where no group spans past it
      std::vector<unsigned int> last_of_group(n_buildings, 0);
      for (unsigned int b = 0; b < n_buildings; ++b)
        {
          unsigned int &last = last_of_group[building_root(parent, b)];
          last               = std::max(last, b);
        }
      std::vector<std::array<unsigned int, 2>> blocks;
      unsigned int                             start = 0, reach = 0;
      for (unsigned int b = 0; b < n_buildings; ++b)
        {
          reach = std::max(reach, last_of_group[building_root(parent, b)]);
          if (reach == b)
            {
              blocks.push_back({{start, b + 1}});
              start = b + 1;
            }
        }
      return blocks;
    }
  } // namespace

  BuildingPartition
  partition_by_building(const Model &model, const LinearSystem &system,
                        const unsigned int n_parts, const std::string &input_file)
  {
    return partition_by_building(model, joined_by_matrices(model, system), n_parts, input_file);
  }

  BuildingPartition
  partition_by_building(const Model &model, const unsigned int n_parts,
                        const std::string &input_file)
  {
    return partition_by_building(model, coupled_buildings(model), n_parts, input_file);
  }

  BuildingPartition
  partition_by_building(const Model &model, const std::vector<std::array<unsigned int, 2>> &joined,
                        const unsigned int n_parts, const std::string &input_file)
  {
    Assert(n_parts >= 1, dealii::ExcMessage("at least one part"));
    const std::vector<unsigned int> first = first_equations(model);
    AssertThrow(first.size() == model.buildings.size() + 1 && first.back() == model.n_equations(),
                dealii::ExcMessage("the buildings' equations must cover the model"));
    const std::vector<std::array<unsigned int, 2>> blocks =
      inseparable_building_blocks(model.buildings.size(), joined);
    if (n_parts > blocks.size())
      throw InputError(input_file, 0, "the number of MPI ranks",
                       std::to_string(n_parts) + " ranks, but the model splits by building into " +
                         std::to_string(blocks.size()) +
                         (blocks.size() == 1 ? " part" : " parts") +
                         " only (buildings joined by M, K or C stay on one rank): run on at most " +
                         std::to_string(blocks.size()) + (blocks.size() == 1 ? " rank" : " ranks"));

    BuildingPartition partition;
    partition.n_blocks = blocks.size();
    partition.first_building.assign(1, 0);
    const double total = model.n_equations();
    unsigned int next  = 0; // the first block not yet given to a part
    for (unsigned int part = 1; part < n_parts; ++part)
      {
        // the cut after block `end - 1` nearest to part N / P, leaving a
        // block to each part still to come
        const double target = total * part / n_parts;
        unsigned int best   = next + 1;
        for (unsigned int end = next + 1; end + (n_parts - part) <= blocks.size(); ++end)
          if (std::abs(double(first[blocks[end - 1][1]]) - target) <
              std::abs(double(first[blocks[best - 1][1]]) - target))
            best = end;
        partition.first_building.push_back(blocks[best - 1][1]);
        next = best;
      }
    partition.first_building.push_back(model.buildings.size());
    for (const unsigned int b : partition.first_building)
      partition.first_equation.push_back(first[b]);
    return partition;
  }

  LowRankDamping
  owned_modal_damping(const LowRankDamping &damping, const std::array<unsigned int, 2> range,
                      const unsigned int n_local)
  {
    // each column is one mode of one building, zero outside its rows (U
    // is block diagonal by building): the part keeps the columns of its
    // own buildings, cut to its rows
    LowRankDamping part;
    if (damping.empty())
      return part;
    const unsigned int        n_owned = range[1] - range[0];
    std::vector<Eigen::Index> columns;
    for (Eigen::Index c = 0; c < damping.factor.cols(); ++c)
      if (damping.factor.col(c).segment(range[0], n_owned).lpNorm<Eigen::Infinity>() > 0)
        {
          const auto column = damping.factor.col(c);
          AssertThrow((column.head(range[0]).array() == 0).all() &&
                        (column.tail(column.size() - range[1]).array() == 0).all(),
                      dealii::ExcMessage("a modal damping column reaches beyond its rank's "
                                         "equations"));
          columns.push_back(c);
        }
    part.factor  = Eigen::MatrixXd::Zero(n_local, columns.size());
    part.weights = Vector(columns.size());
    for (unsigned int j = 0; j < columns.size(); ++j)
      {
        part.factor.col(j).head(n_owned) = damping.factor.col(columns[j]).segment(range[0], n_owned);
        part.weights[j]                  = damping.weights[columns[j]];
      }
    return part;
  }

  LinearSystem
  owned_part(const LinearSystem &system, const std::array<unsigned int, 2> range,
             const unsigned int n_ghosts)
  {
    const unsigned int n_owned = range[1] - range[0], n_local = n_owned + n_ghosts;
    const auto         cut     = [&](const SparseMatrix &matrix) {
      if (matrix.rows() == 0) // absent (no P-Delta, no foundations)
        return SparseMatrix();
      SparseMatrix part = block(matrix, range);
      part.conservativeResize(n_local, n_local);
      part.makeCompressed();
      return part;
    };
    const auto cut_vector = [&](const Vector &x) {
      if (x.size() == 0)
        return Vector();
      Vector part = Vector::Zero(n_local);
      part.head(n_owned) = x.segment(range[0], n_owned);
      return part;
    };
    LinearSystem part;
    part.mass                = cut(system.mass);
    part.stiffness           = cut(system.stiffness);
    part.geometric_stiffness = cut(system.geometric_stiffness);
    part.damping             = cut(system.damping);
    part.structure_mass      = cut(system.structure_mass);
    part.structure_stiffness = cut(system.structure_stiffness);
    part.influence           = cut_vector(system.influence);
    part.influence_y         = cut_vector(system.influence_y);
    part.influence_rz        = cut_vector(system.influence_rz);
    part.influence_z         = cut_vector(system.influence_z);
    part.rayleigh            = system.rayleigh;
    part.modal_damping       = owned_modal_damping(system.modal_damping, range, n_local);
    return part;
  }

  RankPartition::RankPartition(const BuildingPartition &partition, const MPI_Comm communicator,
                               NonlinearElements &elements)
    : communicator(communicator)
  {
    int rank = 0, n = 1;
    MPI_Comm_rank(communicator, &rank);
    MPI_Comm_size(communicator, &n);
    size = n;
    AssertThrow(partition.n_parts() == size,
                dealii::ExcMessage("one part per rank of the communicator"));
    owned   = partition.equations(rank);
    n_owned = owned[1] - owned[0];
    const auto is_own = [this](const int i) { return i >= int(owned[0]) && i < int(owned[1]); };
    for (const NonlinearElement &e : elements)
      for (const int i : e.equations())
        if (i >= 0 && !is_own(i))
          ghosts.push_back(i);
    std::sort(ghosts.begin(), ghosts.end());
    ghosts.erase(std::unique(ghosts.begin(), ghosts.end()), ghosts.end());
    for (NonlinearElement &e : elements)
      e.renumber([&](const int i) {
        if (is_own(i))
          return i - int(owned[0]);
        return int(n_owned + (std::lower_bound(ghosts.begin(), ghosts.end(), i) - ghosts.begin()));
      });

    // ghosts by owner (sorted, and the owners' ranges are increasing)
    receive_count.assign(size, 0);
    for (const int i : ghosts)
      {
        const auto owner = std::upper_bound(partition.first_equation.begin(),
                                            partition.first_equation.end(), (unsigned int)i) -
                           partition.first_equation.begin() - 1;
        ++receive_count[owner];
      }
    receive_offset.assign(size, 0);
    std::partial_sum(receive_count.begin(), receive_count.end() - 1, receive_offset.begin() + 1);
    send_count.assign(size, 0);
    MPI_Alltoall(receive_count.data(), 1, MPI_INT, send_count.data(), 1, MPI_INT, communicator);
    send_offset.assign(size, 0);
    std::partial_sum(send_count.begin(), send_count.end() - 1, send_offset.begin() + 1);
    send_equations.resize(send_offset.back() + send_count.back());
    MPI_Alltoallv(ghosts.data(), receive_count.data(), receive_offset.data(), MPI_INT,
                  send_equations.data(), send_count.data(), send_offset.data(), MPI_INT,
                  communicator);
    for (int &i : send_equations) // asked for in the model's numbering
      i -= owned[0];
    send_buffer.resize(send_equations.size());
    receive_buffer.resize(ghosts.size());
  }

  void
  RankPartition::sum(double *x, const unsigned int n) const
  {
    // every rank adds the same numbers in the same order (rank 0 first), so
    // all get the same bits: the decisions taken from the sums (converged,
    // re-form the tangent) then agree, which MPI_Allreduce does not promise
    sum_buffer.resize(std::size_t(n) * size);
    MPI_Allgather(x, n, MPI_DOUBLE, sum_buffer.data(), n, MPI_DOUBLE, communicator);
    for (unsigned int i = 0; i < n; ++i)
      {
        double total = sum_buffer[i];
        for (unsigned int r = 1; r < size; ++r)
          total += sum_buffer[std::size_t(r) * n + i];
        x[i] = total;
      }
  }

  bool
  RankPartition::any(const bool x) const
  {
    int value = x;
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_INT, MPI_LOR, communicator);
    return value != 0;
  }

  void
  RankPartition::all_gather(const double *x, const unsigned int n, double *all) const
  {
    MPI_Allgather(x, n, MPI_DOUBLE, all, n, MPI_DOUBLE, communicator);
  }

  void
  RankPartition::update_ghosts(Eigen::VectorXd &x) const
  {
    for (unsigned int k = 0; k < send_equations.size(); ++k)
      send_buffer[k] = x[send_equations[k]];
    MPI_Alltoallv(send_buffer.data(), send_count.data(), send_offset.data(), MPI_DOUBLE,
                  receive_buffer.data(), receive_count.data(), receive_offset.data(), MPI_DOUBLE,
                  communicator);
    for (unsigned int k = 0; k < ghosts.size(); ++k)
      x[n_owned + k] = receive_buffer[k];
  }

  void
  RankPartition::zero_ghosts(Eigen::VectorXd &x) const
  {
    x.segment(n_owned, ghosts.size()).setZero();
  }
} // namespace poundfe
