// Set-backs of 3D frame buildings (Model/Dimension = 3, Type = frame;
// doc/theory.md §1.15, "Set-backs"): `Set-backs = s: n_-x n_+x n_-y n_+y;
// ...` removes, from storey s up to the next entry, n bays of the full grid
// on each side. Storey i then keeps the grid lines [a_x, b_x] x [a_y, b_y]
// (a_x = n_-x, b_x = N_x - n_+x, likewise along y): its columns stand on the
// joints of the storey below (each storey keeps no more than the one below),
// and its floor is the rectangle of those lines,
//   C_i = ((x_a + x_b)/2, (y_a + y_b)/2) + e,  L_i = (x_b - x_a, y_b - y_a),
//   I_i = m_i (L_x,i^2 + L_y,i^2) / 12 (a uniform rectangular slab about its
//   centre, unless Plan/Polar moments are given),
// e the mass eccentricity (with the accidental one, ratio x L_i), x_j, y_j
// the grid lines measured from the full grid's centre. The slab outline for
// contact, the diaphragm's master node and the plan response follow C_i and
// L_i. Storey 1 stands on the whole grid.
// Sources: EN 1998-1:2004 §4.2.3.2 and §4.3.2 (set-backs as a regularity
// criterion; accidental eccentricity per floor dimension); Chopra, Dynamics
// of Structures, 4th ed. (2012), ch. 9 (mass and polar moment of a rigid
// rectangular slab about its centre).
#ifndef poundfe_model_set_backs_h
#define poundfe_model_set_backs_h

#include <poundfe/base/input_file.h>
#include <poundfe/base/point.h>
#include <poundfe/model/parameters.h>

#include <array>
#include <string>
#include <vector>

namespace poundfe
{
  /// The first and last grid lines a storey keeps along x and along y.
  struct KeptGrid
  {
    std::array<unsigned int, 2> x{{0, 0}}, y{{0, 0}};

    bool keeps(const unsigned int line_x, const unsigned int line_y) const
    {
      return line_x >= x[0] && line_x <= x[1] && line_y >= y[0] && line_y <= y[1];
    }
  };

  /// A floor's slab rectangle in the building's frame: its centre (from the
  /// full grid's centre) and its sides (L_x, L_y).
  struct FloorRectangle
  {
    Point2 centre{0, 0};
    Point2 dimensions{0, 0};
  };

  /// The coordinates of the n + 1 grid lines of bays `widths` (one value for
  /// all or one per bay), measured from the grid's centre.
  std::vector<double> grid_lines(const std::vector<double> &widths, unsigned int n_bays);

  /// The grid lines storey `storey` (1-based) of frame p keeps.
  KeptGrid kept_grid(const BuildingParameters &p, unsigned int storey);

  /// The slab of floor `storey` (1-based): Plan/Plan dimensions about the
  /// plan centre, or the rectangle of the lines its storey keeps.
  FloorRectangle floor_rectangle(const BuildingParameters &p, unsigned int storey);

  /// `Set-backs` of a 3D frame (the entries in p.set_backs_text) into
  /// p.set_backs. Throws InputError naming `<section>Set-backs`: a storey
  /// that does not exist (or storey 1), a storey given twice, more bays
  /// removed than the grid has, or a storey wider than the one below.
  void parse_set_backs(BuildingParameters &p, const InputFile &input, const std::string &section);
} // namespace poundfe

#endif
