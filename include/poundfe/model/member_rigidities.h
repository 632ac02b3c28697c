// The bound of an elastic frame member's rigidities, shared by the 2D and
// 3D frame buildings' checks.
#ifndef poundfe_model_member_rigidities_h
#define poundfe_model_member_rigidities_h

#include <poundfe/base/input_file.h>

#include <string>
#include <vector>

namespace poundfe
{
  /// E A and E I of `member` ("Column", "Beam") at most largest_model_value
  /// for every storey (each list one value or one per storey): the member's
  /// stiffnesses are their quotients by its length and the solvers square
  /// them (an area of 1e200 m^2 ran to its end with absurd results). An
  /// InputError names `section` + member + " A" or " I".
  void check_member_rigidities(const InputFile &input, const std::string &section,
                               const std::string &member, const std::vector<double> &E,
                               const std::vector<double> &A, const std::vector<double> &I);
} // namespace poundfe

#endif
