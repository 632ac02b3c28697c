// prm -> Model: generated frames, frames from Gmsh meshes, shear buildings,
// placed left to right with the given clear separations.
#ifndef poundfe_model_model_builder_h
#define poundfe_model_model_builder_h

#include <poundfe/model/model.h>
#include <poundfe/model/parameters.h>

namespace poundfe
{
  /// Build the model and number its equations. Throws InputError.
  Model build_model(const InputParameters &parameters);
} // namespace poundfe

#endif
