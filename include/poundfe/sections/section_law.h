// The interface of a beam-column cross-section: stress resultants s and the
// section tangent k_s = ds/de from the section deformations e at one
// integration point of a member, after OpenSees's SectionForceDeformation
// (setTrialSectionDeformation / getStressResultant / getSectionTangent /
// commitState / revertToLastCommit / revertToStart), with the same order
// and signs, so that a member of poundfe and one of OpenSees meet:
//   plane (2 resultants):  e = (eps0, kappa_z),              s = (N, Mz)
//   space (4 resultants):  e = (eps0, kappa_z, kappa_y, theta), s = (N, Mz, My, T)
// eps0 is the axial strain of the reference axis (tension positive), and a
// fibre at (y, z) of the section strains eps = eps0 - y kappa_z + z kappa_y
// (OpenSees's FiberSection2d/3d); theta is the rate of twist, its torque
// T = GJ theta elastic.
// State follows the uniaxial laws (laws/uniaxial_law.h): set_trial ->
// resultant() and tangent() -> commit() or revert(); revert() restores the
// committed state exactly, and nothing but commit() changes it.
// Vectors and matrices are Eigen types of at most 4 rows on the stack: a
// member's state determination allocates nothing.
#ifndef poundfe_sections_section_law_h
#define poundfe_sections_section_law_h

#include <Eigen/Core>

#include <memory>
#include <string>

namespace poundfe
{
  using SectionVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 4, 1>;
  using SectionMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 4, 4>;

  class SectionLaw
  {
  public:
    virtual ~SectionLaw() = default;

    /// 2 (N, Mz) for a plane member, 4 (N, Mz, My, T) for one in space.
    virtual unsigned int n_resultants() const = 0;

    /// Evaluate the trial state at the deformations e (n_resultants()
    /// entries). Returns false when a fibre's law refuses its strain;
    /// failure() then says which and why, and the trial state must not be
    /// used (revert() or a new set_trial()).
    virtual bool set_trial(const SectionVector &deformation) = 0;

    /// s at the trial state.
    virtual const SectionVector &resultant() const = 0;
    /// k_s = ds/de at the trial state, consistent with the fibres' laws.
    virtual const SectionMatrix &tangent() const = 0;
    /// k_s at the virgin state (e = 0).
    virtual SectionMatrix initial_tangent() const = 0;
    /// e of the trial state.
    virtual const SectionVector &deformation() const = 0;

    virtual void commit() = 0;
    virtual void revert() = 0;
    /// Back to the virgin state.
    virtual void reset() = 0;

    /// A copy in the virgin state with the same data (one per integration
    /// point of every member that uses the section).
    virtual std::unique_ptr<SectionLaw> clone() const = 0;

    /// Why set_trial returned false, with the values.
    virtual std::string failure() const { return {}; }
  };
} // namespace poundfe

#endif
