// The `Links` section (dampers and connectors between floors of adjacent
// buildings: laws/link_laws.h) and the `Bumpers` section (a layer in every
// 2D gap: laws/bumper.h), each declaring and checking its own entries
// (deal.II step-33 style). The model builder places them
// (source/model/building_links.cc).
#ifndef poundfe_model_link_parameters_h
#define poundfe_model_link_parameters_h

#include <poundfe/base/choices.h>
#include <poundfe/base/input_file.h>
#include <poundfe/laws/bumper.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  const NameTable<BumperLaw> &bumper_law_names();

  struct LinkParameters
  {
    // 'building floor node building floor node' and the law's numbers
    std::vector<std::string> viscous;         // ... c alpha
    std::vector<std::string> kelvin_voigt;    // ... k c alpha
    std::vector<std::string> maxwell;         // ... k c
    std::vector<std::string> elastic_plastic; // ... k F_y r
    /// 'building building k c': a spring and dashpot between the sways of
    /// two buildings' compliant foundations (the soil between them).
    std::vector<std::string> soil_coupling;
    /// 'building building k c': a rotational spring (N m/rad) and dashpot
    /// (N m s/rad) between the two foundations' rocking (in the x-z plane).
    std::vector<std::string> rocking_soil_coupling;
    double regularization_velocity = 1e-6;    // v_eps, m/s

    /// Declare the entries in the current subsection (`Links`); the entries
    /// are checked against the model by the model builder.
    void declare(dealii::ParameterHandler &prm);
    /// Throws InputError.
    void check(const InputFile &input) const;
  };

  struct BumperInputParameters
  {
    BumperParameters bumper;
    /// 'compression force' pairs separated by ';' (Law = table).
    std::vector<std::string> table;

    /// Declare the entries in the current subsection (`Bumpers`).
    void declare(dealii::ParameterHandler &prm);
    /// Reads the table into bumper.table; throws InputError.
    void finalize(const InputFile &input, const std::string &contact_law);
  };
} // namespace poundfe

#endif
