// poundfe's additions to an OpenSees script's transient analyses, read
// from the domain after each committed step: the energy balance and the
// impact log of its gap elements (the Tcl and Python commands
// poundfe::energy and poundfe::impacts), and the contact events that
// poundfe::locateEvents has the analysis locate inside the step.
//
// Energy balance, in the ground's frame (Uang and Bertero 1990, "Evaluation
// of seismic energy in structures", Earthq. Eng. Struct. Dyn. 19:77-90):
//   E_input = int (P - M r a_g) . du        E_kinetic = 1/2 v^T M v
//   E_elements = int f_e . du_e (strain, hysteresis, material damping)
//   E_damping  = int (alpha_M M v + (beta_K K_t + beta_K0 K_0 + beta_Kc K_c)
//                     v_e + modal damping W diag(c) W^T v) . du
//   E_contact  = int f_e . du_e of the gap elements
//   residual   = E_input - (E_kinetic - E_kinetic,0) - E_elements - E_damping - E_contact,
// each integral by the trapezoidal rule over the committed steps, with the
// forces of each step's equilibrium (beta_Kc: the tangent committed before
// the step). Under Newmark's average acceleration the trapezoidal rule of
// the inertia's work is exactly the change of E_kinetic, so the residual of
// a linear model is the round-off of the equilibrium at each step (plus the
// first step's, when the loads at the start are not zero: OpenSees starts
// from zero acceleration).
#ifndef poundfe_opensees_opensees_energy_h
#define poundfe_opensees_opensees_energy_h

#include <poundfe/integration/impact_log.h>
#include <poundfe/opensees/opensees_domain.h>

#include <map>
#include <string>
#include <vector>

namespace poundfe
{
  namespace opensees
  {
    struct EnergyTerms
    {
      double input = 0, kinetic = 0, elements = 0, damping = 0, contact = 0;
      /// E_input - E_kinetic - E_elements - E_damping - E_contact.
      double residual = 0;
      /// |residual| over the largest |term| (0 while every term is 0).
      double relative_residual = 0;
    };

    /// A gap row of an element: its law's index among the element's
    /// uniaxial rows, the path to the gap law inside it (the component's
    /// index in each MinMax, Parallel or Series on the way; empty: the row's
    /// law is the gap law) and the direction (+1 or -1) in which the gap
    /// law's deformation closes the gap past `gap`.
    struct GapRow
    {
      int                       element = 0;
      unsigned int              row = 0;
      std::vector<unsigned int> path;
      double                    gap = 0, direction = -1;
    };

    /// The gap's state in the domain now (the impact log's and
    /// locateEvents's contact): in contact while the gap law's force is not
    /// zero (a failed MinMax on the way: not in contact); then the force is
    /// the row's (a Parallel's sum, a Series's stress), 0 out of contact;
    /// the penetration is the gap law's deformation past `gap` (a Series's
    /// component's own), the rate the row's. Zero when the element or row
    /// is gone.
    ImpactLog::GapState gap_state(const Domain &domain, const GapRow &row);

    /// The energy balance of the transient analyses of a domain.
    class EnergyBalance
    {
    public:
      /// The state at the start of a transient `analyze` (the rule's first
      /// end) of a model whose vectors are built anew; `contact` names the
      /// gap elements.
      void begin(const Domain &domain, const std::vector<int> &contact);
      /// The start of a later `analyze` of the same model (masses,
      /// damping, modes and elements as at begin): the vectors are kept,
      /// and so is the last state when the domain is still at it.
      void resume(const Domain &domain);
      /// A committed step of that analysis.
      void step(const Domain &domain);
      EnergyTerms terms() const;

    private:
      struct State
      {
        double              time = 0;
        Vector              u, v, p, c; // by node and DOF: displacement, velocity, input and damping forces
        std::vector<Vector> u_e, f_e;   // by element
        /// By element: its committed tangent, under beta_Kc (else empty).
        std::vector<Matrix> k_c;
      };
      /// The state of the domain; `previous` the one before this step (its
      /// k_c: the committed tangent this step's equilibrium used).
      State  state(const Domain &domain, const State *previous) const;
      /// s.c: alpha_M M v of the nodes' own masses, the modal damping, and
      /// each Rayleigh-damped element's Domain::rayleigh_damping_forces
      /// with its beta_Kc part on previous's k_c; s.k_c.
      void   add_damping_forces(const Domain &domain, const State *previous, State &s) const;
      double kinetic(const Domain &domain, const Vector &v) const;
      /// M x by node and DOF: the lumped and the consistent masses.
      Vector mass_times(const Domain &domain, const Vector &x) const;
      Vector gathered(const Domain &domain, const std::vector<double> Node::*response) const;

      /// What an analysis keeps (set by begin): each node's first DOF in
      /// the vectors by node and DOF, the lumped masses, those that take
      /// the ground motion (with the second load of a 2D elasticBeamColumn's
      /// -mass) and alpha_M of the nodes' own masses, the modal damping's
      /// c_i and M phi_i.
      std::map<int, unsigned int> offset;
      unsigned int                n_dofs = 0;
      Vector                      mass, ground_mass, mass_damping;
      std::vector<double>         modal_c;
      std::vector<Vector>         modal_w;
      bool                        nodal_loads = false;

      State            last;
      bool             started = false, has_last = false;
      std::vector<int> contact_elements;
      double           input = 0, elements = 0, damping = 0, contact = 0, kinetic_0 = 0,
             kinetic_now = 0;
    };

    /// poundfe::locateEvents's watch over the gap rows: a gap is in contact
    /// while gap_state's force is not zero (ScriptImpacts's episodes); a step
    /// at whose end a gap's contact differs from the committed one has an
    /// event (a contact starts or ends in it). The laws' own phase() is not
    /// asked: `poundfe run`'s event search reads it, and these laws keep
    /// the default there. The laws' committed force is read at watch(),
    /// when they hold their committed state (between analyses a failed
    /// step has been reverted and `reset` has reset them).
    class ContactEvents
    {
    public:
      /// The gap rows of the domain's elements and their committed contact.
      void watch(const Domain &domain, const std::vector<GapRow> &rows);
      /// Whether a gap's contact at the trial state differs from its
      /// committed contact.
      bool changed() const;
      /// The trial contact committed with the step.
      void commit();

    private:
      /// In contact (gap_state's force not zero) at the trial state.
      bool in_contact(std::size_t h) const;

      /// The domain and its gap rows, valid while the analysis that
      /// watches runs (the script cannot change the model inside `analyze`).
      const Domain       *domain = nullptr;
      std::vector<GapRow> gap_rows;
      std::vector<char>   committed_contact;
    };

    /// poundfe's impact log (integration/impact_log.h) over the gap rows.
    class ScriptImpacts
    {
    public:
      void begin(const Domain &domain, const std::vector<GapRow> &rows);
      /// The start of a later `analyze` with the same gap rows.
      void resume(const Domain &domain);
      void step(const Domain &domain);
      const std::vector<GapRow> &rows() const { return gap_rows; }
      const std::vector<Impact> &impacts() const { return log.impacts(); }
      /// The log as CSV: element, start, end (-1: in contact at the end),
      /// peak force, impulse, max penetration and its time.
      std::string csv() const;

    private:
      std::vector<ImpactLog::GapState> states(const Domain &domain) const;

      std::vector<GapRow>              gap_rows;
      std::vector<ImpactLog::GapState> last;
      double                           last_time = 0;
      ImpactLog                        log;
    };
  } // namespace opensees
} // namespace poundfe

#endif
