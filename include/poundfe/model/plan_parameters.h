// The `Building <i>/Plan` subsection: a building of a 3D model (Model/
// Dimension = 3) in plan: slab rectangle, position and rotation on the site,
// mass eccentricity (with the codes' accidental eccentricity), polar moments
// and the lateral-resisting planes of every storey (doc/theory.md §1.12).
#ifndef poundfe_model_plan_parameters_h
#define poundfe_model_plan_parameters_h

#include <poundfe/base/input_file.h>
#include <poundfe/base/point.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  /// A resisting plane as read, in the building's frame (origin at the plan
  /// centre): position, direction angle from x, storey stiffness (N/m) and
  /// Bouc-Wen yield drift (0: elastic).
  struct PlaneEntry
  {
    Point2 position;
    double angle       = 0; // rad
    double stiffness   = 0;
    double yield_drift = 0;
  };

  struct PlanParameters
  {
    std::vector<double> dimensions{10.0, 10.0};  // L_x, L_y of the slab, m
    std::vector<double> position;                // plan centre on the site; empty: in a row
    double              rotation = 0;            // degrees, counter-clockwise
    std::vector<double> polar_moments;           // per floor; empty: m (L_x² + L_y²) / 12
    std::vector<double> mass_eccentricity{0, 0}; // building frame, m
    std::string         accidental = "none";     // none|+x|-x|+y|-y
    double              accidental_ratio = 0.05;
    std::string         planes_text;             // 'x y angle k [u_y]; ...'
    std::string         storey_law = "planes";   // planes|bidirectional Bouc-Wen

    /// Parsed by finalize: the planes of every storey (empty: the default
    /// perimeter planes, made by the builder from the storey stiffnesses).
    std::vector<PlaneEntry> planes;

    /// Declare the entries of `Plan` (entered and left here).
    void declare(dealii::ParameterHandler &prm);
    /// Check the entries of `<section>Plan/` for a building of n_floors.
    /// Throws InputError.
    void finalize(const InputFile &input, const std::string &section, unsigned int n_floors);
    /// The mass eccentricity within the slab rectangle (Plan dimensions:
    /// shear buildings' slabs and 3D frames' column grids).
    void check_mass_on_slab(const InputFile &input, const std::string &section) const;
  };
} // namespace poundfe

#endif
