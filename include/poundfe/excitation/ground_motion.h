// A horizontal ground acceleration history on a uniform time grid, in m/s^2,
// linear between samples (or held over each interval: white noise) and zero
// outside [0, duration].
#ifndef poundfe_excitation_ground_motion_h
#define poundfe_excitation_ground_motion_h

#include <string>
#include <vector>

namespace poundfe
{
  constexpr double standard_gravity = 9.80665; // m/s^2

  class GroundMotion
  {
  public:
    GroundMotion() = default;
    GroundMotion(double time_step, std::vector<double> acceleration, std::string description,
                 bool held = false);

    double value(double t) const;
    double time_step() const { return dt; }
    double duration() const { return values.empty() ? 0 : dt * (values.size() - 1); }
    double peak() const; // PGA, m/s^2
    const std::vector<double> &samples() const { return values; }
    const std::string &description() const { return text; }
    void scale(double factor);
    /// Index of the first sample that is not finite or is denormal (nonzero
    /// below DBL_MIN in magnitude: a unit or scale factor gone wrong), or
    /// samples().size() when every sample is usable.
    std::size_t first_unusable_sample() const;
    bool empty() const { return values.empty(); }
    bool is_held() const { return held; }
    /// In-place access for a new realization of the same grid.
    std::vector<double> &samples_for_update() { return values; }

  private:
    double              dt = 1;
    std::vector<double> values;
    std::string         text;
    bool                held = false;
  };
} // namespace poundfe

#endif
