// An elastic cross-section: s = k_s e with the constant diagonal k_s
//   plane:  diag(EA, EIz)            space:  diag(EA, EIz, EIy, GJ)
// (OpenSees's ElasticSection2d/3d), the section of a member that stays
// elastic and the reference against which a member's integration is checked
// (an elastic member's exact stiffness, Przemieniecki 1968, ch. 5).
#ifndef poundfe_sections_elastic_section_h
#define poundfe_sections_elastic_section_h

#include <poundfe/sections/section_law.h>

namespace poundfe
{
  class ElasticSection : public SectionLaw
  {
  public:
    /// Plane: EA, EIz.
    ElasticSection(double axial_rigidity, double flexural_rigidity_z);
    /// Space: EA, EIz, EIy, GJ.
    ElasticSection(double axial_rigidity, double flexural_rigidity_z, double flexural_rigidity_y,
                   double torsional_rigidity);

    unsigned int         n_resultants() const override { return stiffness.rows(); }
    bool                 set_trial(const SectionVector &deformation) override;
    const SectionVector &resultant() const override { return trial_resultant; }
    const SectionMatrix &tangent() const override { return stiffness; }
    SectionMatrix        initial_tangent() const override { return stiffness; }
    const SectionVector &deformation() const override { return trial_deformation; }
    void                 commit() override {}
    void                 revert() override {}
    void                 reset() override;
    std::unique_ptr<SectionLaw> clone() const override;

  private:
    SectionMatrix stiffness;
    SectionVector trial_deformation, trial_resultant;
  };
} // namespace poundfe

#endif
