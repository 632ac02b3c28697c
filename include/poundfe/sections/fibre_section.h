// A fibre cross-section after OpenSees's FiberSection2d/3d and Spacone,
// Filippou & Taucer (1996): the section is a set of fibres i at (y_i, z_i)
// of area A_i, each with its own copy of a uniaxial stress-strain material.
// With a_i = (1, -y_i) in the plane and (1, -y_i, z_i) in space (y, z
// measured from the reference axis), the fibre strain, the resultants and
// the exact tangent are
//   eps_i = a_i . (eps0, kappa_z[, kappa_y]),
//   s     = sum_i sigma_i A_i a_i,      k_s = sum_i E_t,i A_i a_i a_i^T,
// and in space the torque T = GJ theta is elastic and uncoupled (OpenSees's
// FiberSection3d with -GJ). As OpenSees does unless told -noCentroid, the
// reference axis is the fibres' area centroid. The fibres' states are kept
// by runs of consecutive fibres of one material: a run of Concrete02 or
// Steel02 holds its fibres' states in one array and evaluates them in one
// call, any other material one law per fibre (fibre_section.cc).
#ifndef poundfe_sections_fibre_section_h
#define poundfe_sections_fibre_section_h

#include <poundfe/laws/material_registry.h>
#include <poundfe/sections/section_law.h>

#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  /// What a material is for in a section: the moment-curvature analysis
  /// reports the extreme strains of each kind and the first yield of steel.
  enum class MaterialRole
  {
    concrete,
    steel,
    other
  };

  /// A material of a section: its name there ("core", "Steel"), its law by
  /// the registry's name and parameters, and the strain limits beyond which
  /// a fibre of it has failed (after OpenSees's MinMax material; NaN: none).
  struct SectionMaterial
  {
    std::string        name;
    MaterialParameters law;
    double             min_strain = std::numeric_limits<double>::quiet_NaN(); // crushing (< 0)
    double             max_strain = std::numeric_limits<double>::quiet_NaN(); // rupture (> 0)

    /// Concrete01/02: concrete; Steel01/02, ElasticPP: steel; else other.
    MaterialRole role() const;
  };

  /// One fibre: its centroid (y, z) in the section's axes, its area and the
  /// index of its material in FibreGeometry::materials.
  struct Fibre
  {
    double       y = 0, z = 0, area = 0;
    unsigned int material = 0;
  };

  /// What a section is made of: its materials and fibres (the generators of
  /// fibre_generators.h fill it).
  struct FibreGeometry
  {
    std::vector<SectionMaterial> materials;
    std::vector<Fibre>           fibres;

    /// The index of the material called `name`; InputError (parameter
    /// "Material") if the section has none of that name.
    unsigned int material_index(const std::string &name) const;
    /// Adds the material (its name must be new) and returns its index.
    unsigned int add_material(const SectionMaterial &material);
    /// sum A_i, and the area centroid.
    double area() const;
    double centroid_y() const;
    double centroid_z() const;
  };

  namespace internal
  {
    /// The fibres' states, by runs of one material (fibre_section.cc).
    struct FibreStates;
  } // namespace internal

  class FibreSection : public SectionLaw
  {
  public:
    /// `n_resultants` 2 (plane) or 4 (space, with the torsional rigidity
    /// GJ). Each fibre gets its own material from the registry (InputError
    /// for a material the registry refuses); a section without fibres or
    /// with a fibre of area <= 0 is an InputError (parameter "Fibres").
    FibreSection(const FibreGeometry &geometry, unsigned int n_resultants,
                 double torsional_rigidity = 0, bool about_centroid = true);
    FibreSection(FibreSection &&) noexcept;
    ~FibreSection() override;

    unsigned int         n_resultants() const override { return n; }
    bool                 set_trial(const SectionVector &deformation) override;
    const SectionVector &resultant() const override { return trial.resultant; }
    const SectionMatrix &tangent() const override { return trial.tangent; }
    SectionMatrix        initial_tangent() const override { return virgin_tangent; }
    const SectionVector &deformation() const override { return trial.deformation; }
    void                 commit() override;
    void                 revert() override;
    void                 reset() override;
    std::unique_ptr<SectionLaw> clone() const override;
    /// The fibre that refused its strain: index, (y, z), material and the
    /// law's reason.
    std::string failure() const override;

    const FibreGeometry &geometry() const { return *fibres; }
    /// The reference axis (y, z) the fibre strains are measured from.
    double reference_y() const { return y_ref; }
    double reference_z() const { return z_ref; }
    /// The trial strain and stress of fibre i.
    double fibre_strain(unsigned int i) const;
    double fibre_stress(unsigned int i) const;
    /// The law of fibre i's material, for its constants (initial stiffness,
    /// yield strain): its state is not the fibre's.
    const UniaxialLaw &fibre_material(unsigned int i) const;

  private:
    struct State
    {
      SectionVector deformation, resultant;
      SectionMatrix tangent;
    };
    FibreSection(std::shared_ptr<const FibreGeometry> geometry, unsigned int n_resultants,
                 double torsional_rigidity, double y_ref, double z_ref);
    /// a_i . e of fibre i.
    double strain_at(unsigned int i, const SectionVector &e) const;

    std::shared_ptr<const FibreGeometry>      fibres; // shared by the clones
    unsigned int                              n;
    double                                    torsional_rigidity;
    double                                    y_ref = 0, z_ref = 0;
    std::unique_ptr<internal::FibreStates>    states;
    State                                     trial, committed;
    SectionMatrix                             virgin_tangent;
    unsigned int                              failed_fibre = 0;
  };
} // namespace poundfe

#endif
