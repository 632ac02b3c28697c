#include <poundfe/output/number_text.h>

#include <charconv>

namespace poundfe
{
  NumberText::NumberText()
  {
    // every slot starts as the text of +0.0, a valid entry
    for (Slot &slot : slots)
      convert(slot, 0, 0.0);
  }

  void
  NumberText::convert(Slot &slot, const std::uint64_t bits, const double x)
  {
    slot.bits   = bits;
    slot.length = std::to_chars(slot.text, slot.text + max_length, x).ptr - slot.text;
  }
} // namespace poundfe
