// The element dissipation shared by the time integrators (time_stepper.h).
#include <poundfe/integration/newmark.h>
#include <poundfe/integration/time_stepper.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  namespace
  {
    /// What an element dissipated from its work, stored energy and supplied
    /// work. Not yet element.dissipates() ? ... : 0: for an undamped contact
    /// law the difference is the quadrature of its work over the steps that
    /// open or close a gap (up to 2e-6 of the input in 3D plan contact),
    /// which would then show in the energy balance error instead.
    double
    dissipation(const double work, const double stored, const double supplied)
    {
      return work - stored + supplied;
    }
  } // namespace

  double
  element_dissipation(const NonlinearElement &element, const double work, const double supplied)
  {
    return dissipation(work, element.stored_energy(), supplied);
  }

  namespace
  {
    /// set_element_dissipation with element h's stored energy stored(h).
    template <typename StoredEnergy>
    void
    book_element_dissipation(EnergyBalance &balance, const NonlinearElements &elements,
                             const std::vector<double> &work,
                             const std::vector<double> &supplied_work,
                             const std::vector<char> &counted, const StoredEnergy &stored)
    {
      balance.hysteretic = balance.contact = balance.friction = balance.links = 0;
      balance.foundation = 0;
      for (unsigned int h = 0; h < elements.size(); ++h)
        {
          if (!counted.empty() && !counted[h])
            continue;
          const double dissipated = dissipation(work[h], stored(h), supplied_work[h]);
          switch (elements[h].kind)
            {
              case ElementKind::gap:
                balance.contact += dissipated;
                break;
              case ElementKind::friction:
                balance.friction += dissipated;
                break;
              case ElementKind::link:
                balance.links += dissipated;
                break;
              case ElementKind::foundation:
                balance.foundation += dissipated;
                break;
              default: // hinges, storeys; elastic springs dissipate nothing
                balance.hysteretic += dissipated;
            }
        }
    }
  } // namespace

  void
  set_element_dissipation(EnergyBalance &balance, const NonlinearElements &elements,
                          const std::vector<double> &work, const std::vector<double> &supplied_work,
                          const std::vector<char> &counted)
  {
    book_element_dissipation(balance, elements, work, supplied_work, counted,
                             [&](const unsigned int h) { return elements[h].stored_energy(); });
  }

  void
  set_element_dissipation(EnergyBalance &balance, const NonlinearElements &elements,
                          const std::vector<double> &work, const std::vector<double> &supplied_work,
                          const std::vector<double> &stored, const std::vector<char> &counted)
  {
    AssertDimension(stored.size(), elements.size());
    book_element_dissipation(balance, elements, work, supplied_work, counted,
                             [&](const unsigned int h) { return stored[h]; });
  }

  void
  update_balance_error(const EnergyBalance &balance, double &scale, double &max_error)
  {
    const double sum      = balance.stored_and_dissipated();
    const double supplied = balance.supplied();
    scale                 = std::max({scale, std::abs(supplied), sum});
    if (scale > 0)
      max_error = std::max(max_error, std::abs(supplied - sum) / scale);
  }
} // namespace poundfe
