// prm -> Model: generated frames, frames from Gmsh meshes, shear buildings,
// placed left to right with the given clear separations.
#ifndef poundfe_model_model_builder_h
#define poundfe_model_model_builder_h

#include <poundfe/base/input_file.h>
#include <poundfe/model/contact_parameters.h>
#include <poundfe/model/model.h>
#include <poundfe/model/parameters.h>

namespace poundfe
{
  /// Build the model and number its equations; `input` names the file in
  /// messages and resolves mesh files. Throws InputError.
  Model build_model(const ModelParameters &parameters, const ContactParameters &contact,
                    const InputFile &input);
} // namespace poundfe

#endif
