// Calls on a nonlinear element through its concrete class where that class
// is UniaxialElement (final): f(element) with the element as the
// UniaxialElement it is, else as the NonlinearElement. Through the final
// class a call such as force() or commit() is the law's own virtual call
// only, not the element's and then the law's; the functions called are the
// same either way, so the results are the same bits. For the per-step loops
// that run over the elements once (records at accept, peaks): the test is a
// comparison of type_info names, cheaper than a dynamic_cast; loops that run
// per Newton iteration keep a typed list instead (integration/newmark.cc).
#ifndef poundfe_elements_typed_element_h
#define poundfe_elements_typed_element_h

#include <poundfe/elements/uniaxial_element.h>

#include <type_traits>
#include <typeinfo>

namespace poundfe
{
  /// f(element) as a UniaxialElement when it is one (const kept), else f(element).
  template <typename Element, typename F>
  decltype(auto)
  on_concrete_element(Element &element, F &&f)
  {
    static_assert(std::is_base_of_v<NonlinearElement, std::remove_const_t<Element>>);
    using Uniaxial =
      std::conditional_t<std::is_const_v<Element>, const UniaxialElement, UniaxialElement>;
    if (typeid(element) == typeid(UniaxialElement))
      return f(static_cast<Uniaxial &>(element));
    return f(element);
  }
} // namespace poundfe

#endif
