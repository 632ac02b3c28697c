#include <poundfe/output/number_text.h>
#include <poundfe/output/shortest_text.h>

namespace poundfe
{
  static_assert(NumberText::max_length >= shortest_text_room);

  NumberText::NumberText()
  {
    // every slot starts as the text of +0.0, a valid entry
    for (Slot &slot : slots)
      convert(slot, 0, 0.0);
  }

  void
  NumberText::convert(Slot &slot, const std::uint64_t bits, const double x)
  {
    // std::to_chars's text, from Dragonbox's digits (about half of Ryu's cost)
    slot.bits   = bits;
    slot.length = shortest_text(slot.text, x) - slot.text;
  }
} // namespace poundfe
