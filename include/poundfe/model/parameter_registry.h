// The numbers of a built model that a realization, a sweep or Python may
// change, each registered by the model part that declares it (as OpenSees's
// setParameter/updateParameter): its path in the parameter file, how to
// find it in a built Model (resolve: the checks and indices), get, set, the
// matrices it enters (M, K, C, or nonlinear elements only), the values it
// can take and what must follow once every value is written (a contact
// damping fitted again, a foundation's impedances, a check of two values
// together).
//   A path is an entry of the parameter file, optionally with a 1-based
//   entry of a list in brackets, e.g. "Building 2/Storey stiffnesses[3]";
//   without [i], a list entry takes the one value on every storey. The
//   registered paths are listed by ParameterRegistry::known_paths() (the
//   parts: source/model/*_registration.cc; dynamics/model_parameter.h says
//   what each does to the model). Refused: entries that place nodes or
//   number equations (heights, bay widths, counts, set-backs, plan
//   dimensions, positions, angles).
// A value is written where the model builder (model/model_builder.cc) put
// the entry's value, so a model with a value set equals the model built
// from a file with that value (tests/dynamics/test_model_parameters.cc).
#ifndef poundfe_model_parameter_registry_h
#define poundfe_model_parameter_registry_h

#include <poundfe/model/contact_parameters.h>
#include <poundfe/model/model.h>
#include <poundfe/model/parameters.h>

#include <deque>
#include <functional>
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
  /// the yield rotation given). A set E, I, k or M_y sets them again as
  /// the builder would.
  struct HingeOrigin
  {
    bool stiffness_from_section = false;
    bool yield_from_moment      = false;
  };

  /// The origins of the model's hinges, from the input it was built from:
  /// those of model.hinges, then those of model.hinges_3d.
  std::vector<HingeOrigin> hinge_origins(const Model &model, const ModelParameters &input);

  struct ParameterRegistration;

  /// A registered parameter found in a built model: its registration and
  /// the indices and shared inputs that say which of the model's values it is.
  struct ModelParameter
  {
    /// The values the parameter can take: [lower, upper] (lower excluded
    /// when !lower_included, upper when !upper_included).
    struct Range
    {
      double lower          = 0;
      bool   lower_included = false;
      double upper          = std::numeric_limits<double>::infinity();
      bool   upper_included = true;
    };
    /// What a value enters (a bit set; none: nonlinear elements only).
    enum Touches : unsigned int
    {
      nonlinear_only = 0,
      mass           = 1,
      stiffness      = 2,
      damping        = 4
    };

    std::string                  path; // as written
    const ParameterRegistration *registration = nullptr;
    /// 0-based building (Model/Separations: the left one)
    unsigned int building = 0;
    /// 0-based storey, floor, list entry, mode, plane or barrier; -1: all
    int entry = -1;
    /// A resolved index besides the entry: a mesh group's id (-1: all).
    int group = -1;
    /// Which of its registration's forms the model has (a 3D section, a
    /// bidirectional Bouc-Wen law, ...; the registration says).
    int          variant = 0;
    Range        value_range;
    unsigned int touches = nonlinear_only;
    /// The sections the model was built from (the paths that say so).
    std::shared_ptr<const ModelInputs> inputs;
    /// The hinges' origins (shared by the parameters of one realization;
    /// settle_hinge_origins); needed by the section and hinge parameters.
    std::shared_ptr<const std::vector<HingeOrigin>> hinges;

    Range range() const { return value_range; }
    /// Whether the value enters M, K or C (else only nonlinear elements).
    bool enters_linear_part() const { return touches != nonlinear_only; }
    /// Whether it enters M or K (the modes change), or M alone.
    bool enters_matrices() const { return (touches & (mass | stiffness)) != 0; }
    bool enters_mass() const { return (touches & mass) != 0; }
    /// Whether 0 is a value it can take (range()).
    bool can_be_zero() const;

    /// The value the model has (its first storey, hinge or gap when it
    /// names several).
    double value(const Model &model) const;
    /// Writes `value` into `model` (or, for a value the builder maps, into
    /// `inputs`, the working copy of the input sections: follow_up() maps
    /// it). Throws std::invalid_argument for a value out of range().
    void set(double value, Model &model, ModelInputs &inputs) const;
    /// Whether set() makes the model the builder makes from a file with the
    /// value, to the last bit (a sweep then sets it in one built model
    /// instead of reading and building each value's input).
    bool set_as_built(const Model &model) const;
    /// Whether it writes every value of the model that `earlier` writes
    /// (parameters act in their order): the same registration, building and
    /// form, on the same storey (member, entry) or, this one, on every one.
    /// A whole list followed by one of its entries is not: both act, the
    /// entry overriding the list there.
    bool overwrites(const ModelParameter &earlier) const;
  };

  /// What must follow once every parameter is written (`inputs`: the working
  /// copy of the input sections, nullptr when none was given).
  using ParameterFollowUp = void (*)(const ModelParameter &, Model &, const ModelInputs *);

  /// One parameter a model part registers.
  struct ParameterRegistration
  {
    /// The entry, without "Building b/" (of_building) and without [i].
    std::string name;
    bool        of_building = false;
    /// Whether it takes [i] (a list entry); if not, whether "[i]" is
    /// refused before resolve (else after it: what is missing first).
    bool takes_index       = false;
    bool index_refused_first = true;
    /// The known-paths list names the first of a family in full and the
    /// others by `label`; an unlisted registration is not named.
    std::string family, label;
    bool        listed = true;
    ModelParameter::Range range;
    unsigned int          touches = ModelParameter::nonlinear_only;
    /// The checks against the model (std::invalid_argument) and the
    /// indices; may narrow range and touches. May be empty.
    std::function<void(ModelParameter &, const Model &)> resolve;
    std::function<double(const ModelParameter &, const Model &)> get;
    std::function<void(const ModelParameter &, double, Model &, ModelInputs &)> set;
    ParameterFollowUp follow_up = nullptr;
    /// Whether set() gives the built model bit for bit (set_as_built);
    /// empty: when the value enters nonlinear elements only (M, K, C as
    /// built), not when the builder derives more from it (positions,
    /// factors, ratios) or the value enters M, K or C (assembled again).
    std::function<bool(const ModelParameter &, const Model &)> built_alike;
    /// Its effect on the hinges' origins once sampled (settle_hinge_origins).
    std::function<void(const ModelParameter &, std::vector<HingeOrigin> &, const Model &)> settle;

    /// "Building b/NAME[i]" as the known-paths list writes it.
    std::string pattern() const;
  };

  /// Every model part's registrations, with the explanations of paths that
  /// are no parameter (the geometry, a list without its field, ...).
  class ParameterRegistry
  {
  public:
    using Explanation = std::function<void(const ModelParameter &, const std::string &entry,
                                           bool of_building, bool indexed, const Model &)>;
    void add(ParameterRegistration registration);
    /// `explain` throws std::invalid_argument for a path it recognises.
    void add_explanation(Explanation explain);
    /// A path read as another ("Links/Viscous dampers": its c).
    void add_alias(const std::string &name, const std::string &same_as);

    const ParameterRegistration *find(const std::string &name, bool of_building) const;
    /// Throws the first explanation of an unregistered path, else that it
    /// is not a parameter.
    [[noreturn]] void refuse(const ModelParameter &p, const std::string &entry,
                             bool of_building, bool indexed, const Model &model) const;
    std::string resolve_alias(const std::string &name) const;
    /// The known paths, for messages: each family once.
    std::string known_paths() const;
    const std::deque<ParameterRegistration> &registrations() const { return entries; }

  private:
    std::deque<ParameterRegistration>                entries;
    std::vector<Explanation>                         explanations;
    std::vector<std::pair<std::string, std::string>> aliases;
  };

  /// The registry of every model part, made once.
  const ParameterRegistry &parameter_registry();

  /// std::invalid_argument: `p` is not a parameter poundfe can vary (with
  /// the known paths).
  [[noreturn]] void refuse_unknown_parameter(const ModelParameter &p);

  // The parts' registration functions (source/model/*_registration.cc),
  // called in this order by parameter_registry(): a new part is one file and
  // one line of its list.
  void register_storey_parameters(ParameterRegistry &registry);   // storeys, 3D planes
  void register_floor_parameters(ParameterRegistry &registry);    // floor masses, polar moments
  void register_damping_parameters(ParameterRegistry &registry);  // Rayleigh, modal
  void register_hinge_parameters(ParameterRegistry &registry);    // hinges, Bouc-Wen
  void register_section_parameters(ParameterRegistry &registry);  // frames 2D/3D, mesh groups
  void register_contact_parameters(ParameterRegistry &registry);  // gaps, barriers, contact, bumpers
  void register_device_parameters(ParameterRegistry &registry);   // friction, links, springs
  void register_foundation_parameters(ParameterRegistry &registry);

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

  /// The value the built model has for `parameter` (ModelParameter::value).
  double model_parameter_value(const ModelParameter &parameter, const Model &model);

  // Shared by the parts' registrations.

  /// The building of hinge h in the order of HingeOrigin: model.hinges,
  /// then model.hinges_3d.
  unsigned int hinge_building(const Model &model, unsigned int h);
  /// Sets a hinge's k and, for a hinge whose u_y comes from its yield
  /// moment, u_y = M_y / k with M_y = k u_y before (the builder's M_y to
  /// rounding).
  void set_hinge_stiffness(BoucWenParameters &law, const HingeOrigin &origin, double stiffness);
  /// 6 E I / L of the member that carries a hinge (k / factor in the
  /// builder; 3D: I about the hinge's axis).
  double section_stiffness(const Model &model, const Hinge &hinge);
  double section_stiffness_3d(const Model &model, const Hinge3D &hinge);
  /// The contact damping fitted again to the contact as set (the builder's
  /// formula or calibration), when it comes from the restitution.
  void refit_contact_damping(const ModelParameter &, Model &model, const ModelInputs *inputs);
  /// std::invalid_argument "'PATH'`what`" (`what` goes on: ": building 'A' has ...").
  [[noreturn]] void refuse_parameter(const ModelParameter &p, const std::string &what);
} // namespace poundfe

#endif
