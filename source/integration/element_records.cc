// The elements' records across accepted steps (integration/element_records.h).
#include <poundfe/elements/typed_element.h>
#include <poundfe/integration/element_records.h>

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
  }

  void
  ElementRecords::accept(NonlinearElements &elements, const double t0, const double t1,
                         const Vector &v_next, const std::vector<char> *counted, double &belt)
  {
    // A gap's or friction element's rate at v_next is taken once: its log
    // closes the entry with it, and it is the committed rate noted for the
    // next step (their deformation() reads only the velocities and the
    // trial state, which a commit keeps). Each element through its concrete
    // class (elements/typed_element.h): the same calls, so the same bits.
    for (const unsigned int h : gaps)
      on_concrete_element(elements[h], [&](const auto &e) {
        const double next = e.deformation(v_next);
        impacts.record(h, t0, t1, {history[h], rate[h], force[h]},
                       {e.history_variable(), next, e.force(), e.contact_point(), e.phase()});
        rate[h] = next;
      });
    for (const unsigned int h : frictions)
      on_concrete_element(elements[h], [&](const auto &e) {
        const double next = e.deformation(v_next);
        stick_slip.record(h, t0, t1, {e.was_active(), rate[h]}, {e.is_active(), next});
        rate[h] = next;
      });
    for (const unsigned int h : kept)
      on_concrete_element(elements[h], [&](auto &e) {
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
        if (e.kind != ElementKind::gap && e.kind != ElementKind::friction)
          rate[h] = e.deformation(v_next);
      });
  }

  void
  ElementRecords::merge(const RankMerge &ranks)
  {
    ranks.owned(Owner::element, work_done);
    ranks.owned(Owner::element, work_supplied);
    impacts.merge(ranks);
  }
} // namespace poundfe
