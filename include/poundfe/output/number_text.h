// The text of doubles in CSV files: std::to_chars's shortest form that reads
// back to the same double, byte for byte, written by shortest_text
// (output/shortest_text.h: Dragonbox's digits in to_chars's layout), with a
// memory of the numbers written lately.
//
// The recorders of one run write the same number many times: the time in
// every file of a step, a floor displacement also as a hinge's drift and in
// the phase portrait, a running maximum or a zero in the same column step
// after step. A direct-mapped table keyed by the bits of the double keeps the
// text of the last number in each of its slots; a hit copies the text instead
// of converting again (doc/benchmarks.md, "Shortest text", has the cost of a
// conversion). The text is that of std::to_chars either way.
#ifndef poundfe_output_number_text_h
#define poundfe_output_number_text_h

#include <array>
#include <cstdint>
#include <cstring>

namespace poundfe
{
  class NumberText
  {
  public:
    /// Room `write` needs after `out`: to_chars's longest double is 24
    /// characters ("-2.2250738585072014e-308"); the copy moves a whole slot.
    static constexpr std::size_t max_length = 32;

    NumberText();

    /// Writes x at `out` (which has max_length characters of room) and
    /// returns the end of the text.
    char *
    write(char *out, const double x)
    {
      std::uint64_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      Slot &slot = slots[(bits * 0x9e3779b97f4a7c15ull) >> (64 - log2_slots)];
      if (slot.bits != bits)
        convert(slot, bits, x);
      std::memcpy(out, slot.text, max_length);
      return out + slot.length;
    }

  private:
    struct Slot
    {
      std::uint64_t bits; // of the double whose text this is
      std::uint32_t length;
      char          text[max_length];
    };
    static constexpr unsigned int log2_slots = 8; // 256 slots of 48 bytes: in L1

    static void convert(Slot &slot, std::uint64_t bits, double x);

    std::array<Slot, 1u << log2_slots> slots;
  };
} // namespace poundfe

#endif
