// A model split over MPI ranks by building (doc/theory.md §3.5d). Buildings
// that M, K or C join (a shared foundation, a linear link) stay together;
// the rest meet only through nonlinear elements (gaps, dampers). Each rank
// owns a run of consecutive buildings, the runs balanced by equations, so
// its equations are one contiguous range and M, K, C and K_eff are block
// diagonal over the ranks: each rank factorises its own block, and only the
// elements between buildings on two ranks couple them, through the ghost
// values of their far ends (assembly/rank_ownership.h).
// A rank numbers its equations locally: its own first (global g is local
// g - first), then its ghosts in increasing global order; its vectors and
// matrices have n_owned + n_ghosts rows, the ghost rows of M, K and C empty.
#ifndef poundfe_assembly_partition_h
#define poundfe_assembly_partition_h

#include <poundfe/assembly/linear_system.h>
#include <poundfe/elements/nonlinear_element.h>
#include <poundfe/assembly/rank_ownership.h>

#include <mpi.h>

#include <array>
#include <string>
#include <vector>

namespace poundfe
{
  struct BuildingPartition
  {
    /// Rank r owns buildings [first_building[r], first_building[r + 1]) and
    /// equations [first_equation[r], first_equation[r + 1]).
    std::vector<unsigned int> first_building, first_equation;
    /// Runs of consecutive buildings that cannot be split (the most ranks).
    unsigned int n_blocks = 0;

    unsigned int                n_parts() const { return first_building.size() - 1; }
    std::array<unsigned int, 2> equations(const unsigned int r) const
    {
      return {{first_equation[r], first_equation[r + 1]}};
    }
  };

  /// `n_parts` runs of buildings balanced by equations, keeping together
  /// the buildings of each pair in `joined` (a < b). Throws InputError
  /// (naming `input_file` and the ranks) when there are more parts than
  /// runs of buildings that `joined` leaves separable.
  BuildingPartition partition_by_building(const Model                                    &model,
                                          const std::vector<std::array<unsigned int, 2>> &joined,
                                          unsigned int n_parts, const std::string &input_file);

  /// The same, with the pairs that the model's M, K and C join
  /// (coupled_buildings: from its elements, nothing assembled). What a
  /// run over ranks uses: every rank gets it before it assembles its part.
  BuildingPartition partition_by_building(const Model &model, unsigned int n_parts,
                                          const std::string &input_file);

  /// The same, with the pairs that the entries of an assembled `system`
  /// join (a check of the above, and a coupling made up in a test).
  BuildingPartition partition_by_building(const Model &model, const LinearSystem &system,
                                          unsigned int n_parts, const std::string &input_file);

  /// The modal damping U diag(w) Uᵀ of the equations [first, last): the
  /// columns of U (one mode of one building each, zero outside its rows)
  /// that have an entry there, cut to those rows and padded with zeros to
  /// `n_local` rows (the ghosts'). U is block diagonal by building, so the
  /// parts of the ranks add up to the model's.
  LowRankDamping owned_modal_damping(const LowRankDamping &damping,
                                     std::array<unsigned int, 2> range, unsigned int n_local);

  /// The part of `system` on the equations [first, last), numbered from 0,
  /// followed by `n_ghosts` empty rows and columns (and zeros in the
  /// influence vectors): M, K, C, the modal damping (owned_modal_damping)
  /// and the foundations' and P-Delta parts.
  LinearSystem owned_part(const LinearSystem &system, std::array<unsigned int, 2> range,
                          unsigned int n_ghosts);

  /// The RankOwnership of one rank of `partition` over `communicator`, whose
  /// ghosts are the equations of `elements` (this rank's, numbered as the
  /// model) that other ranks own; `elements` are renumbered locally.
  /// Collective.
  class RankPartition final : public RankOwnership
  {
  public:
    RankPartition(const BuildingPartition &partition, MPI_Comm communicator,
                  NonlinearElements &elements);

    /// [0, n_owned) in the local numbering.
    std::array<unsigned int, 2> owned_range() const override { return {{0, n_owned}}; }
    /// This rank's equations in the model's numbering.
    std::array<unsigned int, 2> global_range() const { return owned; }
    /// Length of this rank's vectors: its equations and ghosts.
    unsigned int n_local() const { return n_owned + ghosts.size(); }
    unsigned int                n_ranks() const override { return size; }
    using RankOwnership::sum;
    void sum(double *x, unsigned int n) const override;
    bool any(bool x) const override;
    void all_gather(const double *x, unsigned int n, double *all) const override;
    void update_ghosts(Eigen::VectorXd &x) const override;
    void zero_ghosts(Eigen::VectorXd &x) const override;

    unsigned int n_ghosts() const { return ghosts.size(); }
    /// The ghosts in the model's numbering (local n_owned + k is ghost k).
    const std::vector<int> &ghost_equations() const { return ghosts; }
    /// Doubles this rank receives per ghost update (= n_ghosts()).
    unsigned int n_received() const { return ghosts.size(); }

  private:
    MPI_Comm                    communicator;
    unsigned int                size = 1;
    std::array<unsigned int, 2> owned; // in the model's numbering
    unsigned int                n_owned = 0;
    // ghosts (model numbering), sorted: grouped by owner; receive_count[r]
    // of them from rank r; ghost k is local equation n_owned + k
    std::vector<int> ghosts, receive_count, receive_offset;
    // the equations (own, local) each rank asks for, rank after rank
    std::vector<int> send_equations, send_count, send_offset;
    mutable std::vector<double> send_buffer, receive_buffer, sum_buffer;
  };
} // namespace poundfe

#endif
