// The section of uncoupled resultants (see the header): each resultant its
// own uniaxial law of its own deformation, elastic where none is given.
#include <poundfe/base/lean_assert.h>
#include <poundfe/sections/aggregator_section.h>

#include <algorithm>

namespace poundfe
{
  AggregatorSection::AggregatorSection(const SectionVector &rigidities)
    : rigidity(rigidities)
  {
    Assert(rigidity.size() == 2 || rigidity.size() == 4,
           dealii::ExcMessage("a section has 2 or 4 resultants"));
    reset();
  }

  AggregatorSection &
  AggregatorSection::set_law(const unsigned int r, UniaxialLawFactory factory)
  {
    AssertIndexRange(r, n_resultants());
    factories[r] = std::move(factory);
    laws[r]      = factories[r] ? factories[r]() : nullptr;
    const auto at = std::find(given.begin(), given.end(), r);
    if (laws[r] && at == given.end())
      given.push_back(r);
    else if (!laws[r] && at != given.end())
      given.erase(at);
    reset();
    return *this;
  }

  bool
  AggregatorSection::set_trial(const SectionVector &deformation)
  {
    Assert(deformation.size() == rigidity.size(),
           dealii::ExcDimensionMismatch(deformation.size(), rigidity.size()));
    trial_deformation = deformation;
    failed            = -1;
    for (unsigned int r = 0; r < n_resultants(); ++r)
      if (laws[r] && !laws[r]->set_trial(deformation[r], 0) && failed < 0)
        failed = r;
    gather();
    return failed < 0 && trial_resultant.allFinite();
  }

  void
  AggregatorSection::gather()
  {
    for (unsigned int r = 0; r < n_resultants(); ++r)
      {
        trial_resultant[r] =
          laws[r] ? laws[r]->force() : rigidity[r] * trial_deformation[r];
        trial_tangent(r, r) = laws[r] ? laws[r]->tangent() : rigidity[r];
      }
  }

  SectionMatrix
  AggregatorSection::initial_tangent() const
  {
    SectionMatrix k = SectionMatrix::Zero(n_resultants(), n_resultants());
    for (unsigned int r = 0; r < n_resultants(); ++r)
      k(r, r) = laws[r] ? laws[r]->initial_stiffness() : rigidity[r];
    return k;
  }

  void
  AggregatorSection::commit()
  {
    for (const auto &law : laws)
      if (law)
        law->commit();
    committed_deformation = trial_deformation;
  }

  void
  AggregatorSection::revert()
  {
    for (const auto &law : laws)
      if (law)
        law->revert();
    trial_deformation = committed_deformation;
    failed            = -1;
    gather();
  }

  void
  AggregatorSection::reset()
  {
    const unsigned int n = n_resultants();
    for (const auto &law : laws)
      if (law)
        law->reset();
    trial_deformation = committed_deformation = SectionVector::Zero(n);
    trial_resultant   = SectionVector::Zero(n);
    trial_tangent     = SectionMatrix::Zero(n, n);
    failed            = -1;
    gather();
  }

  std::unique_ptr<SectionLaw>
  AggregatorSection::clone() const
  {
    auto copy = std::make_unique<AggregatorSection>(rigidity);
    for (const unsigned int r : given)
      copy->set_law(r, factories[r]);
    return copy;
  }

  std::vector<unsigned int>
  AggregatorSection::response_order() const
  {
    std::vector<unsigned int> order;
    for (unsigned int r = 0; r < n_resultants(); ++r)
      if (!laws[r])
        order.push_back(r);
    order.insert(order.end(), given.begin(), given.end());
    return order;
  }

  std::string
  AggregatorSection::failure() const
  {
    static const char *names[4] = {"N", "Mz", "My", "T"};
    if (failed < 0)
      return {};
    return std::string("aggregator section, resultant ") + names[failed] + ": " +
           laws[failed]->failure();
  }
} // namespace poundfe
