// The elastic cross-section: s = diag(EA, EIz[, EIy, GJ]) e (see the header).
#include <poundfe/base/lean_assert.h>
#include <poundfe/sections/elastic_section.h>

#include <cmath>

namespace poundfe
{
  ElasticSection::ElasticSection(const double axial_rigidity, const double flexural_rigidity_z)
    : stiffness(SectionMatrix::Zero(2, 2))
  {
    stiffness(0, 0) = axial_rigidity;
    stiffness(1, 1) = flexural_rigidity_z;
    reset();
  }

  ElasticSection::ElasticSection(const double axial_rigidity, const double flexural_rigidity_z,
                                 const double flexural_rigidity_y, const double torsional_rigidity)
    : stiffness(SectionMatrix::Zero(4, 4))
  {
    stiffness(0, 0) = axial_rigidity;
    stiffness(1, 1) = flexural_rigidity_z;
    stiffness(2, 2) = flexural_rigidity_y;
    stiffness(3, 3) = torsional_rigidity;
    reset();
  }

  bool ElasticSection::set_trial(const SectionVector &deformation)
  {
    Assert(deformation.size() == stiffness.rows(),
           dealii::ExcDimensionMismatch(deformation.size(), stiffness.rows()));
    trial_deformation = deformation;
    trial_resultant   = stiffness * deformation;
    return trial_resultant.allFinite();
  }

  void ElasticSection::reset()
  {
    trial_deformation = SectionVector::Zero(stiffness.rows());
    trial_resultant   = SectionVector::Zero(stiffness.rows());
  }

  std::unique_ptr<SectionLaw> ElasticSection::clone() const
  {
    auto copy = std::make_unique<ElasticSection>(*this);
    copy->reset();
    return copy;
  }
} // namespace poundfe
