// OpenSees's uniaxial materials made of other materials, as OpenSees 3.8
// defines them (SRC/material/uniaxial/), so that a script's combinations give
// OpenSees's numbers:
//
// Parallel (ParallelMaterial): every component at the same strain and rate;
//   sigma = sum f_i sigma_i, tangent sum f_i E_i, damping tangent
//   sum f_i eta_i (f_i = 1 without -factors), as ParallelMaterial's
//   getDampTangent, which zeroLength adds to its damping matrix when it is
//   given no -doRayleigh 1.
// MinMax (MinMaxMaterial): the component while min < eps < max; a trial
//   outside fails the material (stress 0, tangent 1e-8 times the
//   component's initial tangent, damping tangent 0), and a committed failure
//   is for good.
// Series (SeriesMaterial): the components carry one stress sigma at strains
//   eps_i summing to eps. From the last trial (not the committed state:
//   OpenSees's iteration is incremental), sigma += E (eps - eps_last); then
//   up to maxIter times: each component's strain eps_i += (sigma - sigma_i)
//   / E_i at its last stress sigma_i and tangent E_i, evaluated there (at
//   rate 0), E = 1 / sum 1/E_i (each 1/E_i, and 1/E, kept within
//   [-1e12, 1e12]), the residual strain dv = eps - sum (eps_i + (sigma -
//   sigma_i) / E_i) and dq = E dv, stopping when |dq dv| < tol; sigma += dq
//   of the last pass. A strain change below machine epsilon changes nothing.
//   Initial tangent 1 / sum 1/E0_i; no damping tangent (the components see
//   no rate).
#ifndef poundfe_laws_combined_materials_h
#define poundfe_laws_combined_materials_h

#include <poundfe/laws/uniaxial_law.h>

#include <memory>
#include <vector>

namespace poundfe
{
  class ParallelUniaxial : public UniaxialLaw
  {
  public:
    /// `factors` empty: every factor 1.
    ParallelUniaxial(std::vector<std::unique_ptr<UniaxialLaw>> parts, std::vector<double> factors);

    bool        set_trial(double strain, double rate) override;
    std::string failure() const override { return why; }
    double      force() const override;
    double      tangent() const override;
    double      damping_tangent() const override;
    double      stored_energy() const override;
    double      initial_stiffness() const override;
    void        commit() override;
    void        revert() override;
    void        reset() override;
    /// Component i (0-based), at the Parallel's strain and rate.
    const UniaxialLaw &part(const unsigned int i) const { return *parts.at(i); }

  private:
    template <typename Value>
    double sum(const Value &value) const;

    std::vector<std::unique_ptr<UniaxialLaw>> parts;
    std::vector<double>                       factors;
    std::string                               why;
  };

  class SeriesUniaxial : public UniaxialLaw
  {
  public:
    SeriesUniaxial(std::vector<std::unique_ptr<UniaxialLaw>> parts, unsigned int max_iterations,
                   double tolerance);

    bool        set_trial(double strain, double rate) override;
    std::string failure() const override { return why; }
    double      force() const override { return trial.stress; }
    double      tangent() const override { return trial.tangent; }
    double      stored_energy() const override;
    double      initial_stiffness() const override;
    void        commit() override;
    void        revert() override;
    void        reset() override;
    /// Component i (0-based) and its strain at its last evaluation.
    const UniaxialLaw &part(const unsigned int i) const { return *parts.at(i); }
    double             part_strain(const unsigned int i) const { return strains.at(i); }

  private:
    /// One pass over the components at the trial stress; the residual strain.
    double balance();

    struct State
    {
      double strain = 0, stress = 0, tangent = 0;
    };
    std::vector<std::unique_ptr<UniaxialLaw>> parts;
    unsigned int                              max_iterations;
    double                                    tolerance;
    State                                     trial, committed;
    /// Each component's last strain, stress and compliance 1/E_i, and its
    /// strain at the last commit.
    std::vector<double> strains, stresses, compliances, committed_strains;
    std::string         why;
  };

  class MinMaxUniaxial : public UniaxialLaw
  {
  public:
    MinMaxUniaxial(std::unique_ptr<UniaxialLaw> part, double min_strain, double max_strain);

    bool        set_trial(double strain, double rate) override;
    std::string failure() const override { return part->failure(); }
    double      force() const override { return trial_failed ? 0.0 : part->force(); }
    double      tangent() const override;
    double      damping_tangent() const override;
    double      stored_energy() const override;
    double      initial_stiffness() const override { return part->initial_stiffness(); }
    void        commit() override;
    void        revert() override;
    void        reset() override;
    /// The component, at the MinMax's strain and rate.
    const UniaxialLaw &component() const { return *part; }

  private:
    std::unique_ptr<UniaxialLaw> part;
    double                       min_strain, max_strain;
    bool                         trial_failed = false, committed_failed = false;
  };
} // namespace poundfe

#endif
