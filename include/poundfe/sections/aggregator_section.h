// A section of uncoupled resultants, as OpenSees's SectionAggregator: each
// resultant s_r (N, Mz[, My, T]) follows its own uniaxial law of its own
// deformation e_r (eps0, kappa_z[, kappa_y, theta]),
//   s_r = F_r(e_r),   k_s = diag(dF_r/de_r),
// and a resultant without a law is elastic, s_r = k_r e_r with the given
// rigidity. Any poundfe UniaxialLaw serves: a stress-strain material of the
// registry (laws/material_registry.h) used as a moment-curvature law, the
// Bouc-Wen law, the elastic-perfectly-plastic one. The interaction of the
// resultants (N-M) is absent by construction: it is the section of a
// member whose hinges are known moment-curvature laws, and the nonlinear
// section against which the beam-column elements are checked.
// Source: OpenSees, SectionAggregator (McKenna, Fenves & Scott 2000).
#ifndef poundfe_sections_aggregator_section_h
#define poundfe_sections_aggregator_section_h

#include <poundfe/laws/uniaxial_law.h>
#include <poundfe/sections/section_law.h>

#include <array>
#include <functional>
#include <memory>
#include <vector>

namespace poundfe
{
  /// Makes a law in its virgin state (each clone of a section makes its own).
  using UniaxialLawFactory = std::function<std::unique_ptr<UniaxialLaw>()>;

  class AggregatorSection : public SectionLaw
  {
  public:
    /// `rigidities`: (EA, EIz) of a plane section or (EA, EIz, EIy, GJ) of
    /// one in space, the stiffness of each resultant without a law.
    explicit AggregatorSection(const SectionVector &rigidities);

    /// Resultant r (0 N, 1 Mz, 2 My, 3 T) follows the laws that `factory`
    /// makes (replacing an earlier one). Returns *this to chain.
    AggregatorSection &set_law(unsigned int r, UniaxialLawFactory factory);

    unsigned int         n_resultants() const override { return rigidity.size(); }
    bool                 set_trial(const SectionVector &deformation) override;
    const SectionVector &resultant() const override { return trial_resultant; }
    const SectionMatrix &tangent() const override { return trial_tangent; }
    SectionMatrix        initial_tangent() const override;
    const SectionVector &deformation() const override { return trial_deformation; }
    void                 commit() override;
    void                 revert() override;
    void                 reset() override;
    std::unique_ptr<SectionLaw> clone() const override;
    std::string                 failure() const override;

    /// The law of resultant r; nullptr when it is elastic.
    const UniaxialLaw *law(unsigned int r) const { return laws[r].get(); }

    /// The resultants in OpenSees's order of a SectionAggregator's codes
    /// (its section force|deformation columns): the elastic ones first, as
    /// its base section's, then those with laws in the order first given.
    std::vector<unsigned int> response_order() const;

  private:
    /// The trial resultants and tangent from the laws' trial states.
    void gather();

    SectionVector                               rigidity;
    std::array<UniaxialLawFactory, 4>           factories;
    std::array<std::unique_ptr<UniaxialLaw>, 4> laws;
    std::vector<unsigned int>                   given; // resultants with laws, in order
    SectionVector committed_deformation, trial_deformation, trial_resultant;
    SectionMatrix                               trial_tangent;
    int                                         failed = -1; // the resultant whose law refused
  };
} // namespace poundfe

#endif
