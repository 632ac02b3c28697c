// The elements' records across accepted steps (integration/element_records.h).
#include <poundfe/elements/uniaxial_element.h>
#include <poundfe/integration/element_records.h>

#include <deal.II/base/exceptions.h>

namespace poundfe
{
  ElementRecords::ElementRecords(const NonlinearElements *elements,
                                 const std::vector<char>  *observed)
  {
    const unsigned int n = elements ? elements->size() : 0;
    for (unsigned int h = 0; h < n; ++h)
      {
        if (observed && !(*observed)[h])
          continue;
        kept.push_back(h);
        if ((*elements)[h].kind == ElementKind::gap)
          gaps.push_back(h);
        if ((*elements)[h].kind == ElementKind::friction)
          frictions.push_back(h);
      }
    for (auto *x : {&work_done, &work_supplied, &force, &history, &rate})
      x->assign(n, 0.0);
  }

  void
  ElementRecords::note_committed(const NonlinearElements &elements, const Vector &v)
  {
    for (const unsigned int h : kept)
      {
        const NonlinearElement &e = elements[h];
        force[h]                  = e.force();
        history[h]                = e.history_variable();
        rate[h]                   = e.deformation(v);
      }
  }

  void
  ElementRecords::start(const NonlinearElements &elements)
  {
    impacts.reset(elements.size());
    stick_slip.reset(elements.size());
    std::fill(work_supplied.begin(), work_supplied.end(), 0.0);
    held_work = 0;
    for (const unsigned int h : kept)
      work_done[h] = elements[h].stored_energy();
    // accept() commits these through the pointers: it must be given the
    // elements given here, as both callers do (the integrator's own). The
    // const_cast goes with start()'s const argument in the header.
    typed.assign(elements.size(), nullptr);
    for (const unsigned int h : kept)
      typed[h] = const_cast<UniaxialElement *>(as_uniaxial(elements[h]));
  }

  template <typename Element>
  void
  ElementRecords::accept_element(const unsigned int h, Element &e, const std::vector<char> *counted,
                                 double &belt)
  {
    const double supplied = e.supplied_work_increment();
    work_done[h] += e.work_increment();
    work_supplied[h] += supplied;
    if (!counted || (*counted)[h])
      {
        belt += supplied;
        held_work += e.held_load_work_increment();
      }
    e.commit();
    force[h]   = e.force();
    history[h] = e.history_variable();
  }

  void
  ElementRecords::accept(NonlinearElements &elements, const double t0, const double t1,
                         const Vector &v_next, const std::vector<char> *counted, double &belt)
  {
    // The elements hold the step's trial state, their last evaluation: a
    // uniaxial element's rate at v_next is the one it was evaluated with
    // (the same sums, so the same bits), read through the final class.
    // Another class forms it as before: a gap's or friction element's
    // before the commit (it closes their log entries), the others' after.
    Assert(typed.size() == elements.size(), dealii::ExcMessage("accept() before start()"));
    const auto on_element = [&](const unsigned int h, auto &&f) {
      if (UniaxialElement *const e = typed[h])
        f(*e, e->trial_rate_value());
      else
        f(elements[h], elements[h].deformation(v_next));
    };
    for (const unsigned int h : gaps)
      on_element(h, [&](const auto &e, const double next) {
        impacts.record(h, t0, t1, {history[h], rate[h], force[h]},
                       {e.history_variable(), next, e.force(), e.contact_point(), e.phase()});
        rate[h] = next;
      });
    for (const unsigned int h : frictions)
      on_element(h, [&](const auto &e, const double next) {
        stick_slip.record(h, t0, t1, {e.was_active(), rate[h]}, {e.is_active(), next});
        rate[h] = next;
      });
    for (const unsigned int h : kept)
      if (UniaxialElement *const e = typed[h])
        {
          Assert(e == &elements[h], dealii::ExcMessage("accept() without start()'s elements"));
          accept_element(h, *e, counted, belt);
          rate[h] = e->trial_rate_value();
        }
      else
        {
          NonlinearElement &other = elements[h];
          accept_element(h, other, counted, belt);
          if (other.kind != ElementKind::gap && other.kind != ElementKind::friction)
            rate[h] = other.deformation(v_next);
        }
  }

  void
  ElementRecords::merge(const RankMerge &ranks)
  {
    ranks.owned(Owner::element, work_done);
    ranks.owned(Owner::element, work_supplied);
    impacts.merge(ranks);
  }
} // namespace poundfe
