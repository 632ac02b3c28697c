// The largest ground acceleration an input may ask for, one bound for every
// entry that sets one (a record's or a generated motion's target PGA, a
// design spectrum's a_g).
#ifndef poundfe_excitation_ground_motion_bounds_h
#define poundfe_excitation_ground_motion_bounds_h

namespace poundfe
{
  /// 10 g: more than twice the largest ground acceleration ever recorded
  /// (about 4.4 g, 2008 Iwate-Miyagi Nairiku, station IWTH25) and far
  /// above any design value; an absurd value is refused at input instead
  /// of overflowing the response into NaN (a target PGA of 1e200 g did).
  inline constexpr double largest_ground_acceleration_g = 10;
  /// Why, for the message of a value beyond it.
  inline constexpr const char *largest_ground_acceleration_why =
    "more than twice the largest ground acceleration recorded";
} // namespace poundfe

#endif
