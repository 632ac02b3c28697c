// 3D frame buildings drawn in Gmsh (Model/Dimension = 3, Type = mesh): a
// line mesh in 3D (x, y horizontal, z up; mesh/line_mesh.h), its physical
// ids the member groups, made of the parts of a generated 3D frame
// (model/frame_3d_assembler.h), so that hinges, damping, foundations,
// recorders, VTU and contact in plan work unchanged (doc/theory.md §1.15,
// "Frames drawn in Gmsh"):
//   - members: vertical ones columns (drawn bottom to top), horizontal
//     ones beams, the others braces (no hinges); per group the 3D section
//     (Group E, G, A, I = Iy, Iz, J, mass per length) and the vector v of
//     the local x-z plane (default: columns global X, others global Z);
//   - floors: one at each distinct level z of the beams above the lowest
//     joint, holding every joint at that level; its slab in plan is the
//     convex hull H of those joints (Graham/Andrew monotone chain), the
//     outline for contact; with a uniform slab of mass m (Floor masses)
//     the mass centre is H's centroid (plus Plan/Mass eccentricity and the
//     accidental one) and the polar moment m J_H / A_H (J_H the polar
//     second moment of H about its centroid, A_H its area) unless
//     Plan/Polar moments gives it;
//   - bases: the joints at the lowest z, per Base fixity (or on the
//     basemat of a compliant foundation);
//   - other joints are free (two nodes of their own, no mass).
// The mesh is drawn in the building's frame; the centre of its bounding
// box in plan goes to Plan/Position (or the next place in the row), turned
// by Plan/Rotation, as a generated frame's grid centre.
// Sources: Wilson, Three-Dimensional Static and Dynamic Analysis of
// Structures, 3rd ed. (2002), ch. 7 (rigid diaphragms, master at the mass
// centre); Chopra, Dynamics of Structures, 4th ed. (2012), ch. 9 (polar
// moment of a rigid slab); Andrew, "Another efficient algorithm for convex
// hulls in two dimensions", Inf. Process. Lett. 9 (1979) 216-219.
#ifndef poundfe_model_mesh_building_3d_h
#define poundfe_model_mesh_building_3d_h

#include <poundfe/base/exceptions.h>
#include <poundfe/base/input_file.h>
#include <poundfe/model/model.h>
#include <poundfe/model/parameters.h>

#include <vector>

namespace poundfe
{
  /// Building b's (0-based) Mesh file read by `read` (read_line_mesh or
  /// read_line_mesh_3d); its InputError named as Building <b+1>/Mesh file
  /// of `input`.
  template <typename Mesh>
  Mesh
  read_building_mesh(const InputFile &input, const BuildingParameters &p, const unsigned int b,
                     Mesh (*read)(const std::string &))
  {
    const std::string path = "Building " + std::to_string(b + 1) + "/Mesh file";
    try
      {
        return read(input.resolve(p.mesh_file));
      }
    catch (const InputError &e)
      {
        throw InputError(input.file, input.line_of(path), path, e.what());
      }
  }

  /// Building b (0-based) of a 3D model from its Mesh file (resolved
  /// against `input`'s folder); `left`: where the row of buildings has got
  /// to along x (used without Plan/Position). Throws InputError naming
  /// Building <b+1>/<entry>: a mesh in one horizontal plane (a 2D mesh), a
  /// member of zero length, a physical id not in Group ids, an orientation
  /// along a member, no horizontal member, a floor whose joints are on one
  /// line (rigid diaphragm), Floor masses or Plan/Polar moments of a count
  /// other than 1 (Floor masses) or the number of floors.
  void build_mesh_frame_3d(Model &model, const InputFile &input, const BuildingParameters &p,
                           unsigned int b, Building &building, double left);

  /// The convex hull of `points`, counter-clockwise, without collinear
  /// points (fewer than 3 points when they are all on one line).
  std::vector<Point2> convex_hull(std::vector<Point2> points);

  /// Area A, centroid and polar second moment of area J about the centroid
  /// of a simple polygon given counter-clockwise.
  struct PolygonProperties
  {
    double area = 0;
    Point2 centroid;
    double polar_moment = 0;
  };
  PolygonProperties polygon_properties(const std::vector<Point2> &polygon);
} // namespace poundfe

#endif
