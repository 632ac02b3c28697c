// Numeric parameters of a built model, named by the path of the input entry
// they come from, and a realization of the model in which some of them take
// sampled values (issue 24: uncertain structures).
//   A path is an entry of the parameter file, optionally with a 1-based
//   entry of a list in brackets:
//     Building b/Storey stiffnesses[i]   k of storey i          (K; C through Rayleigh)
//     Building b/Storey damping[i]       storey dashpot c       (C)
//     Building b/Storey yield drifts[i]  Bouc-Wen u_y of storey i (nonlinear element)
//     Building b/Floor masses[i]         mass of floor i, in equal shares at its joints
//                                        (M; K_G under P-Delta; modes, Rayleigh and modal
//                                        C; the gaps' effective masses m1 m2/(m1 + m2))
//     Building b/Hinges/Yield moment     M_y of every hinge of b: u_y = M_y / k (nonlinear)
//     Building b/Damping/Damping ratio   zeta of b's Rayleigh damping (C)
//     Model/Separations[i]               gap between buildings i and i+1 (nonlinear)
//     Contact/Barriers/gap[i]            the gap of barrier i (nonlinear; a bumper
//                                        no thicker)
//     Contact/Stiffness, Contact/Damping the contact law of every gap (nonlinear)
//     Friction/Static coefficient, Friction/Kinetic coefficient (nonlinear)
//     Links/LIST/FIELD[i]                FIELD of entry i of the Links entry LIST
//                                        (nonlinear): Viscous dampers/c, alpha;
//                                        Kelvin-Voigt links/k, c, alpha; Maxwell
//                                        links/k, c; Elastic-plastic links/k, Fy, r;
//                                        Soil coupling/k, c; Rocking soil coupling/k,
//                                        c. Links/Viscous dampers[i] is .../c[i] (0:
//                                        a damper without force, as the mitigation
//                                        study's bare case of a damper size)
//     Springs/SD springs/K[i], L[i], H[i], Springs/Cubic springs/k1[i], k3[i]
//                                        of spring i of that entry (K, k1: the
//                                        linear K; the rest: the element; a friction
//                                        element's N from the SD spring follows)
//     Bumpers/Stiffness, Bumpers/Thickness
//                                        the bumper of every gap (nonlinear; t at
//                                        most the smallest gap)
//     Building b/Column E[i], Column A[i], Column I[i], Column mass per length[i]
//                                        section of the columns of storey i of a
//                                        generated frame (K; M, K_G for the mass;
//                                        E, I: the k = f 6 E I / L of their hinges)
//     Building b/Beam E[i], Beam A[i], Beam I[i], Beam mass per length[i]
//                                        the same for the beams of floor i
//     Building b/Hinges/Stiffness, Building b/Hinges/Stiffness factor
//                                        k of every hinge of b (K), as the builder
//                                        sets it (u_y = M_y / k follows)
//     Building b/Hinges/Yield rotation   u_y of b's hinges without a yield moment
//     Building b/Bouc-Wen/P              P = alpha, A, beta, gamma, n, delta A,
//                                        delta nu, delta eta of every hinge (2D; 3D:
//                                        both bending axes, uniaxial or biaxial) and
//                                        hysteretic storey or resisting plane of b
//                                        (nonlinear; a bidirectional law: n >= 2, no
//                                        degradation)
//     Building b/Damping/a0, a1          given Rayleigh coefficients (C)
//     Building b/Damping/Modal ratios[i] zeta of mode i, modal damping (C)
//     Building b/Column E|G|A|I|Iz|J|Avy|Avz|mass per length[i], Building
//     b/Beam ...[i]                      the same for a 3D frame (Model/Dimension = 3;
//                                        I is Iy; k = f 6 E I_y|z / L of its hinges)
//     Building b/Group E|A|I|mass per length[i]
//                                        group i (Group ids order) of a 2D mesh building
//     Building b/Group E|G|A|I|Iz|J|mass per length[i]
//                                        the same of a 3D mesh building (I is Iy; its
//                                        hinges' k = f 6 E I_y|z / L follows)
//     Building b/Storey stiffnesses[i], Storey yield drifts[i] of a 3D shear
//                                        building: k/2 and u_y of each of the default
//                                        four planes of storey i (K; nonlinear)
//     Building b/Plan/Resisting planes/k[i], u_y[i]
//                                        k, u_y of typed plane i of a 3D shear
//                                        building, in every storey (K; nonlinear)
//     Building b/Plan/Polar moments[i]   the typed polar moment of floor i of a 3D
//                                        building with rigid slabs (M; the modes,
//                                        Rayleigh and modal C, K_G under P-Delta)
//     Building b/Floor masses[i] of a 3D building: the floor's translational
//                                        masses and, when Plan/Polar moments is not
//                                        given, its polar moment J = m (L_x^2 + L_y^2)/12
//                                        (the same share of m as before)
//     Building b/Foundation/ENTRY        the soil (Shear-wave velocity, Soil density,
//                                        Poisson ratio), size (Length, Width, Embedment),
//                                        typed springs and dashpots, Mass and inertias
//                                        of b's compliant foundation: its parts as the
//                                        builder sets them (K, M; dashpots: nonlinear)
//     Contact/Coefficient of restitution the contact damping as the builder fits it
//                                        (formula or calibration; nonlinear)
//     Friction/Stribeck velocity, Belt velocity, Normal force, Normal force per
//     displacement|velocity|velocity cubed, Stick stiffness, Regularization velocity
//                                        of every friction element (nonlinear; a
//                                        stick dashpot 2 sqrt(k_s M_ii) follows k_s and M)
//   Without [i], a list entry takes the one value on every storey.
//   Refused: entries that place nodes or number equations (heights, bay
//   widths, counts, set-backs, plan dimensions, positions, angles).
// A realization writes the sampled values into a working copy of the built
// Analysis (never the file, never the model builder). Only when a value
// enters the linear part (K, C) are M, K (and, for Rayleigh damping fitted at
// modes, the building's modes) and C assembled again; a value that enters a
// nonlinear element only leaves M, K, C and their factorisations as they are.
#ifndef poundfe_dynamics_model_parameter_h
#define poundfe_dynamics_model_parameter_h

#include <poundfe/dynamics/analysis.h>
#include <poundfe/model/contact_parameters.h>
#include <poundfe/model/parameters.h>

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  /// The input sections a model was built from, for the parameters whose
  /// value the builder turns into others: the mesh groups' ids, whether a
  /// floor's polar moment was typed, a foundation's entries as typed, how
  /// the contact damping comes from the restitution.
  struct ModelInputs
  {
    ModelParameters   model;
    ContactParameters contact;
  };

  /// How the model builder set a hinge's k and u_y (model.hinges order):
  /// k = factor 6 E I / L of its member (else given), u_y = M_y / k (else
  /// the yield rotation given). A sampled E, I, k or M_y sets them again as
  /// the builder would.
  struct HingeOrigin
  {
    bool stiffness_from_section = false;
    bool yield_from_moment      = false;
  };

  /// The origins of the model's hinges, from the input it was built from:
  /// those of model.hinges, then those of model.hinges_3d.
  std::vector<HingeOrigin> hinge_origins(const Model &model, const ModelParameters &input);

  struct ModelParameter
  {
    enum class Kind
    {
      storey_stiffness,
      storey_damping,
      storey_yield_drift,
      floor_mass,
      hinge_yield_moment,
      damping_ratio,
      separation,
      contact_stiffness,
      contact_damping,
      static_friction,
      kinetic_friction,
      link_entry,        // `link_field` of the Links entry `list`
      member_section,   // `section` of the columns or beams (`member_kind`) of a frame
      hinge_stiffness,
      hinge_stiffness_factor,
      hinge_yield_rotation,
      bouc_wen_shape,   // `shape` of b's hinges and hysteretic storeys
      rayleigh_a0,
      rayleigh_a1,
      modal_ratio,
      member_section_3d, // `section_3d` of a 3D frame's columns or beams
      friction_entry,    // `friction` of every friction element
      contact_restitution,
      foundation_entry,  // `foundation` of building b's compliant foundation
      polar_moment,      // the typed polar moment of a 3D building's floor(s)
      spring_entry,      // `spring_field` of the Springs entry `list`
      bumper_entry,      // `bumper_field` of the bumper of every gap
      resisting_plane,   // k (or u_y: `plane_yield_drift`) of a 3D shear building's typed plane(s)
      barrier_gap        // the gap of Contact/Barriers entry `entry` (all: -1)
    };
    Kind         kind     = Kind::storey_stiffness;
    std::string  path;          // as written
    unsigned int building = 0;  // 0-based (storey, floor, hinge, damping: the building; separation: the left one)
    int          entry    = -1; // 0-based storey or floor (link_entry, spring_entry: the list's entry; modal_ratio: mode; resisting_plane: plane; barrier_gap: barrier); -1: all
    MemberKind               member_kind = MemberKind::column; // member_section
    double Section::*        section     = nullptr;            // member_section
    double BoucWenParameters::*shape     = nullptr;            // bouc_wen_shape
    /// bouc_wen_shape: the building's law is bidirectional (n >= 2)
    bool                       bidirectional = false;
    double Section3D::*        section_3d = nullptr;           // member_section_3d
    /// member_section of a mesh building: the members of physical group
    /// `group` (-1: a generated frame's columns or beams)
    int                        group      = -1;
    /// The entry of a friction law or of a foundation's input.
    double &(*friction)(FrictionLawParameters &)  = nullptr;
    double &(*foundation)(FoundationParameters &) = nullptr;
    /// foundation_entry: whether it enters K or M (else only the dashpots).
    bool                       foundation_matrices = false;
    /// link_entry, spring_entry: the entry of the input whose list it is
    /// ("Links/Maxwell links", "Springs/SD springs") and the law's field.
    std::string                   list;
    double LinkLawParameters::*   link_field   = nullptr;
    double SpringLawParameters::* spring_field = nullptr;
    double BumperParameters::*    bumper_field = nullptr; // bumper_entry
    /// resisting_plane: the plane's u_y (else its k); `entry` is the plane.
    bool                          plane_yield_drift = false;
    /// The sections the model was built from (needed by the mesh sections,
    /// 3D floor masses, foundations and restitution).
    std::shared_ptr<const ModelInputs> inputs;
    /// The hinges' origins (shared by the parameters of one realization;
    /// settle_hinge_origins); needed by the section and hinge kinds.
    std::shared_ptr<const std::vector<HingeOrigin>> hinges;

    /// The values the parameter can take: [lower, upper] (lower excluded
    /// when !lower_included, upper when !upper_included).
    struct Range
    {
      double lower          = 0;
      bool   lower_included = false;
      double upper          = std::numeric_limits<double>::infinity();
      bool   upper_included = true;
    };
    Range range() const;

    /// Whether the value enters M, K or C (else only nonlinear elements).
    bool enters_linear_part() const;
    /// Whether it enters M or K (the modes change), or M alone.
    bool enters_matrices() const;
    bool enters_mass() const;
    /// Whether 0 is a value it can take (a damping, gap or friction
    /// coefficient); otherwise only values > 0 are (a stiffness, yield
    /// drift or moment, damping ratio). Negative values never are, except
    /// for the Bouc-Wen beta and gamma (range()).
    bool can_be_zero() const;
  };

  /// The parameter `path` names in `model`. Throws std::invalid_argument
  /// saying what is wrong: no such entry, an entry that is not a number
  /// poundfe can vary (with the list of those it can), a building or storey
  /// out of range, a storey that is not hysteretic, no gaps, no hinges, ...
  /// `hinges` (hinge_origins) lets it refuse a Hinges/Stiffness factor or
  /// Yield rotation that no hinge of the building uses.
  /// `inputs` (the sections the model was built from) is needed by the
  /// paths that say so.
  ModelParameter model_parameter(const std::string &path, const Model &model,
                                 std::shared_ptr<const std::vector<HingeOrigin>> hinges = {},
                                 std::shared_ptr<const ModelInputs>              inputs = {});

  /// Gives every parameter the hinges' origins as they are once the
  /// parameters are sampled: a random Hinges/Stiffness makes k given, a
  /// random Hinges/Yield moment makes u_y = M_y / k (as the file with the
  /// sampled value would).
  void settle_hinge_origins(std::vector<ModelParameter> &parameters,
                            std::vector<HingeOrigin> origins, const Model &model);

  /// The value the built model has for `parameter` (its first storey, hinge
  /// or gap when it names several).
  double model_parameter_value(const ModelParameter &parameter, const Model &model);

  /// The built model with some parameters sampled: owns a working copy of
  /// the analysis the time history of a realization runs on.
  class ModelRealization
  {
  public:
    /// `eigensolver` recomputes a building's modes when its K changes and
    /// its Rayleigh damping is fitted at modes.
    ModelRealization(const Analysis &base, std::vector<ModelParameter> parameters,
                     Eigensolver eigensolver);

    const std::vector<ModelParameter> &parameters() const { return targets; }
    /// The analysis with the values last applied (the base's before any).
    const Analysis &analysis() const { return working; }
    /// Whether any parameter enters the linear part.
    bool changes_linear_part() const { return linear; }

    /// Writes values[p] into parameter p; assembles M, K, C again when a
    /// parameter enters them. Throws std::invalid_argument for a value the
    /// model cannot take (a stiffness, yield drift, mass or ratio <= 0, a
    /// negative damping or gap, a bumper thicker than a gap) naming the
    /// parameter, and NumericalError when
    /// the sampled K has no modes (a mechanism).
    void apply(const std::vector<double> &values);

  private:
    void assemble_linear_part(bool matrices_changed);
    /// Building b's foundation record from its entries as sampled, as the
    /// builder makes it (FoundationParameters::recompute_impedance,
    /// planar_foundation, plan_foundation).
    void map_foundation(unsigned int b);

    Analysis                    working;
    /// The input sections the parameters write into before the builder's
    /// formulas map them (foundations as typed, the contact's restitution).
    ModelInputs                 inputs;
    bool                        has_inputs = false;
    std::vector<ModelParameter> targets;
    Eigensolver                 eigensolver;
    bool                        linear = false;
  };
} // namespace poundfe

#endif
