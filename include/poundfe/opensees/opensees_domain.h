// The domain of an OpenSees script on poundfe's engine: nodes with their
// constraints and masses, elements, materials, time series, load patterns
// and recorders, as the script's commands build them (the Tcl reader in
// source/commands/opensees_*.cc fills it; nothing here knows of Tcl).
// Its analysis (opensees_analysis.h) numbers the free DOFs (equalDOF's
// constrained DOFs share their retained DOF's equation, as OpenSees's Plain
// and Transformation handlers give for an identity constraint), assembles
// OpenSees's residual and tangent into poundfe's sparse matrices and solves
// with poundfe's linear solvers. doc/architecture.md says why a script
// builds this thin domain and not a poundfe Model.
#ifndef poundfe_opensees_opensees_domain_h
#define poundfe_opensees_opensees_domain_h

#include <poundfe/elements/beam_column.h>
#include <poundfe/elements/beam_integration.h>
#include <poundfe/elements/crd_transformation.h>
#include <poundfe/laws/material_registry.h>
#include <poundfe/laws/uniaxial_law.h>
#include <poundfe/sections/section_law.h>

#include <Eigen/Core>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace poundfe
{
  namespace opensees
  {
    using Matrix = Eigen::MatrixXd;
    using Vector = Eigen::VectorXd;

    /// A refusal of a script's command (bad arguments, missing tags,
    /// unsupported options): the reader reports it at the script's line.
    class ScriptError : public std::runtime_error
    {
    public:
      using std::runtime_error::runtime_error;
    };

    struct Node
    {
      int                 tag = 0;
      std::vector<double> coordinates;
      std::vector<double> mass;  // per DOF
      /// Lumped masses of the elements on it (elasticBeamColumn -mass),
      /// per DOF: in M, not in `mass` (OpenSees's node mass).
      std::vector<double> element_mass;
      std::vector<bool>   fixed; // per DOF
      /// Committed response per DOF (relative to the ground).
      std::vector<double> disp, vel, accel;
      /// The equation of each DOF (-1: fixed; -2 - j: the analysis's j-th
      /// imposed displacement), set by the analysis.
      std::vector<int> equation;
    };

    /// OpenSees's Rayleigh factors: C = alpha_M M + beta_K K_t + beta_K0 K_0 +
    /// beta_Kc K_c (Element::getDamp, Node::getDamp).
    struct RayleighFactors
    {
      double alpha_m = 0, beta_k = 0, beta_k_init = 0, beta_k_committed = 0;
    };

    /// Uniaxial laws on rows of an element's DOFs (zeroLength, truss): the
    /// strains (t u) strain_scale and rates (t v) strain_scale of the
    /// laws, the force force_scale t^T sigma, the tangent (force_scale
    /// strain_scale) t^T E t. The state of such an element, which the
    /// analysis's typed loops over small models read and set in place of
    /// the element's calls (opensees_analysis.cc, UniaxialLinks).
    struct UniaxialRows
    {
      Matrix                                    t; // materials x DOFs
      std::vector<std::unique_ptr<UniaxialLaw>> laws;
      Vector strain, rate; // the materials' trial strains and strain rates
      double strain_scale = 1, force_scale = 1; // a truss: 1/L and A
      std::string why; // a law's refusal of its trial state
    };

    /// An element in OpenSees's terms: trial response from the end nodes'
    /// displacements and velocities, resisting force and tangents in the
    /// global DOFs of its nodes (node after node), commit/revert.
    class Element
    {
    public:
      Element(const int tag, std::vector<int> nodes)
        : tag(tag)
        , node_tags(std::move(nodes))
      {}
      virtual ~Element() = default;
      const int              tag;
      const std::vector<int> node_tags;

      virtual unsigned int n_dofs() const = 0;
      /// False when a material refuses its state (failure() says why).
      virtual bool   set_trial(const Vector &u, const Vector &v) = 0;
      virtual Vector force() const = 0; // static resisting force, material damping included
      virtual Matrix tangent() const = 0;
      virtual Matrix initial_tangent() const = 0;
      /// The damping matrix of its materials (used when not Rayleigh-damped).
      virtual Matrix material_damping() const { return Matrix::Zero(n_dofs(), n_dofs()); }
      /// The same four into the caller's storage, which keeps its memory
      /// from one iteration to the next (the analysis's calls); an element
      /// that computes them in place overrides these.
      virtual void force_into(Vector &f) const { f = force(); }
      virtual void tangent_into(Matrix &k) const { k = tangent(); }
      virtual void initial_tangent_into(Matrix &k) const { k = initial_tangent(); }
      virtual void material_damping_into(Matrix &c) const { c = material_damping(); }
      /// c_k K_t + c_c C_m into k, C_m the materials' damping (an element
      /// not Rayleigh-damped), `c` the storage of C_m: the iteration
      /// matrix's terms of the element. The default from tangent_into and
      /// material_damping_into; an element that sums both at once overrides it.
      virtual void tangent_and_damping_into(double c_k, double c_c, Matrix &k, Matrix &c) const;
      /// Whether the domain's Rayleigh factors damp it (OpenSees: beams
      /// always, zeroLength with -doRayleigh).
      virtual bool rayleigh_damped() const = 0;
      /// Whether its set_trial costs microseconds (a member's section
      /// states at its integration points), enough to pay for a thread.
      virtual bool costly_trial() const { return false; }
      virtual void commit() {}
      virtual void revert() {}
      virtual void reset() {}
      virtual std::string failure() const { return {}; }
      /// The element as UniaxialRows alone (its set_trial, force and
      /// tangents those of the rows); null for any other element.
      virtual UniaxialRows *uniaxial_rows() { return nullptr; }
      /// Element loads (eleLoad -beamUniform): whether it takes them; its
      /// loads zeroed, and a uniform load added, wy across its local x (and
      /// wz along local z, in 3D) and wx along it, already times its
      /// pattern's factor (OpenSees's Element::zeroLoad and addLoad).
      virtual bool takes_beam_loads() const { return false; }
      virtual void zero_loads() {}
      virtual void add_beam_uniform(double /*wy*/, double /*wx*/, double /*wz*/) {}
      /// A response by OpenSees's words (recorder Element, eleResponse):
      /// "force" (or "globalForce") for every element, and for beam-columns
      /// "localForce", "basicForce", "basicDeformation", "section" i
      /// "force"|"deformation" (i 1-based). ScriptError naming the words
      /// when the element has no such response.
      virtual std::vector<double> response(const std::vector<std::string> &words) const;
      /// The same response resolved once (a recorder's, read at every
      /// step): appends the values of the element's state to its argument.
      /// ScriptError as response(); the default reads response() each time.
      using ResponseReader = std::function<void(std::vector<double> &)>;
      virtual ResponseReader response_reader(const std::vector<std::string> &words) const;

      /// The tangent at the last commit (OpenSees's K_c for betaKc).
      Matrix committed_tangent;
      /// The equation of each local DOF (-1: fixed), set by the analysis.
      std::vector<int> equations;
    };

    /// Whether the words ask for the global resisting force ("force",
    /// "forces", "globalForce", "globalForces").
    bool is_global_force(const std::vector<std::string> &words);

    /// A time series: the factor at time t (OpenSees's TimeSeries::getFactor).
    struct TimeSeries
    {
      enum class Kind
      {
        constant,
        linear,
        path,
        trig
      } kind = Kind::constant;
      double              factor = 1;
      double              dt     = 0; // path: the values' spacing
      std::vector<double> values;    // path
      /// path: the values' times, not decreasing (OpenSees's
      /// PathTimeSeries: -time, -fileTime), in place of dt; 0 before the
      /// first and after the last.
      std::vector<double> times;
      /// path with dt (OpenSees's PathSeries): -useLast (the last value
      /// after the end, in place of 0) and -startTime (the first value's).
      bool                use_last   = false;
      double              start_time = 0;
      double start = 0, finish = 0, period = 1, shift = 0, zero_shift = 0; // trig
      double              at(double time) const;
      /// at() of a series with times (PathTimeSeries::getFactor).
      double path_time_factor(double time) const;
    };

    struct NodalLoad
    {
      int                 node = 0;
      std::vector<double> values;
    };

    /// eleLoad -ele tag -type -beamUniform Wy <Wx> (in 3D: Wy Wz <Wx>).
    struct BeamUniformLoad
    {
      int    element = 0;
      double wy = 0, wx = 0, wz = 0;
    };

    /// sp node dof value inside a Plain pattern: the DOF (0-based) held at
    /// value times the pattern's factor (OpenSees's SP_Constraint of a
    /// pattern, which the Transformation handler removes from the
    /// equations and imposes).
    struct ImposedDisplacement
    {
      int          node = 0;
      unsigned int dof  = 0;
      double       value = 0;
    };

    /// A load pattern: Plain (nodal loads times its series) or
    /// UniformExcitation (ground acceleration along `direction`).
    struct Pattern
    {
      int                         tag = 0;
      bool                        uniform_excitation = false;
      std::shared_ptr<TimeSeries> series;
      double                      factor    = 1; // -fact
      unsigned int                direction = 0; // uniform excitation: 0-based DOF
      std::vector<NodalLoad>      loads;
      std::vector<BeamUniformLoad> beam_loads;
      std::vector<ImposedDisplacement> imposed;
      /// loadConst: the factor frozen at the time it was called.
      bool   constant        = false;
      double constant_factor = 0;
      double load_factor(double time) const;
    };

    struct EqualDof
    {
      int                       retained = 0, constrained = 0;
      std::vector<unsigned int> dofs; // 0-based
    };

    /// A rigid tie, u_c = C_cr u_r with C_cr the small-rotation rigid body
    /// motion of the offset d = x_c - x_r,
    ///   u_c = u_r + theta_r x d,  theta_c = theta_r:
    /// rigidDiaphragm perpDirn rNode cNodes (3D, -ndf 6; OpenSees's
    /// RigidDiaphragm) ties each constrained node's in-plane translations
    /// and rotation about perpDirn, with theta_r's perpDirn component only,
    ///   u_a = u_a,r - d_b theta_r,  u_b = u_b,r + d_a theta_r,  theta = theta_r,
    /// (a, b, perp) cyclic; rigidLink beam rNode cNode (OpenSees's RigidBeam)
    /// ties every DOF of its one constrained node (in 2D, -ndf 3:
    /// u = u_r - d_y theta_r, v = v_r + d_x theta_r; with ndf = ndm, no
    /// rotations, u_c = u_r).
    struct RigidTie
    {
      unsigned int     perpendicular = 2; // 0-based axis
      bool             beam          = false; // rigidLink beam
      int              retained      = 0;
      std::vector<int> constrained;
      std::string      where; // "file:line" of its command ("" outside a file)
      /// The command's name, with its file and line when known.
      std::string name() const;
      /// The constrained DOFs of each constrained node.
      std::vector<unsigned int> tied_dofs(unsigned int ndf) const;
      /// Row k of C_cr for a constrained node at offset d: the retained
      /// DOFs and their factors, the identity's first.
      std::vector<std::pair<unsigned int, double>>
      row(unsigned int k, unsigned int ndm, unsigned int ndf, const std::vector<double> &d) const;
    };

    /// `beamIntegration`: Lobatto or Legendre with n points on one section,
    /// or HingeRadau (sections of end I, end J and the interior, hinge
    /// lengths); the rule of HingeRadau needs the member's length.
    struct IntegrationSpec
    {
      enum class Kind
      {
        lobatto,
        legendre,
        hinge_radau
      } kind                = Kind::lobatto;
      unsigned int n_points = 0;
      int          section = 0, section_i = 0, section_j = 0; // hinge_radau: section = interior
      double       hinge_length_i = 0, hinge_length_j = 0;
    };

    /// A material of other materials (laws/combined_materials.h), made from
    /// its components' tags when an element is: Parallel (with its factors,
    /// empty: 1), Series (with -iter's maxIter and tol) or MinMax (one
    /// component and its strain limits).
    struct CombinedMaterial
    {
      std::string         type;
      std::vector<int>    components;
      std::vector<double> factors;
      double              min_strain = -1.0e16, max_strain = 1.0e16; // OpenSees's defaults
      unsigned int        max_iterations = 1;
      double              tolerance      = 1.0e-10;
    };

    /// What a script built; the analysis (opensees_analysis.h) moves it.
    struct Domain
    {
      unsigned int ndm = 0, ndf = 0; // 0: no `model` yet
      std::map<int, Node>                     nodes;
      std::map<int, std::unique_ptr<Element>> elements;
      std::map<int, MaterialParameters>       materials;
      std::map<int, CombinedMaterial>         combined_materials;
      std::map<int, Transformation>           transformations;
      /// The vecxz of each 3D geomTransf (by its tag).
      std::map<int, std::array<double, 3>>    vecxz;
      /// Sections by tag, each cloned into every integration point.
      std::map<int, std::shared_ptr<const SectionLaw>> sections;
      std::map<int, IntegrationSpec>   integrations;
      std::map<int, std::shared_ptr<TimeSeries>> series;
      std::map<int, Pattern>                  patterns;
      std::vector<EqualDof>                   equal_dofs;
      std::vector<RigidTie>                  rigid_ties;
      RayleighFactors                         rayleigh;
      /// Per-object factors in place of `rayleigh`'s: a region's (-rayleigh,
      /// setElementRayleighDampingFactors) and the zeros of a node or element
      /// made after the last `rayleigh` (OpenSees sets the factors of the
      /// objects that exist then); the `rayleigh` command clears them.
      std::map<int, RayleighFactors> element_rayleigh;
      std::map<int, double>          node_alpha_m;
      /// The tags of the script's regions (a tag once only).
      std::vector<int> regions;
      /// An element's mass lumped on a node (elasticBeamColumn and
      /// beam-column -mass, truss -rho, twoNodeLink -mass): `mass` on each
      /// of its translations, in Node::element_mass too. Its alpha_M
      /// damping is the element's, and only when the element is
      /// Rayleigh-damped (Element::getDamp's alpha_M M_e).
      struct LumpedMass
      {
        int    element = 0, node = 0;
        double mass = 0;
        /// Its ground-motion load -m a_g enters the reactions (a truss's
        /// and a beam-column's: their getResistingForce subtracts theLoad).
        bool load_in_reaction = false;
        /// Its ground-motion load acts twice: OpenSees 3.8's ElasticBeam2d
        /// subtracts its inertia load Q in getResistingForce (when rho is
        /// not 0) and again in getResistingForceIncInertia, so that a
        /// 2D elasticBeamColumn's -mass takes 2 m a_g (doc/user-guide.md).
        bool ground_load_twice = false;
      };
      std::vector<LumpedMass> lumped_masses;
      /// An element's consistent mass (-cMass 1): its matrix on the
      /// element's DOFs (node after node, -ndf each), in M beside the
      /// nodes' diagonal; alpha_M damps it when the element is
      /// Rayleigh-damped. Its ground-motion load -M r a_g enters the
      /// reactions when `load_in_reaction` (a truss's, as LumpedMass's).
      struct ConsistentMass
      {
        int              element = 0;
        std::vector<int> nodes;
        Matrix           matrix;
        bool             load_in_reaction = false;
        /// As LumpedMass's (a 2D elasticBeamColumn's -cMass).
        bool ground_load_twice = false;
      };
      std::vector<ConsistentMass> consistent_masses;
      /// The modes of the last `eigen` (OpenSees's Domain eigenvalues and
      /// its DOF groups' eigenvectors), M-normalised, by node and DOF.
      struct Modes
      {
        std::vector<double>                             eigenvalues;
        std::vector<std::map<int, std::vector<double>>> shapes;
      };
      Modes modes;
      /// modalDamping's factors zeta_i (one per mode of the last `eigen`)
      /// and whether its matrix enters the tangent (modalDamping) or only
      /// its force the unbalance (modalDampingQ); empty: none.
      std::vector<double> modal_damping;
      bool                modal_damping_in_tangent = true;
      /// Counts the changes of `modes` and `modal_damping` (an analysis
      /// renews its own vectors of them).
      unsigned int modal_stamp = 0;
      double                                  time = 0; // committed
      /// OpenSees's global ops_Dt: the step of the last transient
      /// `analyze` (0 until then), over which a ViscousDamper integrates.
      /// Its materials hold a reference to it: a Domain is never moved.
      double time_step = 0;
      /// Set whenever nodes, elements or constraints change: the analysis
      /// numbers the equations again.
      bool changed = true;

      const Node &node(int tag) const;
      Node       &node(int tag);
      /// The Rayleigh factors of an element, of a node (its alpha_M).
      const RayleighFactors &rayleigh_of(int element) const;
      double                 alpha_m_of(int node) const;
      /// Whether some element's damping takes K_c (its committed tangent
      /// renewed at every commit).
      bool committed_stiffness_damping() const;
      /// Whether alpha_M is the same for every mass, the domain's
      /// `rayleigh` one (no region's, every lumped mass on a Rayleigh-damped
      /// element, or alpha_M 0).
      bool uniform_mass_damping() const;
      /// alpha_M M by node and DOF: the node's mass times its alpha_M plus
      /// each lumped mass times its element's (see LumpedMass).
      std::map<int, std::vector<double>> mass_damping() const;
      /// The nodal loads of the Plain patterns at `time` (per node, per DOF).
      std::map<int, std::vector<double>> nodal_loads(double time) const;
      /// The Plain patterns' element loads at `time` handed to their
      /// elements (OpenSees's LoadPattern::applyLoad: zeroLoad, addLoad).
      void apply_element_loads(double time);
      /// The displacement of each DOF the Plain patterns' sp commands
      /// impose, at `time` (the sum over the patterns that impose it).
      std::map<std::pair<int, unsigned int>, double> imposed_displacements(double time) const;
      /// The ground acceleration along each DOF at `time` (UniformExcitation).
      std::vector<double> ground_acceleration(double time) const;
      /// The same into `a` (ndf values), its storage kept.
      void ground_acceleration(double time, std::vector<double> &a) const;
      /// The flag of OpenSees's Domain::calculateNodalReactions (`reactions`,
      /// `reactions -dynamic`, `reactions -rayleigh`).
      enum class ReactionFlag
      {
        resisting, // 0: element resisting forces minus applied loads, plus alpha_M M v
        dynamic,   // 1: with the inertia and Rayleigh damping forces of nodes and elements
        rayleigh   // 2: the Rayleigh damping forces alone
      };
      /// OpenSees's nodal reactions at the committed state.
      std::map<int, std::vector<double>>
      reactions(ReactionFlag flag = ReactionFlag::resisting) const;
      /// An element's nodal values of a node response (disp, vel, accel),
      /// node after node, in its DOFs' order.
      Vector element_values(const Element &element,
                            const std::vector<double> Node::*response) const;
      /// OpenSees's Element::getRayleighDampingForces: (alpha_M M_e +
      /// beta_K K_t + beta_K0 K_0 + beta_Kc K_c) v_e with the element's
      /// factors, whether or not they damp it in the analysis.
      Vector rayleigh_damping_forces(const Element &element) const;
      /// An element's OpenSees getResistingForceIncInertia: its resisting
      /// force, its Rayleigh damping when it is damped, its lumped masses'
      /// inertia m a and ground-motion load (see LumpedMass).
      Vector force_with_inertia(const Element &element) const;
      /// OpenSees's getResistingForce of an element with mass under a
      /// ground motion (its `force` response and eleForce): the element's
      /// force plus its lumped masses' ground-motion load m a_g on the
      /// translations (load_in_reaction).
      Vector force_with_ground_load(const Element &element) const;
      /// Whether the element has a lumped mass whose ground-motion load its
      /// getResistingForce subtracts (LumpedMass::load_in_reaction).
      bool has_ground_load(const Element &element) const;
      /// Element::response with OpenSees's getResistingForce for the
      /// global force ("force", "globalForce": force_with_ground_load).
      std::vector<double> element_response(const Element                  &element,
                                           const std::vector<std::string> &words) const;
      /// `remove element tag` (OpenSees's Domain::removeElement): the
      /// element, its lumped masses and its region's factors; nothing when
      /// there is none. ScriptError when a pattern's element load names it
      /// (OpenSees 3.8 keeps the load on the removed element).
      void remove_element(int tag);
      /// Row k of tie's C_cr for its constrained node c (RigidTie::row at
      /// c's offset from the retained node).
      std::vector<std::pair<unsigned int, double>>
      tie_row(const RigidTie &tie, int c, unsigned int k) const;
      /// `remove mp cNode` (OpenSees's Domain::removeMP_Constraints): every
      /// equalDOF, rigidLink and rigidDiaphragm tie of constrained node
      /// cNode; nothing when there is none.
      void remove_ties_of(int constrained);
      /// `remove node tag`: ScriptError when an element, an equalDOF, a
      /// rigidDiaphragm or a pattern's load or sp names it (OpenSees 3.8
      /// removes it from under them); nothing when there is none.
      void remove_node(int tag);
      /// OpenSees's Domain::revertToStart (`reset`): every node's response
      /// zero, every element back to its initial state (and its trial
      /// state at those displacements), the time 0.
      void revert_to_start();
      void clear();
    };

    /// A fresh material of the domain's tag (each element owns its own, as
    /// OpenSees copies a material into every element that names it).
    std::unique_ptr<UniaxialLaw> make_domain_material(const Domain &domain, int tag);

    /// The committed displacements of a member's two nodes when it is made,
    /// `n_node_dofs` per node (zero past a node's own DOFs): OpenSees's
    /// coordinate transformations (LinearCrdTransf2d/3d, PDeltaCrdTransf2d/
    /// 3d, CorotCrdTransf2d::initialize: nodeIInitialDisp, nodeJInitialDisp)
    /// take a member added on nodes that have moved along and as long as it
    /// is then and measure its displacements from them.
    Vector displacements_when_made(const Domain &domain, const std::array<int, 2> &nodes,
                                   unsigned int n_node_dofs);

    /// elasticBeamColumn in 2D with a Linear or PDelta transformation,
    /// measured from the nodes' displacements when it is made.
    std::unique_ptr<Element> make_elastic_beam_2d(const Domain &domain, int tag,
                                                  std::array<int, 2> nodes, double A, double E,
                                                  double I, Transformation transformation);

    /// elasticBeamColumn in 3D (OpenSees's ElasticBeam3d with
    /// LinearCrdTransf3d or PDeltaCrdTransf3d): local axes x along the
    /// member, y = vecxz × x, z = x × y.
    struct ElasticSection3d
    {
      double A = 0, E = 0, G = 0, J = 0, Iy = 0, Iz = 0;
    };
    /// A 3D member's local axes as the rows of R (x along its displaced
    /// chord, elements/displaced_chord.h, of length L; y = vecxz × x /
    /// |vecxz × x|, z = x × y); u_made: its nodes' 12 displacements when it
    /// was made (zero on nodes that have not moved); ScriptError when L is 0
    /// or vecxz is along x.
    Eigen::Matrix3d member_axes(const Domain &domain, int tag, const std::array<int, 2> &nodes,
                                const std::array<double, 3> &vecxz, double &L,
                                const Eigen::VectorXd &u_made = Eigen::VectorXd::Zero(12));
    /// A beam-column's consistent mass (-cMass; OpenSees 3.8's
    /// ElasticBeam2d/3d and DispBeamColumn2d/3d::getMass): the cubic
    /// Hermitian mass rho L/420 [...] of each bending plane, rho L/6 [2 1;
    /// 1 2] axially and, in 3D, torsion_ratio times that on the twists
    /// (ElasticBeam3d: J/A; DispBeamColumn3d: 0), taken to the global DOFs
    /// T^T m_l T (vecxz null in 2D).
    Matrix beam_consistent_mass(const Domain &domain, int tag, const std::array<int, 2> &nodes,
                                double rho, double torsion_ratio,
                                const std::array<double, 3> *vecxz);
    std::unique_ptr<Element> make_elastic_beam_3d(const Domain &domain, int tag,
                                                  std::array<int, 2>   nodes,
                                                  const ElasticSection3d &section,
                                                  Transformation        transformation,
                                                  const std::array<double, 3> &vecxz);

    /// forceBeamColumn (nonlinearBeamColumn) and dispBeamColumn in 2D on the
    /// domain's integration (OpenSees's ForceBeamColumn2d, DispBeamColumn2d),
    /// both with uniform element loads except on a Corotational
    /// transformation.
    enum class BeamColumnKind
    {
      force_based,
      displacement_based
    };
    /// The force-based element iterates as OpenSees does (elements/
    /// beam_column.h: OpenSeesIteration, with -iter's maxIter and tol).
    std::unique_ptr<Element> make_beam_column_2d(const Domain &domain, int tag,
                                                 std::array<int, 2> nodes, BeamColumnKind kind,
                                                 Transformation           transformation,
                                                 const IntegrationSpec   &integration,
                                                 const OpenSeesIteration &iteration);
    /// forceBeamColumn and dispBeamColumn in 3D (BeamColumn<3>: OpenSees's
    /// ForceBeamColumn3d, DispBeamColumn3d) on a Linear, PDelta or
    /// Corotational transformation with the geomTransf's vecxz; uniform
    /// element loads as the member's own (BeamColumn::set_uniform_load),
    /// except on a Corotational one.
    std::unique_ptr<Element> make_beam_column_3d(const Domain &domain, int tag,
                                                 std::array<int, 2> nodes, BeamColumnKind kind,
                                                 Transformation               transformation,
                                                 const std::array<double, 3> &vecxz,
                                                 const IntegrationSpec       &integration,
                                                 const OpenSeesIteration     &iteration);
    /// elasticBeamColumn on a Corotational transformation: the exact
    /// elastic basic stiffness (a displacement-based member on an elastic
    /// section with two Gauss points) on the corotational basic system, as
    /// OpenSees's ElasticBeam2d with CorotCrdTransf2d.
    /// A uniform load wy (transverse), wx (axial) on a member of length L
    /// added to its basic fixed-end forces q0 and basic reactions p0
    /// (OpenSees's ElasticBeam2d and DispBeamColumn2d::addLoad).
    void add_uniform_beam_load(double L, double wy, double wx, Eigen::Vector3d &q0,
                               Eigen::Vector3d &p0);

    std::unique_ptr<Element> make_elastic_corotational_2d(const Domain &domain, int tag,
                                                          std::array<int, 2> nodes, double A,
                                                          double E, double I);
    /// The same in space (ElasticBeam3d with CorotCrdTransf3d), with the
    /// geomTransf's vecxz; no element loads.
    std::unique_ptr<Element> make_elastic_corotational_3d(const Domain &domain, int tag,
                                                          std::array<int, 2>      nodes,
                                                          const ElasticSection3d &section,
                                                          const std::array<double, 3> &vecxz);

    /// zeroLength: uniaxial materials along local directions (1-based as in
    /// OpenSees: 1-3 translations, 4-6 rotations) of the local axes x, y.
    struct ZeroLengthData
    {
      std::array<int, 2>        nodes{};
      std::vector<int>          materials;
      std::vector<int>          directions;
      std::array<double, 3>     x{{1, 0, 0}}, y{{0, 1, 0}};
      bool                      rayleigh = false;
    };
    std::unique_ptr<Element> make_zero_length(const Domain &domain, int tag,
                                              const ZeroLengthData &data);
    /// twoNodeLink (OpenSees's TwoNodeLink): uniaxial materials on the
    /// basic deformations of directions 1 to the node's number of DOFs (the
    /// local DOFs of node j minus node i, shear with the moments of
    /// -shearDist), on the local axes of -orient or of the nodes; -pDelta's
    /// moment ratios (2D: rMz1 rMz2; 3D: rMy1 rMy2 rMz1 rMz2).
    struct TwoNodeLinkData
    {
      std::array<int, 2>    nodes{};
      std::vector<int>      materials;
      std::vector<int>      directions; // 1-based
      /// -orient: x and yp (6 values), or one vector (3 values: x in 1D and
      /// 2D, yp in 3D).
      std::vector<double>   orient;
      std::vector<double>   p_delta;        // empty: no P-Delta
      std::vector<double>   shear_distance; // empty: 0.5 0.5
      bool                  rayleigh = false;
      /// -mass: half on each node's translations (a Domain::LumpedMass).
      double                mass = 0;
    };
    std::unique_ptr<Element> make_two_node_link(const Domain &domain, int tag,
                                                const TwoNodeLinkData &data);
    /// The uniaxial rows of a zeroLength or twoNodeLink (also on moved
    /// nodes, or with -pDelta, which the analysis's own loops leave to the
    /// element), to read its materials' states; null for another element.
    UniaxialRows *link_rows(Element &element);

    /// The twoNodeLink's local axes, the rows x, y, z (TwoNodeLink::setUp's
    /// trans), and its length L.
    Eigen::Matrix3d two_node_link_axes(const Domain &domain, int tag, const TwoNodeLinkData &data,
                                       double &L);
    /// truss: a uniaxial material over the area A along the member, small
    /// strains (OpenSees's Truss); Rayleigh-damped only when asked.
    std::unique_ptr<Element> make_truss(const Domain &domain, int tag, std::array<int, 2> nodes,
                                        double area, int material, bool rayleigh);
  } // namespace opensees
} // namespace poundfe

#endif
