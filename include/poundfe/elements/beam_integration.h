// The integration rules of a beam-column along its length, as OpenSees's
// BeamIntegration: points xi_i and weights w_i on [0, 1] (x = xi L), so that
//   int_0^L g(x) dx ~ L sum_i w_i g(xi_i L),   sum_i w_i = 1.
//   Gauss-Lobatto (OpenSees's Lobatto), n = 2..10 points: both ends are
//     points, exact for polynomials of degree 2n - 3; the ends carry the
//     largest moments of a member under end loads, where it yields first.
//     Points: the ends and the roots of P'_{n-1}; weights
//     2 / (n (n - 1) P_{n-1}(x_i)^2) on [-1, 1].
//   Gauss-Legendre (OpenSees's Legendre), n = 1..10: the roots of P_n,
//     weights 2 / ((1 - x_i^2) P'_n(x_i)^2), exact to degree 2n - 1; the
//     rule of the displacement-based element.
//   HingeRadau (Scott & Fenves 2006, "Plastic hinge integration methods for
//     force-based beam-column elements", J. Struct. Eng. 132(2), eq. 17;
//     OpenSees's HingeRadauBeamIntegration): six points, two-point Gauss-
//     Radau over 4 lp at each end, the end point weighted lp, so that the
//     plastic rotation of the end section is its plastic curvature times lp
//     exactly and the member's elastic response is exact; two-point Gauss
//     over the interior (0.5 - 2(lpI + lpJ)/L each):
//       xi = 0, 8 lpI/(3L), beta -/+ alpha/sqrt(3), 1 - 8 lpJ/(3L), 1
//       w  = lpI/L, 3 lpI/L, alpha, alpha, 3 lpJ/L, lpJ/L
//     alpha = 0.5 - 2 (lpI + lpJ)/L, beta = 0.5 + 2 (lpI - lpJ)/L. Points
//     0, 1 take the section of end I, 2, 3 the interior's, 4, 5 end J's.
// Sources: Abramowitz & Stegun (1964) 25.4.29-32; Scott & Fenves (2006);
// OpenSees's LobattoBeamIntegration, LegendreBeamIntegration,
// HingeRadauBeamIntegration.
#ifndef poundfe_elements_beam_integration_h
#define poundfe_elements_beam_integration_h

#include <vector>

namespace poundfe
{
  struct BeamIntegration
  {
    std::vector<double> points;  // xi_i in [0, 1]
    std::vector<double> weights; // w_i, summing to 1
    unsigned int        size() const { return points.size(); }
  };

  /// The most integration points of a member (OpenSees's limit of 10 for
  /// Lobatto and Legendre).
  constexpr unsigned int max_integration_points = 10;

  /// Gauss-Lobatto with n points; InputError (parameter "Integration
  /// points") unless 2 <= n <= 10.
  BeamIntegration lobatto_integration(unsigned int n);
  /// Gauss-Legendre with n points; InputError unless 1 <= n <= 10.
  BeamIntegration legendre_integration(unsigned int n);
  /// HingeRadau with hinge lengths lpI, lpJ on a member of length L;
  /// InputError (parameter "Hinge length") unless lpI, lpJ > 0 and
  /// 4 (lpI + lpJ) < L.
  BeamIntegration hinge_radau_integration(double hinge_length_i, double hinge_length_j,
                                          double length);
} // namespace poundfe

#endif
