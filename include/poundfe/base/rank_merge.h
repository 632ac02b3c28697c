// What each rank of a run partitioned by building observed of its own part,
// merged on rank 0 (doc/theory.md §3.5d "Observation by rank"). Every rank
// runs the same observers on a view of the whole model in which only its
// own buildings and elements move (the others stay at rest); a value of a
// floor, a building, an element or an equation is kept from the rank that
// owns that entity and the others' are dropped, so the merged value is
// the owner's exactly (a sum of one number and zeros). The MPI side is in
// report/run_outputs.cc: this interface keeps it out of the observers.
#ifndef poundfe_base_rank_merge_h
#define poundfe_base_rank_merge_h

#include <vector>

namespace poundfe
{
  /// Who owns a value in a run partitioned by building.
  enum class Owner
  {
    root,     // the same on every rank (time, energy, ground motion): rank 0's
    floor,    // a FloorResponse index (a floor, or the storey below it)
    building, // a building
    element,  // a nonlinear element of the whole model
    equation  // an equation of the whole model
  };

  /// An entity: the owner of one column of a recorded table.
  struct ColumnOwner
  {
    Owner        kind  = Owner::root;
    unsigned int index = 0;
  };

  /// Collective merges, called in the same order on every rank; the
  /// merged values are on rank 0 (the other ranks' are left as they were).
  class RankMerge
  {
  public:
    virtual ~RankMerge() = default;
    /// values[i] (one per entity of `kind`) from the rank that owns entity i.
    virtual void owned(Owner kind, std::vector<double> &values) const = 0;
    virtual void owned(Owner kind, std::vector<unsigned int> &values) const = 0;
    /// values[i] from the rank that owns entity entity_of[i] of `kind`
    /// (several values per entity: a building's plan peaks).
    virtual void owned(Owner kind, const std::vector<unsigned int> &entity_of,
                       std::vector<double> &values) const = 0;
    /// The least of every rank's `value`.
    virtual void least(double &value) const = 0;
    /// Every rank's `values`, one after the other in the order of the ranks.
    virtual void concatenated(std::vector<double> &values) const = 0;
  };
} // namespace poundfe

#endif
