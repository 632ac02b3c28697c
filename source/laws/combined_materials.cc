// OpenSees's Parallel and MinMax materials (equations and sources in
// laws/combined_materials.h).
#include <poundfe/laws/combined_materials.h>

namespace poundfe
{
  ParallelUniaxial::ParallelUniaxial(std::vector<std::unique_ptr<UniaxialLaw>> parts,
                                     std::vector<double>                       factors)
    : parts(std::move(parts))
    , factors(std::move(factors))
  {
    if (this->factors.empty())
      this->factors.assign(this->parts.size(), 1.0);
  }

  template <typename Value>
  double
  ParallelUniaxial::sum(const Value &value) const
  {
    double total = 0;
    for (unsigned int i = 0; i < parts.size(); ++i)
      total += factors[i] * value(*parts[i]);
    return total;
  }

  bool
  ParallelUniaxial::set_trial(const double strain, const double rate)
  {
    bool ok = true;
    for (auto &part : parts)
      if (!part->set_trial(strain, rate) && ok)
        {
          ok  = false;
          why = "Parallel: " + part->failure();
        }
    return ok;
  }

  double
  ParallelUniaxial::force() const
  {
    return sum([](const UniaxialLaw &l) { return l.force(); });
  }

  double
  ParallelUniaxial::tangent() const
  {
    return sum([](const UniaxialLaw &l) { return l.tangent(); });
  }

  double
  ParallelUniaxial::damping_tangent() const
  {
    return sum([](const UniaxialLaw &l) { return l.damping_tangent(); });
  }

  double
  ParallelUniaxial::stored_energy() const
  {
    return sum([](const UniaxialLaw &l) { return l.stored_energy(); });
  }

  double
  ParallelUniaxial::initial_stiffness() const
  {
    return sum([](const UniaxialLaw &l) { return l.initial_stiffness(); });
  }

  void
  ParallelUniaxial::commit()
  {
    for (auto &part : parts)
      part->commit();
  }

  void
  ParallelUniaxial::revert()
  {
    for (auto &part : parts)
      part->revert();
  }

  void
  ParallelUniaxial::reset()
  {
    for (auto &part : parts)
      part->reset();
  }

  MinMaxUniaxial::MinMaxUniaxial(std::unique_ptr<UniaxialLaw> part, const double min_strain,
                                 const double max_strain)
    : part(std::move(part))
    , min_strain(min_strain)
    , max_strain(max_strain)
  {}

  bool
  MinMaxUniaxial::set_trial(const double strain, const double rate)
  {
    if (committed_failed)
      return true;
    trial_failed = strain >= max_strain || strain <= min_strain;
    return trial_failed || part->set_trial(strain, rate);
  }

  double
  MinMaxUniaxial::tangent() const
  {
    return trial_failed ? 1.0e-8 * part->initial_stiffness() : part->tangent();
  }

  double
  MinMaxUniaxial::damping_tangent() const
  {
    return trial_failed ? 0.0 : part->damping_tangent();
  }

  double
  MinMaxUniaxial::stored_energy() const
  {
    return trial_failed ? 0.0 : part->stored_energy();
  }

  void
  MinMaxUniaxial::commit()
  {
    committed_failed = trial_failed;
    if (!trial_failed)
      part->commit();
  }

  void
  MinMaxUniaxial::revert()
  {
    if (!committed_failed)
      part->revert();
    trial_failed = committed_failed;
  }

  void
  MinMaxUniaxial::reset()
  {
    part->reset();
    trial_failed = committed_failed = false;
  }
} // namespace poundfe
