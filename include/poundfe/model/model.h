// The structural model: nodes with 3 DOFs (ux, uy, rz), frame members, storey
// links, lumped masses, supports, grouped into buildings placed side by side.
// Plain data: no deal.II headers here, because nearly every file includes it.
#ifndef poundfe_model_model_h
#define poundfe_model_model_h

#include <poundfe/base/point.h>
#include <poundfe/laws/bouc_wen.h>
#include <poundfe/laws/contact_law.h>
#include <poundfe/laws/elastic_springs.h>
#include <poundfe/laws/friction.h>

#include <array>
#include <string>
#include <vector>

namespace poundfe
{
  constexpr unsigned int n_dofs_per_node = 3;

  /// Components of a nodal DOF triple.
  enum class Component : unsigned int
  {
    ux = 0,
    uy = 1,
    rz = 2
  };

  /// Elastic section of a frame member; mass per unit length may be zero.
  struct Section
  {
    double youngs_modulus  = 0;
    double area            = 0;
    double second_moment   = 0;
    double mass_per_length = 0;
  };

  struct Node
  {
    Point2                   position;
    unsigned int             building = 0;
    std::array<bool, 3>      fixed{{false, false, false}};
    /// A hinge node shares the translations (ux, uy) of this node; -1: none.
    int                      tied_to = -1;
  };

  enum class MemberKind
  {
    column,
    beam,
    other
  };

  /// Two-node Euler-Bernoulli beam-column element.
  struct Member
  {
    std::array<unsigned int, 2> nodes{{0, 0}};
    Section                     section;
    unsigned int                building = 0;
    unsigned int                group    = 0;
    MemberKind                  kind     = MemberKind::other;
    /// Whether each end is an end of the whole member (a joint or support)
    /// rather than a node inside a member split into several elements.
    std::array<bool, 2>         at_joint{{true, true}};
    double                      member_length = 0; // whole member
    /// Building and place, e.g. A3_C1.2 (storey 1, column line 2) or
    /// A3_B2.1 (floor 2, bay 1); the pieces of a split member share it.
    std::string                 label;
  };

  /// Shear-building storey: a horizontal spring and dashpot between floors.
  struct StoreyLink
  {
    std::array<unsigned int, 2> nodes{{0, 0}}; // bottom, top
    double                      stiffness = 0;
    double                      damping   = 0;
    unsigned int                building  = 0;
    /// Bouc-Wen storey (stiffness = hysteresis.stiffness) or elastic.
    bool                        hysteretic = false;
    BoucWenParameters           hysteresis;
  };

  /// A rotational Bouc-Wen spring at a member end: between the rotation of
  /// the member-side node (a copy of the joint that shares its translations)
  /// and the joint's rotation (absent when the joint is clamped).
  struct Hinge
  {
    unsigned int      member_node = 0;
    unsigned int      joint_node  = 0;
    unsigned int      member      = 0; // the element that carries the hinge
    unsigned int      building    = 0;
    std::string       label;
    BoucWenParameters law;
  };

  /// A gap element: contact between a node of one building and a node of
  /// its right-hand neighbour (closure = ux_left - ux_right), or between a
  /// node and a rigid barrier (closure = +ux for a barrier on the right,
  /// -ux on the left).
  struct Gap
  {
    std::array<int, 2>          nodes{{-1, -1}}; // left, right; -1: the barrier
    std::array<unsigned int, 2> buildings{{0, 0}};
    double                      level          = 0;
    double                      initial_gap    = 0;
    double                      effective_mass = 0;
    std::string                 label;
  };

  /// Translational mass lumped at a node (acts on ux and uy).
  /// A nonlinear elastic spring between a node's ux and the ground.
  struct Spring
  {
    unsigned int        node     = 0;
    unsigned int        building = 0;
    SpringLawParameters law;
    std::string         label;
  };

  /// A friction element between a node's ux and the ground or a belt.
  struct FrictionSurface
  {
    unsigned int          node     = 0;
    unsigned int          building = 0;
    FrictionLawParameters law; // k_s: set by prepare_analysis when 0 (automatic)
    std::string           label;
  };

  struct NodalMass
  {
    unsigned int node = 0;
    double       mass = 0;
  };

  /// A floor: its level and the nodes on it; the storey below it has height
  /// `storey_height` (from the floor below, or the base).
  struct Floor
  {
    double                    level         = 0;
    double                    storey_height = 0;
    std::vector<unsigned int> nodes;
  };

  enum class BuildingType
  {
    frame,
    mesh,
    shear
  };

  /// How the Rayleigh damping C = a0 M + a1 K of one building is defined.
  struct RayleighDamping
  {
    enum class Kind
    {
      none,
      modes,
      coefficients
    };
    Kind         kind          = Kind::none;
    double       damping_ratio = 0;
    unsigned int first_mode    = 1; // 1-based, as users count modes
    unsigned int second_mode   = 2;
    double       a0            = 0;
    double       a1            = 0;
  };

  struct Building
  {
    std::string        name;
    BuildingType       type = BuildingType::frame;
    unsigned int       first_node = 0;
    unsigned int       n_nodes    = 0; // made by its generator; contact may add more
    double             left  = 0; // horizontal extent, for placement
    double             right = 0;
    double             base_level = 0;
    std::vector<Floor> floors; // bottom to top
    RayleighDamping    damping;
  };

  enum class MassMatrixType
  {
    lumped,
    consistent
  };

  /// p_delta: the geometric stiffness of the gravity loads, linearised and
  /// part of K (assembly/linear_system.h).
  enum class GeometricNonlinearity
  {
    none,
    p_delta
  };

  class Model
  {
  public:
    std::vector<Node>       nodes;
    std::vector<Member>     members;
    std::vector<StoreyLink> links;
    std::vector<Hinge>      hinges;
    std::vector<Gap>        gaps;
    std::vector<Spring>          springs;
    std::vector<FrictionSurface> friction_surfaces;
    /// The contact law of every gap (its gap and m_e are set per gap).
    ContactLawParameters    contact;
    std::vector<NodalMass>  masses;
    std::vector<Building>   buildings;
    MassMatrixType          mass_matrix = MassMatrixType::lumped;
    GeometricNonlinearity   geometric_nonlinearity = GeometricNonlinearity::none;
    double                  gravity                = 9.81; // m/s^2, for P-Delta

    unsigned int n_nodes() const { return nodes.size(); }
    unsigned int n_dofs() const { return n_dofs_per_node * nodes.size(); }

    static unsigned int
    dof(const unsigned int node, const Component c)
    {
      return n_dofs_per_node * node + static_cast<unsigned int>(c);
    }

    /// Number the free DOFs building by building (fixed DOFs get -1). Call
    /// once the supports are set; equations of a building are contiguous.
    void number_equations();

    unsigned int n_equations() const { return n_free; }
    int equation(const unsigned int dof) const { return equation_of_dof[dof]; }
    const std::vector<int> &equations() const { return equation_of_dof; }

    /// Equations [first, last) of building b.
    std::array<unsigned int, 2> equation_range(unsigned int b) const;

    /// Total translational mass of building b in x (from all mass sources).
    double total_mass(unsigned int b) const;

  private:
    std::vector<int>          equation_of_dof;
    std::vector<unsigned int> first_equation_of_building;
    unsigned int              n_free = 0;
  };
} // namespace poundfe

#endif
