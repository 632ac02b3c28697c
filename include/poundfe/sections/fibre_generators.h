// The fibres of patches and reinforcing layers, with OpenSees's geometry
// exactly (material/section/repres: QuadPatch, CircPatch, StraightReinfLayer,
// CircReinfLayer and their Tcl commands), so that an OpenSees `section Fiber`
// block maps one to one onto a poundfe section:
//   patch quad M nIJ nJK yI zI yJ zJ yK zK yL zL  vertices counter-clockwise;
//       the square (xi, eta) in [-1, 1]^2 maps bilinearly onto I J K L, cut
//       in nIJ x nJK cells (j outer, i inner), each a fibre at the
//       quadrilateral's centroid with its area;
//   patch rect M nY nZ yI zI yJ zJ  the quad (yI,zI) (yJ,zI) (yJ,zJ) (yI,zJ);
//   patch circ M nCirc nRad yc zc rInt rExt [a0 a1]  angles in degrees
//       (default 0 360); ring j (outer), sector i (inner) an annular sector
//       of area (theta/2)(r2^2 - r1^2) at its centroid, radius
//       (2/3) sin(theta/2)/(theta/2) (r2^3 - r1^3)/(r2^2 - r1^2), on the
//       sector's bisector (OpenSees's CircSectionCell);
//   layer straight M n A y1 z1 y2 z2  n bars evenly from the first point to
//       the second (one bar: at the midpoint);
//   layer circ M n A yc zc r [a0 a1]  bars at a0 + i (a1 - a0)/(n - 1);
//       without angles, or with a1 - a0 >= 360, a1 = a0 + 360 - 360/n (no two
//       bars at one place);
//   fiber y z A M  one fibre.
// OpenSees names a material by its tag; here by its name in the section.
#ifndef poundfe_sections_fibre_generators_h
#define poundfe_sections_fibre_generators_h

#include <poundfe/sections/fibre_section.h>

#include <array>
#include <string>

namespace poundfe
{
  /// A point of the section, (y, z) in m.
  struct SectionPoint
  {
    double y = 0, z = 0;
  };

  /// Each adds its fibres with material index `material`. InputError
  /// (parameter "Fibres") for a count < 1, a non-positive area or
  /// dimension, clockwise vertices or a ring with rExt <= rInt.
  void add_quad_patch(FibreGeometry &geometry, unsigned int material, unsigned int n_ij,
                      unsigned int n_jk, const std::array<SectionPoint, 4> &vertices);
  void add_rect_patch(FibreGeometry &geometry, unsigned int material, unsigned int n_y,
                      unsigned int n_z, SectionPoint i, SectionPoint j);
  void add_circ_patch(FibreGeometry &geometry, unsigned int material, unsigned int n_circ,
                      unsigned int n_rad, SectionPoint centre, double inner_radius,
                      double outer_radius, double start_angle = 0, double end_angle = 360);
  void add_straight_layer(FibreGeometry &geometry, unsigned int material, unsigned int n_bars,
                          double bar_area, SectionPoint start, SectionPoint end);
  void add_circ_layer(FibreGeometry &geometry, unsigned int material, unsigned int n_bars,
                      double bar_area, SectionPoint centre, double radius, double start_angle = 0,
                      double end_angle = 360);
  void add_fibre(FibreGeometry &geometry, unsigned int material, SectionPoint at, double area);

  /// Adds the fibres of a text of OpenSees commands (the forms above, with
  /// material names for tags) separated by ';' or new lines. InputError
  /// (parameter "Fibres") naming the command, its number and what is wrong.
  void add_fibre_commands(FibreGeometry &geometry, const std::string &text);
} // namespace poundfe

#endif
