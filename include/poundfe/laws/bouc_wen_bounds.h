// The meaningful ranges of the Bouc-Wen shape entries (laws/bouc_wen.h),
// F = alpha k u + (1 - alpha) k u_y z, dz/du = (A - |z|^n (beta sgn(du z)
// + gamma)) / u_y, z dimensionless, k and u_y the entries' stiffness and
// yield deformation:
//   A in [0.01, 100]: the hysteretic part's initial stiffness is
//     A (1 - alpha) k; A = 1 makes k the initial stiffness, as the entries
//     mean it (A is redundant with beta, gamma and u_y: Ma, Zhang & Xu,
//     J. Sound Vib. 271 (2004) 1, who set A = 1);
//   n in [1, 100]: n sets how sharp the yield transition is; at n = 100,
//     |z|^n < 1/2 until |z| > 0.993, the bilinear law to well within a
//     storey's data (Ismail, Ikhouane & Rodellar, Arch. Comput. Methods
//     Eng. 16 (2009) 161: n -> infinity is the bilinear law);
//   beta + gamma > 0 and beta >= |gamma| or gamma >= |beta| (|z| stays
//     bounded; the loop is dissipative), |beta|, |gamma| <= 100 (A's bound:
//     beta + gamma = A in the normalised law);
//   z_u = (A / (beta + gamma))^(1/n) in [0.01, 100]: the hysteretic part's
//     strength is (1 - alpha) k u_y z_u, within a factor 100 of the yield
//     force k u_y the entries give.
// Beyond them (A, n, beta or gamma of 1e200) a run failed as a numerical
// failure, or gave forces far past any structure's.
#ifndef poundfe_laws_bouc_wen_bounds_h
#define poundfe_laws_bouc_wen_bounds_h

#include <string>

namespace poundfe
{
  struct BoucWenParameters;

  /// The first shape entry of `h` outside its range ("alpha", "A", "n",
  /// "beta", "gamma") and what is wrong with it; an empty entry when the
  /// shape is meaningful.
  struct BoucWenShapeProblem
  {
    std::string entry;
    std::string problem;
  };

  BoucWenShapeProblem bouc_wen_shape_problem(const BoucWenParameters &h);
} // namespace poundfe

#endif
