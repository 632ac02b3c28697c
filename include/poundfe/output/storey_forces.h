// Storey shears and member end forces from the element forces.
//
// The shear of storey i of a building is the horizontal force carried
// across a horizontal cut at mid-height of the storey, positive when it
// resists a positive drift:
//   frames:  V_i = -sum over the elements crossing the cut of f_x at their
//            lower node, with f = K_e u_e the element's end forces in
//            global axes (a distributed self-weight is vertical: along a
//            vertical column it changes N alone, so the shear is the same
//            anywhere along it);
//   shear buildings: V_i = F_i + c_i d'_i, the storey spring (k_i d_i, or
//            the Bouc-Wen force) plus the storey dashpot.
// The base shear is V_1. Rayleigh damping forces are not element forces:
// horizontal equilibrium of the building reads
//   sum_x (M a_abs) + sum_x (C u') + V_1 = 0
// (sums over the building's ux equations; exact for a shear building with
// storey dashpots only, and for any building once the Rayleigh part is
// added; doc/theory.md §10).
// Dimension 3 (doc/theory.md §1.15, §10): the storey's forces in plan, the
// shears V_x, V_y and the torque T about the mass centre at rest C of the
// floor on top of the storey, from
//   3D frames: f = K_e T_e q, the global end forces of each column crossing
//            the cut at its lower end (x, y): V = -Σ f_x,y,
//            T = -Σ ((x - C_x) f_y - (y - C_y) f_x + m_z);
//   shear buildings: each resisting plane j of the storey, force F_j along
//            d_j at p_j: V = Σ F_j d_j, T = Σ (p_j - C) × F_j d_j;
// V_x is the storey shear above (as in 2D, along x).
// Member end forces are the local (N, V, M) at both ends of a whole member
// (its first and last element when it is split), Przemieniecki (1968) ch. 5;
// a 3D member's the local (N, Vy, Vz, T, My, Mz) at both ends; an elastic
// member's K_e u plus the fixed-end forces of its distributed self-weight. A
// fibre member's are its element's resisting forces (not K_e u, wrong once it
// cracks; its self-weight included).
#ifndef poundfe_output_storey_forces_h
#define poundfe_output_storey_forces_h

#include <poundfe/assembly/linear_system.h>
#include <poundfe/elements/frame_element.h>
#include <poundfe/elements/nonlinear_element.h>
#include <poundfe/model/model.h>
#include <poundfe/output/observer.h>

#include <optional>

#include <string>
#include <vector>

namespace poundfe
{
  class StoreyForces
  {
  public:
    StoreyForces(const Model &model, const NonlinearElements &elements);

    /// Storey shears of every building, in FloorResponse order (building by
    /// building, storeys bottom up), N.
    void storey_shears(const Vector &u, const Vector &v, std::vector<double> &shear) const;
    /// The shear of one storey (`index` in that layout), N.
    double storey_shear(unsigned int index, const Vector &u, const Vector &v) const;
    /// Dimension 3: (V_x, V_y, T) of one storey (`index` as above), N and N m.
    std::array<double, 3> plan_forces(unsigned int index, const Vector &u) const;
    /// Index of storey s (0-based) of building b in that layout.
    unsigned int index(unsigned int b, unsigned int s) const { return first[b] + s; }

    /// The whole members with this label (A3_C1.2, a 3D frame's A_C1.1.2); empty if none.
    bool has_member(const std::string &label) const;
    /// Local end forces (N1, V1, M1, N2, V2, M2) of the labelled member.
    Vector6 member_end_forces(const std::string &label, const Vector &u) const;
    /// Local end forces (N, Vy, Vz, T, My, Mz at end 1, then at end 2) of
    /// the labelled 3D member.
    Eigen::Matrix<double, 12, 1> member_end_forces_3d(const std::string &label,
                                                      const Vector &u) const;

  private:
    struct CutElement
    {
      std::array<int, 6> equations; // global DOFs of the element; -1: fixed
      Matrix6            stiffness; // global K_e
      unsigned int       lower;     // 0 or 1: the node below the cut
      int                member_element = -1; // a fibre member's element (its forces)
    };
    /// A 3D member crossing a cut: the global forces (fx, fy, fz, mx, my,
    /// mz) at its lower end are `forces` times its model DOFs' values, or
    /// a fibre member's element's end forces there.
    struct CutMember3D
    {
      std::vector<int>                        equations; // of its model DOFs; -1: fixed
      Eigen::Matrix<double, 6, Eigen::Dynamic> forces;
      Point2                                  at; // the lower end in plan
      unsigned int                            lower          = 0;
      int                                     member_element = -1;
    };
    struct Storey
    {
      std::vector<CutElement> elements;
      std::vector<CutMember3D> members_3d;
      // (plane link, its Bouc-Wen element or -1, the element's force component)
      std::vector<std::array<int, 3>> planes;
      Point2                  centre;          // Dimension 3: of the floor on top, at rest
      int                     link = -1;      // shear building: the StoreyLink
      int                     hysteretic = -1; // its Bouc-Wen element, if any
    };
    Vector6 end_displacements(const std::array<int, 6> &equations, const Vector &u) const;
    void    add_members_3d();
    void    add_planes();

    const Model               &model;
    const NonlinearElements    &nonlinear;
    /// The nonlinear element of each fibre member (model.members order;
    /// -1: an elastic member, forces K_e u).
    std::vector<int> member_elements;
    /// The global end forces of fibre member element `e`, as it is now.
    Vector6 fibre_member_forces(int e) const;
    /// The same of a 3D fibre member (its 12 global end forces).
    Eigen::Matrix<double, 12, 1> fibre_member_forces_3d(int e) const;
    /// How many 3D fibre members' elements follow the plane ones.
    int member_elements_3d = 0;
    /// The nonlinear element of each 3D member (model.members_3d order;
    /// -1: an elastic member).
    std::vector<int> member_3d_elements;
    std::vector<unsigned int> first;
    std::vector<Storey>       storeys;
  };

  /// The 12 global end displacements of a 3D member, u_e = T q (its map
  /// over the model DOFs; fixed DOFs give 0).
  Eigen::Matrix<double, 12, 1> member_3d_end_displacements(const Model &model, const Member3D &member,
                                                           const Vector &u);

  /// The largest |base shear| V_1 of every building over a run and when it
  /// occurred, at every step and sub-step (summary.json, whatever the
  /// recorders): only the first storey's cut is evaluated. Dimension 3: V_1
  /// is V_x, and the peaks of |V_y| and of the resultant sqrt(V_x^2 + V_y^2)
  /// are kept beside it (the resultant's peak is not a combination of the
  /// two peaks: they need not coincide).
  class BaseShearPeaks : public StepObserver
  {
  public:
    void initialize(const ResponseView &state) override;
    void observe_step(const ResponseView &state) override;
    void observe_substep(const ResponseView &state) override { observe_step(state); }
    /// Observation by rank: each building's peak from the rank that owns
    /// it, on rank 0. Collective.
    void merge(const RankMerge &ranks) override
    {
      for (Peaks *p : {&along_x, &along_y, &resultant})
        if (!p->value.empty() || p == &along_x) // along y and the resultant: 3D only
          {
            ranks.owned(Owner::building, p->value);
            ranks.owned(Owner::building, p->time);
          }
    }
    /// Per building, N and s (3D: along x).
    const std::vector<double> &peak() const { return along_x.value; }
    const std::vector<double> &time_of_peak() const { return along_x.time; }
    /// Dimension 3: per building, the peak |V_y| and the peak resultant, N,
    /// and when each occurred, s; empty in 2D.
    const std::vector<double> &peak_y() const { return along_y.value; }
    const std::vector<double> &time_of_peak_y() const { return along_y.time; }
    const std::vector<double> &peak_resultant() const { return resultant.value; }
    const std::vector<double> &time_of_peak_resultant() const { return resultant.time; }

  private:
    struct Peaks
    {
      std::vector<double> value, time;
      /// Keep |v| of building b at time t if it is the largest yet.
      void keep(unsigned int b, double v, double t);
    };
    std::optional<StoreyForces> forces;
    Peaks                       along_x, along_y, resultant;
  };
} // namespace poundfe

#endif
