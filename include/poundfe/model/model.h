// The structural model: nodes with 3 DOFs (ux, uy, rz), frame members, storey
// links, lumped masses, supports, grouped into buildings placed side by side.
// Dimension 3 (torsionally coupled shear buildings, doc/theory.md §1.12): a
// floor node's DOFs are the plan motion (ux, uy, θz) of its rigid diaphragm at
// the mass centre; the node's position is (x of the mass centre, level), and
// the plan (mass centres, slab outlines) is in Building::plan.
// Plain data: no deal.II headers here, because nearly every file includes it.
#ifndef poundfe_model_model_h
#define poundfe_model_model_h

#include <poundfe/base/point.h>
#include <poundfe/laws/bouc_wen.h>
#include <poundfe/laws/bumper.h>
#include <poundfe/laws/contact_law.h>
#include <poundfe/laws/elastic_springs.h>
#include <poundfe/laws/friction.h>
#include <poundfe/laws/link_laws.h>
#include <poundfe/sections/section_law.h>

#include <algorithm>
#include <array>
#include <memory>
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

  /// Elastic section of a member in space (elements/frame_element_3d.h). A
  /// shear area of 0 means no shear deformation in that plane.
  struct Section3D
  {
    double youngs_modulus   = 0;
    double shear_modulus    = 0;
    double area             = 0;
    double second_moment_y  = 0; // Iy: bending in the local x-z plane
    double second_moment_z  = 0; // Iz: bending in the local x-y plane
    double torsion_constant = 0; // J (Saint-Venant)
    double shear_area_y     = 0; // Avy: shear along local y
    double shear_area_z     = 0; // Avz: shear along local z
    double mass_per_length  = 0;
  };

  struct Node
  {
    Point2                   position;
    /// A node of a 3D frame whose three DOFs are not (ux, uy, rz): the
    /// joint's (uz, rx, ry), or a hinge's two relative rotations (model/
    /// frame_building_3d.h). The ground's influence skips it.
    bool                     generalized = false;
    /// A generalized node that is a 3D frame joint's (uz, rx, ry): its
    /// slot 0 is a vertical translation (the vertical ground motion's
    /// influence), unlike a hinge's or a foundation's rotations.
    bool                     joint_translation_z = false;
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

  /// How a member of a fibre building (Building <i>/Member model = fibre)
  /// is made: a beam-column (elements/beam_column.h) on the plane section
  /// Model::section_laws[section] at each integration point; section < 0:
  /// the elastic frame element of Member::section.
  struct FibreMember
  {
    int          section     = -1;
    bool         force_based = true; // else displacement-based
    unsigned int n_points    = 5;    // Gauss-Lobatto (force), Gauss-Legendre (displacement)
    bool         p_delta     = false; // PDelta transformation, else Linear

    bool fibre() const { return section >= 0; }
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
    /// A fibre member: `section` then holds the initial rigidities of its
    /// fibre section (E = 1, A = EA, I = EI) and its mass per length.
    FibreMember                 fibre;
    /// Its self-weight as a uniform load along it, downwards (N/m; Building
    /// <i>/Member self-weight = distributed): in the gravity analysis, an
    /// element load of a fibre member, the consistent nodal loads of an
    /// elastic one; its mass's weight then does not load its nodes. 0: none.
    double                      weight_per_length = 0;
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
    /// On a compliant foundation: the base node whose rotation θ rocks the
    /// storey, d = ux(top) - ux(bottom) - rocking_arm θ (-1: fixed base, d =
    /// ux(top) - ux(bottom)); rocking_arm is the storey height.
    int                         rocking_node = -1;
    double                      rocking_arm  = 0;
  };

  /// One spring-dashpot of a foundation to the ground, with the inertia on
  /// the same motion: on the deformation d = Σ coefficients[i] q(dofs[i])
  /// it adds k a aᵀ to K, m a aᵀ to M and a Kelvin-Voigt element (k, c).
  struct FoundationPart
  {
    std::vector<unsigned int> dofs;
    std::vector<double>       coefficients;
    double                    stiffness = 0, damping = 0, inertia = 0;
    std::string               name; // appended to the building's name
  };

  /// A compliant foundation (doc/theory.md §1.16). 2D shear building: the
  /// base node's ux (sway u_0) and rz (rocking θ). 3D shear building: the
  /// base node's (ux, uy, θz) about the foundation's centre and
  /// `rocking_node`'s rotations (rx, ry) (a generalized node, slots 1 and 2;
  /// its uz is fixed). `parts`: the springs, dashpots and inertias on them.
  struct Foundation
  {
    unsigned int node     = 0;
    int          rocking_node = -1; // 3D only
    unsigned int building = 0;
    /// In the plane (2D), along the foundation's local x (3D): what the
    /// report and ASCE 7's period formula quote.
    double       horizontal_stiffness = 0, rocking_stiffness = 0; // N/m, N m/rad
    double       horizontal_damping = 0, rocking_damping = 0;     // N s/m, N m s/rad
    double       mass = 0, rotary_inertia = 0;                    // kg, kg m²
    std::vector<FoundationPart> parts;
  };

  /// An exact master-slave constraint (Cook, Malkus, Plesha & Witt 2002,
  /// §9.2, by transformation; no penalty): q(dof) = Σ c q(master) over
  /// `masters`. A slave with one master of coefficient 1 shares the master's
  /// equation; any other has none, and whatever acts on it acts on its
  /// masters (Model::equation_terms). The column bases of a 2D frame on a
  /// rigid foundation (model/frame_foundation.h).
  struct DofConstraint
  {
    unsigned int                                 dof = 0;
    std::vector<std::pair<unsigned int, double>> masters;
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

  /// A 3D beam-column of a frame building (Dimension 3; elements/
  /// frame_element_3d.h): its 12 end DOFs (ux, uy, uz, rx, ry, rz per end,
  /// site axes) are u_e = T q over the model DOFs `dofs`, T (12 x
  /// dofs.size(), row-major in `map`) the exact master-slave reduction of
  /// the rigid floor diaphragm and the hinge rotations; the ground is 0.
  struct Member3D
  {
    std::array<std::array<double, 3>, 2> ends{};        // (x, y, z), site
    std::array<double, 3>                orientation{}; // v_xz, in the local x-z plane
    Section3D                            section;
    unsigned int                         building = 0;
    /// Columns of storey i: 2i - 1, beams of floor i: 2i (as 2D frames').
    unsigned int                         group    = 0;
    MemberKind                           kind     = MemberKind::other;
    std::string                          label;
    std::vector<unsigned int>            dofs;
    std::vector<double>                  map;
    /// A fibre member: `section` then holds the initial rigidities of its
    /// fibre section (E = G = 1, A = EA, Iz = EIz, Iy = EIy, J = GJ, no
    /// shear areas) and its mass per length.
    FibreMember                          fibre;
    /// Its self-weight along it, along -z (N/m), as Member's.
    double                               weight_per_length = 0;
  };

  /// A Bouc-Wen hinge of a 3D member end about one local bending axis: its
  /// deformation is the relative rotation, DOF `slot` of `node` (a
  /// generalized node); torsion and axial stay elastic.
  struct Hinge3D
  {
    unsigned int      node     = 0;
    unsigned int      slot     = 0; // 0: about the local y axis, 1: about z
    unsigned int      building = 0;
    unsigned int      member   = 0; // in Model::members_3d: the member it ends
    /// Hinges/Biaxial interaction: the hinges of slots 0 and 1 of `node`
    /// share one bidirectional Bouc-Wen element (laws/bidirectional_bouc_wen.h).
    bool              biaxial  = false;
    std::string       label;
    BoucWenParameters law;
  };

  /// A mass on one DOF (3D frames: a joint's vertical translation).
  struct DofMass
  {
    unsigned int dof  = 0;
    double       mass = 0;
    /// false: the mass's weight alone (a gravity load on the DOF), no
    /// inertia in M (a 3D floor's Vertical floor mass = none)
    bool inertia = true;
  };

  /// Two facing slab edges in plan, at rest, site coordinates: the edge of
  /// each floor (ends counter-clockwise along its own outline), each floor's
  /// mass centre, and which end of the edges' overlap the gap watches (0:
  /// the end at the start of the second floor's edge, 1: at its end).
  struct PlanContactGeometry
  {
    std::array<std::array<Point2, 2>, 2> edges;
    std::array<Point2, 2>                centres;
    unsigned int                         end = 0;
  };

  /// A slab edge against a column of a 3D frame between its floors (the
  /// slab of another building at a level the column's building has no
  /// floor at; model/column_contact_geometry.h): the slab's edge at rest
  /// (ends counter-clockwise along its outline) and mass centre, the
  /// column's axis in plan at rest, and the plan displacement of the column
  /// at the slab's height, w = W u over the model DOFs `column_dofs` (W the
  /// column's cubic Hermite shape functions times its member map, 2 x n,
  /// row-major in `weights`).
  struct ColumnContactGeometry
  {
    std::array<Point2, 2>     edge;
    Point2                    slab_centre;
    Point2                    column_point;
    std::vector<unsigned int> column_dofs;
    std::vector<double>       weights;
    std::string               column; // the column member's label
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
    /// Dimension 3: contact between the slab outlines of the two floors in
    /// plan (elements/plan_contact.h); nodes are the two floors' nodes.
    bool                        in_plan = false;
    PlanContactGeometry         plan;
    /// Dimension 3: contact between the slab of nodes[1]'s floor and a
    /// column of buildings[0] (in_plan is false; nodes[0] is the node of the
    /// column's building's floor at the column's top).
    bool                        on_column = false;
    ColumnContactGeometry       column;
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
    /// k_s was 0 in the input: 1e4 K_ii, set again when K changes (fit_stick_laws).
    bool                  automatic_stick_stiffness = false;
  };

  /// A link (damper, connector) between two floor nodes, usually of two
  /// adjacent buildings, on d = ux(nodes[0]) - ux(nodes[1]); a rocking
  /// soil coupling acts on rz instead (slot 2 of a generalized node: θ_y
  /// of a 3D foundation's rocking node).
  struct BuildingLink
  {
    std::array<unsigned int, 2> nodes{{0, 0}};
    Component                   component = Component::ux;
    std::array<unsigned int, 2> buildings{{0, 0}};
    LinkLawParameters           law;
    std::string                 label;
    /// The `Links` entry it comes from ("Links/Kelvin-Voigt links", "Links/Soil
    /// coupling", ...): a soil coupling's law is a Kelvin-Voigt one too, and a
    /// random parameter names a link by its entry (dynamics/model_parameter.h).
    std::string                 entry;
  };

  struct NodalMass
  {
    unsigned int node = 0;
    double       mass = 0;
    /// Polar moment of inertia on rz (3D floors: about the mass centre), kg m².
    double       polar_moment = 0;
  };

  /// A lateral-resisting plane of one storey of a 3D shear building: a
  /// spring on the deformation d = coefficients · (q_bottom, q_top), q =
  /// (ux, uy, θz) of the floors (the bottom one the ground for storey 1).
  struct PlaneLink
  {
    std::array<unsigned int, 2> nodes{{0, 0}}; // bottom, top
    std::array<double, 6>       coefficients{{0, 0, 0, 0, 0, 0}};
    double                      stiffness = 0;
    unsigned int                building  = 0;
    unsigned int                storey    = 1; // 1-based
    unsigned int                plane     = 1; // 1-based, as listed
    bool                        hysteretic = false; // Bouc-Wen (stiffness = hysteresis.stiffness)
    BoucWenParameters           hysteresis;
    /// On a compliant foundation: its rotations (rx, ry) (slots 1, 2 of the
    /// generalized node rocking_node) enter d with rocking_coefficients =
    /// (h d_y, -h d_x), h the storey height (-1: fixed base).
    int                         rocking_node = -1;
    std::array<double, 2>       rocking_coefficients{{0, 0}};
    /// Plan/Storey law = bidirectional Bouc-Wen: the plane of the same storey
    /// (index into Model::plane_links) that shares this plane's bidirectional
    /// element (one element per pair, made at the lower index); -1: none.
    int                         partner = -1;

    /// The DOFs and coefficients of d: (q_bottom, q_top) and the rocking.
    void terms(std::vector<unsigned int> &dofs, std::vector<double> &weights) const;
  };

  /// One floor of a 3D building in plan (site coordinates, at rest).
  struct PlanFloor
  {
    Point2              mass_centre;
    std::vector<Point2> outline; // the slab's corners, counter-clockwise
  };

  /// A floor: its level and the nodes on it; the storey below it has height
  /// `storey_height` (from the floor below, or the base).
  struct Floor
  {
    double                    level         = 0;
    double                    storey_height = 0;
    std::vector<unsigned int> nodes;
    /// A vertical load (N, downwards) beyond the floor's weight (Building
    /// <i>/Floor loads: dead and live loads without mass): in a gravity
    /// analysis, shared equally by the floor's nodes of a 2D frame; in the
    /// P-Delta compression of a shear building's storeys below.
    double                    gravity_load  = 0;
  };

  enum class BuildingType
  {
    frame,
    mesh,
    shear
  };

  /// A frequency band [low, high) (Hz) whose modes get one damping ratio.
  struct DampingBand
  {
    double low = 0, high = 0, damping_ratio = 0;
  };

  /// How the damping of one building is defined: Rayleigh, C = a0 M + a1 K
  /// (fitted at two modes or given), or modal, C = M Phi diag(2 zeta_i
  /// omega_i) Phi^T M over its first modes (a ratio per mode, or per
  /// frequency band; assembly/modal_damping.h).
  struct RayleighDamping
  {
    enum class Kind
    {
      none,
      modes,
      coefficients,
      modal,
      bands
    };
    Kind         kind          = Kind::none;
    double       damping_ratio = 0;
    unsigned int first_mode    = 1; // 1-based, as users count modes
    unsigned int second_mode   = 2;
    double       a0            = 0;
    double       a1            = 0;
    /// modal: the ratio of modes 1, 2, ... (as many modes as values).
    std::vector<double>      modal_ratios;
    /// bands: the bands, over the first `damped_modes` modes.
    std::vector<DampingBand> bands;
    unsigned int             damped_modes = 0;

    /// Whether C is modal (low rank in the building's modes).
    bool is_modal() const { return kind == Kind::modal || kind == Kind::bands; }
    /// The modes the damping needs (0: none).
    unsigned int n_modes_needed() const
    {
      return kind == Kind::modes ? std::max(first_mode, second_mode) :
             kind == Kind::modal ? static_cast<unsigned int>(modal_ratios.size()) :
             kind == Kind::bands ? damped_modes : 0u;
    }
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
    /// Dimension 3: one per floor, bottom to top; empty in 2D.
    std::vector<PlanFloor> plan;
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

  /// Model/Gravity analysis: a load-controlled static analysis of the
  /// gravity loads before any dynamics (integration/static_analysis.h),
  /// whose state the dynamics start from with the loads held constant.
  struct GravityAnalysisSettings
  {
    bool         enabled        = false; // Type = static
    unsigned int n_steps        = 10;
    double       tolerance      = 1e-8; // on the residual, relative to the load
    unsigned int max_iterations = 25;
    unsigned int max_step_cuts  = 8;
  };

  class Model
  {
  public:
    std::vector<Node>       nodes;
    std::vector<Member>     members;
    std::vector<StoreyLink> links;
    std::vector<PlaneLink>  plane_links; // 3D shear buildings
    std::vector<Hinge>      hinges;
    std::vector<Member3D>   members_3d; // 3D frame buildings
    std::vector<Hinge3D>    hinges_3d;
    std::vector<DofMass>    dof_masses;
    std::vector<Gap>        gaps;
    std::vector<Spring>          springs;
    std::vector<FrictionSurface> friction_surfaces;
    std::vector<BuildingLink>    building_links;
    std::vector<Foundation>      foundations; // compliant bases
    std::vector<DofConstraint>   constraints; // masters free, slaves not fixed
    /// A bumper in every 2D gap (law none: bare gaps).
    BumperParameters             bumper;
    /// The contact law of every gap (its gap and m_e are set per gap).
    ContactLawParameters    contact;
    std::vector<NodalMass>  masses;
    std::vector<Building>   buildings;
    /// The plane sections of the `Sections` input (in its order) that fibre
    /// members name (FibreMember::section); null where none does. Shared:
    /// each member clones its own sections from them.
    std::vector<std::shared_ptr<const SectionLaw>> section_laws;
    /// The resultants of those sections: (N, Mz) in the plane, (N, Mz, My,
    /// T) in space.
    unsigned int section_resultants() const { return dimension == 3 ? 4 : 2; }
    MassMatrixType          mass_matrix = MassMatrixType::lumped;
    GeometricNonlinearity   geometric_nonlinearity = GeometricNonlinearity::none;
    double                  gravity                = 9.81; // m/s^2, for P-Delta
    GravityAnalysisSettings gravity_analysis;
    /// 2: planar frames and stick models; 3: torsionally coupled shear
    /// buildings and 3D frames.
    unsigned int            dimension              = 2;
    /// What the builder found given without effect in this model (an entry
    /// of the contact law that the law does not have, a contact law that
    /// made no gap), each naming file, line and entry; the run goes on and
    /// reports them (summary.json's warnings, the terminal).
    std::vector<std::string> warnings;

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
    /// The (equation, coefficient) pairs of q(dof), into `terms`: one (e, 1)
    /// for a free or shared DOF, none for a fixed one, the masters' for a
    /// constrained one.
    void equation_terms(unsigned int dof, std::vector<std::pair<int, double>> &terms) const;
    /// Whether some DOF is a combination of others (equation_terms needed).
    bool has_combinations() const { return combined; }
    int equation(const unsigned int dof) const { return equation_of_dof[dof]; }
    const std::vector<int> &equations() const { return equation_of_dof; }

    /// Equations [first, last) of building b.
    std::array<unsigned int, 2> equation_range(unsigned int b) const;

    /// Total translational mass of building b in x (from all mass sources).
    double total_mass(unsigned int b) const;

  private:
    std::vector<int>          equation_of_dof;
    std::vector<int>          constraint_of_dof; // -1: none
    bool                      combined = false;
    std::vector<unsigned int> first_equation_of_building;
    unsigned int              n_free = 0;
  };
} // namespace poundfe

#endif
