// The torsionally coupled shear building of
// include/poundfe/model/torsional_shear_building.h (equations and sources
// there; doc/theory.md §1.12).
#include <poundfe/base/exceptions.h>
#include <poundfe/model/torsional_shear_building.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace poundfe
{
  namespace
  {
    Eigen::Vector2d
    unit_direction(const ResistingPlane &plane)
    {
      return Eigen::Vector2d(plane.direction.x, plane.direction.y).normalized();
    }


    std::string
    storey_name(const unsigned int floor)
    {
      return "Floor " + std::to_string(floor + 1) + "/Planes";
    }

    void
    check_floor(const TorsionalFloor &floor, const unsigned int i)
    {
      const std::string name = "Floor " + std::to_string(i + 1);
      if (!(floor.mass > 0) || !std::isfinite(floor.mass))
        throw InputError("", 0, name + "/Mass", "must be a positive number");
      if (!(floor.polar_moment > 0) || !std::isfinite(floor.polar_moment))
        throw InputError("", 0, name + "/Polar moment of inertia", "must be a positive number");
      for (const ResistingPlane &plane : floor.planes)
        {
          if (!(std::hypot(plane.direction.x, plane.direction.y) > 0))
            throw InputError("", 0, storey_name(i), "a plane's direction is the zero vector");
          if (!(plane.stiffness >= 0) || !std::isfinite(plane.stiffness))
            throw InputError("", 0, storey_name(i),
                             "a plane's stiffness must be 0 or a positive number");
        }
    }
  } // namespace

  Eigen::Vector3d
  plane_row(const ResistingPlane &plane, const Point2 &point)
  {
    const Eigen::Vector2d d = unit_direction(plane);
    return {d.x(), d.y(),
            d.y() * (plane.position.x - point.x) - d.x() * (plane.position.y - point.y)};
  }

  Eigen::Matrix3d
  storey_stiffness(const std::vector<ResistingPlane> &planes, const Point2 &point)
  {
    Eigen::Matrix3d k = Eigen::Matrix3d::Zero();
    for (const ResistingPlane &plane : planes)
      {
        const Eigen::Vector3d a = plane_row(plane, point);
        k += plane.stiffness * a * a.transpose();
      }
    return k;
  }

  Point2
  stiffness_centre(const std::vector<ResistingPlane> &planes)
  {
    // Referred to the first plane's point (any point: the result does not
    // depend on it; a near one keeps the sums free of cancellation).
    const Point2          o = planes.empty() ? Point2{} : planes.front().position;
    const Eigen::Matrix3d k = storey_stiffness(planes, o);
    // K_xθ(R) = K_xθ + K_xx y_R - K_xy x_R = 0, K_yθ(R) = K_yθ + K_xy y_R - K_yy x_R = 0
    const double det = k(0, 0) * k(1, 1) - k(0, 1) * k(0, 1);
    if (!(det > 1e-12 * k(0, 0) * k(1, 1)) || !(k(0, 0) > 0) || !(k(1, 1) > 0))
      throw InputError("", 0, "Planes",
                       "the planes of a storey are all parallel (or without stiffness): they "
                       "resist no force across them and have no stiffness centre");
    const double x = (k(0, 0) * k(1, 2) - k(0, 1) * k(0, 2)) / det;
    const double y = (k(0, 1) * k(1, 2) - k(0, 2) * k(1, 1)) / det;
    return {o.x + x, o.y + y};
  }

  void
  check_building(const TorsionalShearBuilding &building)
  {
    if (building.floors.empty())
      throw InputError("", 0, "Floors", "a building needs at least one floor");
    for (unsigned int i = 0; i < building.n_floors(); ++i)
      {
        const TorsionalFloor &floor = building.floors[i];
        check_floor(floor, i);
        Point2 centre;
        try
          {
            centre = stiffness_centre(floor.planes);
          }
        catch (const InputError &e)
          {
            throw InputError("", 0, storey_name(i), e.problem());
          }
        const Eigen::Matrix3d k     = storey_stiffness(floor.planes, centre);
        double                reach = 0; // the planes' largest distance from the centre
        for (const ResistingPlane &plane : floor.planes)
          reach = std::max(reach, std::hypot(plane.position.x - centre.x,
                                             plane.position.y - centre.y));
        if (!(k(2, 2) > 1e-12 * (k(0, 0) + k(1, 1)) * reach * reach))
          throw InputError("", 0, storey_name(i),
                           "the planes of the storey all pass through one point: the floor "
                           "has no torsional stiffness (a singular diaphragm)");
      }
  }

  Eigen::MatrixXd
  stiffness_matrix(const TorsionalShearBuilding &building)
  {
    const unsigned int n = building.n_dofs();
    Eigen::MatrixXd    k = Eigen::MatrixXd::Zero(n, n);
    for (unsigned int i = 0; i < building.n_floors(); ++i)
      for (const ResistingPlane &plane : building.floors[i].planes)
        {
          // storey drift along the plane: a(C_i)·q_i - a(C_{i-1})·q_{i-1}
          const Eigen::Vector3d top = plane_row(plane, building.floors[i].mass_centre);
          k.block<3, 3>(3 * i, 3 * i) += plane.stiffness * top * top.transpose();
          if (i == 0)
            continue; // the ground does not move
          const Eigen::Vector3d bottom = plane_row(plane, building.floors[i - 1].mass_centre);
          const Eigen::Matrix3d cross  = plane.stiffness * top * bottom.transpose();
          k.block<3, 3>(3 * (i - 1), 3 * (i - 1)) += plane.stiffness * bottom * bottom.transpose();
          k.block<3, 3>(3 * i, 3 * (i - 1)) -= cross;
          k.block<3, 3>(3 * (i - 1), 3 * i) -= cross.transpose();
        }
    return k;
  }

  Eigen::MatrixXd
  mass_matrix(const TorsionalShearBuilding &building)
  {
    Eigen::VectorXd diagonal(building.n_dofs());
    for (unsigned int i = 0; i < building.n_floors(); ++i)
      diagonal.segment<3>(3 * i) << building.floors[i].mass, building.floors[i].mass,
        building.floors[i].polar_moment;
    return Eigen::MatrixXd(diagonal.asDiagonal());
  }

  StoreyTorsion
  storey_torsion(const TorsionalShearBuilding &building, const unsigned int floor)
  {
    const TorsionalFloor &f = building.floors.at(floor);
    StoreyTorsion         t;
    t.stiffness_centre      = stiffness_centre(f.planes);
    t.eccentricity          = {t.stiffness_centre.x - f.mass_centre.x,
                               t.stiffness_centre.y - f.mass_centre.y};
    const Eigen::Matrix3d k = storey_stiffness(f.planes, t.stiffness_centre);
    t.torsional_stiffness   = k(2, 2);
    t.torsional_radius_x    = std::sqrt(k(2, 2) / k(1, 1));
    t.torsional_radius_y    = std::sqrt(k(2, 2) / k(0, 0));
    t.radius_of_gyration    = std::sqrt(f.polar_moment / f.mass);
    return t;
  }

  bool
  StoreyTorsion::regular_in_plan() const
  {
    // analysis along y: e_0x against r_x; along x: e_0y against r_y
    return std::abs(eccentricity.x) <= 0.30 * torsional_radius_x &&
           torsional_radius_x >= radius_of_gyration &&
           std::abs(eccentricity.y) <= 0.30 * torsional_radius_y &&
           torsional_radius_y >= radius_of_gyration;
  }

  Point2
  accidental_eccentricity(const Point2 &plan_dimensions, const PlanDirection action,
                          const int sign, const double ratio)
  {
    const double s = sign < 0 ? -ratio : ratio;
    return action == PlanDirection::x ? Point2{0, s * plan_dimensions.y} :
                                        Point2{s * plan_dimensions.x, 0};
  }

  TorsionalShearBuilding
  with_accidental_eccentricity(const TorsionalShearBuilding &building,
                               const std::vector<Point2> &plan_dimensions,
                               const PlanDirection action, const int sign, const double ratio)
  {
    if (plan_dimensions.size() != 1 && plan_dimensions.size() != building.n_floors())
      throw InputError("", 0, "Plan dimensions",
                       "give one (L_x, L_y) for all floors or one per floor (" +
                         std::to_string(building.n_floors()) + "), not " +
                         std::to_string(plan_dimensions.size()));
    TorsionalShearBuilding shifted = building;
    for (unsigned int i = 0; i < building.n_floors(); ++i)
      {
        const Point2 e = accidental_eccentricity(
          plan_dimensions[plan_dimensions.size() == 1 ? 0 : i], action, sign, ratio);
        shifted.floors[i].mass_centre.x += e.x;
        shifted.floors[i].mass_centre.y += e.y;
      }
    return shifted;
  }
} // namespace poundfe
