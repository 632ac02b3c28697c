// The `Building <i>/Foundation` subsection: a compliant foundation under a
// 2D or 3D shear building (the sway-rocking model) or a frame (a rigid
// foundation under its column bases, with a vertical spring too; doc/
// theory.md §1.16): the
// soil's shear-wave velocity, density and Poisson ratio and the
// foundation's size and embedment give the springs and dashpots by Gazetas'
// formulas or Wolf's cones (laws/foundation_impedance.h), or they are typed
// in; the foundation's mass and rotary inertia. Off (Type = none) by default.
#ifndef poundfe_model_foundation_parameters_h
#define poundfe_model_foundation_parameters_h

#include <poundfe/base/choices.h>
#include <poundfe/base/input_file.h>
#include <poundfe/laws/foundation_impedance.h>
#include <poundfe/model/model.h>

#include <string>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  /// The soils' shear-wave velocities a foundation may stand on, m/s: below
  /// 1 m/s the impedances (rho V_s^2 ...) are no soil's and underflow for a
  /// typo like 1e-300; above 10 km/s no rock.
  inline constexpr double smallest_shear_wave_velocity = 1;
  inline constexpr double largest_shear_wave_velocity  = 1e4;

  enum class FoundationType
  {
    none,
    gazetas,
    cone,
    given
  };

  const NameTable<FoundationType> &foundation_type_names();

  struct FoundationParameters
  {
    FoundationType     type = FoundationType::none;
    SoilProperties     soil;
    FoundationGeometry geometry;
    /// Type = given: the springs and dashpots as typed.
    FoundationImpedance given;
    double              mass           = 0; // kg, on the sway
    double              rotary_inertia = 0; // kg m², about the base node

    /// Set by finalize: the springs and dashpots in use (and Wolf's added
    /// rotary inertia, already in rotary_inertia).
    FoundationImpedance impedance;

    /// Dimension 3: the typed-in sway along y, rocking about x and torsion
    /// (Type = given; along x and about y: `given`), the rotary inertia
    /// about x (rotary_inertia: about y) and the polar one about the
    /// vertical, and, set by finalize_3d, the impedances in use.
    FoundationImpedance3D given_3d;
    double                rotary_inertia_x = 0; // kg m²
    double                polar_inertia    = 0; // kg m²
    FoundationImpedance3D impedance_3d;

    bool enabled() const { return type != FoundationType::none; }

    /// Declare the entries of `Foundation` (entered and left here).
    void declare(dealii::ParameterHandler &prm);
    /// Check `<section>Foundation/` and compute the impedance for a building
    /// of `type` (meshes are refused; frames need the vertical spring).
    /// Throws InputError.
    void finalize(const InputFile &input, const std::string &section, BuildingType type);
    /// Dimension 3, after finalize: check the 3D entries and compute
    /// impedance_3d. Throws InputError.
    void finalize_3d(const InputFile &input, const std::string &section);

    /// The entries as typed, of finalized parameters: the rotary inertias
    /// without the soil's added ones (Wolf's cones).
    FoundationParameters as_typed(bool three_d) const;
    /// On entries as typed (checked): the impedances in use and the rotary
    /// inertias with the soil's added ones, as finalize (and, `three_d`,
    /// finalize_3d) set them. A realization with a random foundation entry
    /// calls it (dynamics/model_parameter.h).
    void recompute_impedance(bool three_d);

  private:
    void compute_planar_impedance(); // impedance; rotary_inertia += the added one
    void compute_impedance_3d();     // impedance_3d; rotary_inertia_x += the added one
  };
} // namespace poundfe

#endif
