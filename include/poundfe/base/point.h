// A point of the plane of the frames, (x, y) in m. Its own header so that
// the mesh reader and the model can both use it without including each other.
#ifndef poundfe_base_point_h
#define poundfe_base_point_h

namespace poundfe
{
  struct Point2
  {
    double x = 0;
    double y = 0;
  };
} // namespace poundfe

#endif
