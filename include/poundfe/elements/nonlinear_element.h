// A nonlinear element on k DOFs u_e (its equations; -1 is the ground, where
// u = 0) with an internal force f_e(u_e, u_e') and the consistent tangents
// K_t = df_e/du_e, C_t = df_e/du_e', neither necessarily symmetric.
// A part K_ref,e of its stiffness may be assembled once into the linear K
// (the initial stiffness of hinges and storeys); the element then gives the
// integrator only
//   the force correction  f_e - K_ref,e u_e                  (k entries), and
//   the tangent change    K_t - K_ref,e + c C_t = B_e D_e B_e^T,
// c = gamma/(beta dt), with B_e a constant k x r_e matrix (r_e the element's
// rank: 1 for a uniaxial element, 2 for one coupling two directions) and
// D_e a dense r_e x r_e matrix of any sign or symmetry. The integrator
// solves with sum_e B_e D_e B_e^T either by the Woodbury identity on the one
// factorisation of K_eff (B fixed, so A^-1 B is computed once) or by adding
// it into K_eff and refactorising; see integration/newmark.h.
// State follows OpenSees's UniaxialMaterial (setTrialStrain / commitState /
// revertToLastCommit / revertToStart): set_trial -> force and tangent ->
// commit() or revert(); a rejected iteration or cut step costs a revert(),
// which restores the committed state exactly.
#ifndef poundfe_elements_nonlinear_element_h
#define poundfe_elements_nonlinear_element_h

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace poundfe
{
  enum class ElementKind
  {
    hinge,  // moment-rotation at a member end
    storey, // force-drift of a shear-building storey
    gap,    // contact
    spring, // nonlinear elastic spring to the ground (SD, Duffing)
    friction, // dry friction against the ground or a moving belt
    link,     // a damper or connector between floors of two buildings
    foundation, // a compliant foundation's sway or rocking spring and dashpot
    member      // a beam-column on fibre sections (elements/member_element.h)
  };

  class NonlinearElement
  {
  public:
    /// Local vectors are views of contiguous storage (no copies).
    using LocalVector    = Eigen::Ref<const Eigen::VectorXd>;
    using LocalVectorOut = Eigen::Ref<Eigen::VectorXd>;
    using LocalMatrixOut = Eigen::Ref<Eigen::MatrixXd>;

    NonlinearElement(const ElementKind kind, const unsigned int building, std::string label,
                     std::vector<int> equations)
      : kind(kind)
      , building(building)
      , label(std::move(label))
      , dof_equations(std::move(equations))
    {}
    virtual ~NonlinearElement() = default;

    ElementKind  kind     = ElementKind::hinge;
    unsigned int building = 0;
    std::string  label;

    /// The equation of each local DOF; -1: the ground.
    const std::vector<int> &equations() const { return dof_equations; }
    /// Equation i becomes new_equation(i) (the ground, -1, stays): a rank's
    /// own numbering of a model partitioned over ranks (assembly/partition.h).
    template <typename Renumbering>
    void renumber(const Renumbering &new_equation)
    {
      for (int &i : dof_equations)
        if (i >= 0)
          i = new_equation(i);
    }
    unsigned int n_dofs() const { return dof_equations.size(); }

    /// r_e, the number of columns of B_e.
    virtual unsigned int rank() const = 0;
    /// B_e (n_dofs x rank). Constant: the Woodbury path factorises with it.
    virtual Eigen::MatrixXd tangent_basis() const = 0;
    /// Whether B_e D_e B_e^T is always symmetric (Eigen's LDLT can then
    /// refactorise the tangent; otherwise an LU backend must).
    virtual bool has_symmetric_tangent() const = 0;

    /// The time at the end of the step about to be tried (before set_trial).
    virtual void set_trial_time(double) {}
    /// The factor of the element's own loads (a member's self-weight) from
    /// the next set_trial on: the gravity analysis's load factor, 1 once
    /// it is done. Elements without loads ignore it.
    virtual void set_load_factor(double) {}
    /// Evaluate the trial state at local displacements and velocities (0 on
    /// ground DOFs). Returns false when the element's own iteration fails;
    /// failure() then says why, and the trial state must not be used.
    virtual bool set_trial(const LocalVector &u, const LocalVector &v) = 0;
    /// f_e - K_ref,e u_e at the trial state.
    virtual void force_correction(LocalVectorOut f) const = 0;
    /// D_e at the trial state for c = damping_factor (r_e x r_e).
    virtual void tangent_change(double damping_factor, LocalMatrixOut d) const = 0;
    /// Work done on the element from the committed to the trial state
    /// (trapezoidal; exact for the average-acceleration rule).
    virtual double work_increment() const = 0;
    /// Work done on the structure from the committed to the trial state by
    /// what drives the element (a moving belt under a friction element).
    virtual double supplied_work_increment() const { return 0; }
    /// Work done on the element from the committed to the trial state by
    /// its own loads (a member's self-weight, held at its factor after the
    /// gravity analysis), J; work_increment() includes it. The integrator
    /// books it as the work of the loads held constant.
    virtual double held_load_work_increment() const { return 0; }
    /// u_e^T K_ref,e u_e / 2 at the trial state: the part of
    /// stored_energy() that the linear K already counts.
    virtual double reference_energy() const = 0;

    virtual void commit() = 0;
    virtual void revert() = 0;
    /// Back to the virgin state.
    virtual void reset() = 0;
    /// Why set_trial returned false; empty: no reason given (the
    /// integrator then says so rather than print nothing).
    virtual std::string failure() const { return {}; }

    /// Contact: whether the trial / committed state carries force. A change
    /// between them within a step is an event the integrator locates by
    /// cutting the step.
    virtual bool is_active() const { return false; }
    virtual bool was_active() const { return false; }
    /// The branch of a piecewise element at the trial / committed state
    /// (friction: stick 0, slip -1 or +1); a change within a step is an
    /// event, located by cutting the step.
    virtual int phase() const { return is_active(); }
    virtual int committed_phase() const { return was_active(); }
    /// Contact: the duration of an impact, which the integrator resolves by
    /// `Steps per contact` steps. At the committed state: of the contact
    /// under way, or, when open, of one that would begin at `closing_rate`
    /// (m/s, > 0 approaching). 0: not a contact, or no impact at that rate.
    virtual double contact_duration(double /*closing_rate*/) const { return 0; }

    /// Contact in plan: where the force acts at the trial state (x, y);
    /// NaN for elements without a point.
    virtual std::array<double, 2> contact_point() const
    {
      return {{std::nan(""), std::nan("")}};
    }

    // What observers and outputs read: scalar measures of the trial state,
    // which is the committed state between steps.
    virtual double force() const = 0;
    /// An element on several deformations (elements/biaxial_element.h): the
    /// force along deformation a; the others have one, force().
    virtual double force_component(const unsigned int /*a*/) const { return force(); }
    /// The element's deformation measure at global displacements u.
    virtual double deformation(const Eigen::VectorXd &u) const = 0;
    virtual double history_variable() const { return 0; }
    /// Recoverable energy; the work done minus this is what was dissipated.
    virtual double stored_energy() const = 0;
    /// Whether the element can dissipate (UniaxialLaw::dissipates); not
    /// used by the energy balance yet.
    virtual bool dissipates() const { return true; }
    /// Deformation at which the element yields (for ductility); 0 if none.
    virtual double yield_deformation() const { return 0; }
    virtual double initial_stiffness() const { return 0; }

  private:
    std::vector<int> dof_equations;
  };

  /// The nonlinear elements of a model, owned, indexed as elements[h].
  class NonlinearElements
  {
    using Storage = std::vector<std::unique_ptr<NonlinearElement>>;

    /// Iterates over the elements rather than the pointers.
    template <typename BaseIterator, typename Element>
    class Iterator
    {
    public:
      using iterator_category = std::forward_iterator_tag;
      using value_type        = Element;
      using difference_type   = std::ptrdiff_t;
      using pointer           = Element *;
      using reference         = Element &;

      explicit Iterator(BaseIterator it)
        : it(it)
      {}
      reference operator*() const { return **it; }
      pointer   operator->() const { return it->get(); }
      Iterator &operator++()
      {
        ++it;
        return *this;
      }
      bool operator==(const Iterator &other) const { return it == other.it; }
      bool operator!=(const Iterator &other) const { return it != other.it; }

    private:
      BaseIterator it;
    };

  public:
    using iterator       = Iterator<Storage::iterator, NonlinearElement>;
    using const_iterator = Iterator<Storage::const_iterator, const NonlinearElement>;

    unsigned int size() const { return elements.size(); }
    bool         empty() const { return elements.empty(); }

    NonlinearElement       &operator[](const unsigned int h) { return *elements[h]; }
    const NonlinearElement &operator[](const unsigned int h) const { return *elements[h]; }

    void push_back(std::unique_ptr<NonlinearElement> element) { add(std::move(element)); }
    /// The element made; if keep_only() drops it, it lives until the next
    /// one is added.
    template <typename Element, typename... Arguments>
    Element &emplace_back(Arguments &&...arguments)
    {
      auto element       = std::make_unique<Element>(std::forward<Arguments>(arguments)...);
      Element &reference = *element;
      add(std::move(element));
      return reference;
    }

    /// From now on add only the elements for which `keep(element)` is true
    /// and drop the others as they come (a rank's share of a partitioned
    /// model: never the whole model's elements at once). Empty: keep all.
    void keep_only(std::function<bool(const NonlinearElement &)> keep_)
    {
      keep = std::move(keep_);
      dropped.reset();
    }

    /// Drop the elements for which `drop(element)` is true (a rank's
    /// share of a partitioned model keeps those on its equations).
    template <typename Predicate>
    void erase_if(const Predicate &drop)
    {
      elements.erase(std::remove_if(elements.begin(), elements.end(),
                                    [&](const std::unique_ptr<NonlinearElement> &e) {
                                      return drop(static_cast<const NonlinearElement &>(*e));
                                    }),
                     elements.end());
    }

    iterator       begin() { return iterator(elements.begin()); }
    iterator       end() { return iterator(elements.end()); }
    const_iterator begin() const { return const_iterator(elements.begin()); }
    const_iterator end() const { return const_iterator(elements.end()); }

  private:
    void add(std::unique_ptr<NonlinearElement> element)
    {
      if (keep && !keep(*element))
        dropped = std::move(element);
      else
        elements.push_back(std::move(element));
    }

    Storage                                        elements;
    std::function<bool(const NonlinearElement &)> keep;
    std::unique_ptr<NonlinearElement>              dropped; // the last one keep refused
  };
} // namespace poundfe

#endif
