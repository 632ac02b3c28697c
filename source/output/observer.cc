#include <poundfe/output/observer.h>

namespace poundfe
{
  const char *
  RunStatus::name() const
  {
    switch (kind)
      {
        case Kind::completed:
          return "completed";
        case Kind::failed:
          return "failed";
        case Kind::interrupted:
          return "interrupted";
      }
    return "unknown"; // unreachable: every Kind is listed above
  }

  ResponseView::ResponseView(const Model &model_, const LinearSystem &system_,
                             const NonlinearElements &elements_,
                             const TimeStepper &integrator_)
    : model(model_)
    , system(system_)
    , elements(elements_)
    , integrator(integrator_)
  {}

  void
  ResponseView::set_step(const unsigned long step, const std::array<double, 3> &ground_acceleration)
  {
    step_index = step;
    ground     = ground_acceleration;
  }

  double
  ResponseView::dissipated_energy(const unsigned int h) const
  {
    const double stored = stored_energies ? (*stored_energies)[h] : elements[h].stored_energy();
    return integrator.element_work(h) - stored +
           integrator.element_supplied_work(h);
  }
} // namespace poundfe
