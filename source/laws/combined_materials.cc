// OpenSees's Parallel, Series and MinMax materials (equations and sources in
// laws/combined_materials.h).
#include <poundfe/laws/combined_materials.h>

#include <cfloat>
#include <cmath>

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

  namespace
  {
    /// 1/x within [-1e12, 1e12] (OpenSees's SeriesMaterial: x near 0 is
    /// 1e-12 of its sign, 0 counting as positive).
    double
    bounded_inverse(const double x)
    {
      if (std::abs(x) > 1.0e-12)
        return 1.0 / x;
      return x < 0.0 ? -1.0e12 : 1.0e12;
    }
  } // namespace

  SeriesUniaxial::SeriesUniaxial(std::vector<std::unique_ptr<UniaxialLaw>> parts,
                                 const unsigned int max_iterations, const double tolerance)
    : parts(std::move(parts))
    , max_iterations(max_iterations)
    , tolerance(tolerance)
  {
    reset();
  }

  double
  SeriesUniaxial::balance()
  {
    double compliance = 0, strain_sum = 0;
    for (unsigned int i = 0; i < parts.size(); ++i)
      {
        strains[i] += compliances[i] * (trial.stress - stresses[i]);
        if (!parts[i]->set_trial(strains[i], 0.0) && why.empty())
          why = "Series: " + parts[i]->failure();
        stresses[i]    = parts[i]->force();
        compliances[i] = bounded_inverse(parts[i]->tangent());
        compliance += compliances[i];
        strain_sum += strains[i] + compliances[i] * (trial.stress - stresses[i]);
      }
    trial.tangent = bounded_inverse(compliance);
    return trial.strain - strain_sum;
  }

  bool
  SeriesUniaxial::set_trial(const double strain, double)
  {
    double dv = strain - trial.strain;
    if (std::abs(dv) < DBL_EPSILON)
      return why.empty();
    why          = "";
    trial.strain = strain;
    double dq    = trial.tangent * dv;
    trial.stress += dq;
    for (unsigned int j = 0; j < max_iterations; ++j)
      {
        dv = balance();
        dq = trial.tangent * dv;
        if (std::abs(dq * dv) < tolerance)
          break;
      }
    trial.stress += dq;
    return why.empty() && std::isfinite(trial.stress) && std::isfinite(trial.tangent);
  }

  double
  SeriesUniaxial::stored_energy() const
  {
    double total = 0;
    for (const auto &part : parts)
      total += part->stored_energy();
    return total;
  }

  double
  SeriesUniaxial::initial_stiffness() const
  {
    double k_series = parts[0]->initial_stiffness();
    for (unsigned int i = 1; i < parts.size(); ++i)
      {
        const double k = parts[i]->initial_stiffness();
        if (k_series + k == 0.0)
          return 0.0;
        k_series = k_series * k / (k_series + k);
      }
    return k_series;
  }

  void
  SeriesUniaxial::commit()
  {
    committed         = trial;
    committed_strains = strains;
    for (auto &part : parts)
      part->commit();
  }

  /// OpenSees's revertToLastCommit: the components' committed state read
  /// back (so a compliance is the committed tangent's, even before a first
  /// commit).
  void
  SeriesUniaxial::revert()
  {
    trial   = committed;
    strains = committed_strains;
    why     = "";
    for (unsigned int i = 0; i < parts.size(); ++i)
      {
        parts[i]->revert();
        stresses[i]    = parts[i]->force();
        compliances[i] = bounded_inverse(parts[i]->tangent());
      }
  }

  void
  SeriesUniaxial::reset()
  {
    for (auto &part : parts)
      part->reset();
    const std::size_t n = parts.size();
    strains.assign(n, 0.0);
    stresses.assign(n, 0.0);
    compliances.assign(n, 0.0);
    committed_strains.assign(n, 0.0);
    why       = "";
    committed = trial = State{0, 0, initial_stiffness()};
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
