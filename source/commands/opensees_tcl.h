// The Tcl reader of OpenSees scripts (the `opensees` command), private to
// source/commands/opensees_*.cc so that <tcl.h> stays out of every other
// file: the session a script's commands build (an OpenSees domain, its
// analysis and recorders; opensees/) and the helpers of the command
// procedures. The commands are in opensees_tcl_model.cc (model, loads,
// recorders), opensees_tcl_sections.cc (sections, beam integrations,
// beam-column elements), opensees_tcl_regions.cc (region, damping by
// element), opensees_tcl_print.cc (print, printModel) and
// opensees_tcl_analysis.cc (analysis and queries).
#ifndef poundfe_commands_opensees_tcl_h
#define poundfe_commands_opensees_tcl_h

#include <poundfe/opensees/opensees_analysis.h>
#include <poundfe/opensees/opensees_domain.h>
#include <poundfe/opensees/opensees_energy.h>
#include <poundfe/opensees/opensees_recorder.h>

#include <tcl.h>

#include <array>
#include <functional>
#include <iosfwd>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace poundfe
{
  struct FibreGeometry;

  namespace opensees_tcl
  {
    /// What `print` and `printModel -JSON` write of an element or a
    /// section beyond its tag (opensees_tcl_print.cc): OpenSees's class
    /// name and, in OpenSees's order, its fields as JSON texts.
    struct Printed
    {
      std::string                                      type;
      std::vector<std::pair<std::string, std::string>> fields;
    };

    /// A number, numbers, a tag and tags as OpenSees's JSON writes them (a
    /// tag of a material, section or transformation as a string); the
    /// numbers in the shortest text that reads back to them.
    std::string json_number(double value);
    std::string json_numbers(const std::vector<double> &values);
    std::string json_tag(int tag);
    std::string json_tags(const std::vector<int> &tags);
    std::string json_strings(const std::vector<std::string> &texts); // each quoted

    /// What a script has built and asked for so far.
    struct Session
    {
      explicit Session(std::ostream &warnings)
        : warnings(warnings)
      {}
      /// The recorders' lines still queued reach them before they go.
      ~Session()
      {
        if (writer)
          writer->drain();
      }
      opensees::Domain                                     domain;
      opensees::AnalysisOptions                            options;
      /// Which of `test`, `algorithm` and the static and transient
      /// integrators the script gave (the others: OpenSees's defaults).
      bool has_test = false, has_algorithm = false;
      bool has_static_integrator = false, has_transient_integrator = false;
      std::unique_ptr<opensees::Analysis>                  analysis;
      /// The recorders' writer thread (made with the first recorder when
      /// output_writer_threaded()); before `recorders`, which drain it as they go.
      std::shared_ptr<OutputQueue>                         writer;
      std::vector<std::unique_ptr<opensees::Recorder>>     recorders;
      /// Each recorder's tag (`remove recorder`), and the next one.
      std::vector<int> recorder_tags;
      int              next_recorder_tag = 0;
      /// The fibres of the section Fiber whose body runs (nullptr outside).
      FibreGeometry *fibres = nullptr;
      /// OpenSeesPy's conventions (poundfe.opensees): a Plain pattern and a
      /// Fiber section take no body; the pattern stays the current one, and
      /// the section stays open (`open_fibres`, tag `open_section`) for the
      /// patch, layer and fiber commands after it, until close_open_section.
      bool                           without_bodies = false;
      std::shared_ptr<FibreGeometry> open_fibres;
      int                            open_section = 0;
      double                         open_torsion = 0; // its GJ (3D)
      /// Every command defined, and whether poundfe implements it.
      std::map<std::string, bool> commands;
      /// What printModel writes of the section Fiber being filled: the
      /// command that made each fibre (0 fiber, 1 patch, 2 layer) and each
      /// command's sectionRepr object, by kind (opensees_tcl_sections.cc).
      struct FibrePrint
      {
        std::vector<int>                        kinds;
        std::array<std::vector<std::string>, 3> repr;
      } fibre_print;
      /// What print writes of each element and section (by tag).
      std::map<int, Printed> printed_elements, printed_sections;
      /// Which of OpenSees's node vectors exist, since Node::Print writes
      /// only those: displacements once an element held the node or an
      /// analysis step ran; velocities once a truss, corotTruss,
      /// zeroLength or twoNodeLink held it (they ask for them as they are
      /// made) or a transient step ran, accelerations then too. Kept
      /// through `remove element` and `wipeAnalysis`, as OpenSees's are.
      struct NodeVectors
      {
        std::set<int> displacements, velocities;
        bool          analysed = false, transient_analysed = false;
      } node_vectors;
      /// The files `print -file` has made in this run (device, inode): a
      /// later print appends to such a file in place; any other file at
      /// the path, an earlier run's, is replaced (opensees_tcl_print.cc).
      /// Kept through `wipe`, as OpenSees keeps appending after it.
      std::set<std::pair<unsigned long long, unsigned long long>> print_files;
      std::map<int, std::vector<double>>                   reactions; // of `reactions`
      opensees::AnalysisCounts                             counts;    // of earlier analyses
      /// The -mat tags of each zeroLength and twoNodeLink (their gap rows).
      std::map<int, std::vector<int>> link_materials;
      /// poundfe::energy and poundfe::impacts: the transient analyses' balance and
      /// contacts, while the script has them on (`poundfe::energy on`).
      std::optional<opensees::EnergyBalance> energy;
      std::optional<opensees::ScriptImpacts> impacts;
      /// What the observers' cached vectors were built for (begin_observing).
      std::vector<std::size_t> observed_model;
      /// poundfe::stepCutting's most halvings of a failed step (0: off).
      unsigned int max_cuts = 0;
      /// poundfe::locateEvents's most halvings of a step with a contact
      /// event (0: off) and the gaps it watches.
      unsigned int            event_levels = 0;
      opensees::ContactEvents contact_events;
      int            current_pattern = -1; // the Plain pattern whose body runs
      /// An error in a pattern's body where the file says it is (Tcl's
      /// errorInfo names the `pattern` line): its message, file and line.
      struct BodyError
      {
        std::string message, file;
        int         line;
      } body_error{"", "", 0};
      bool           exited          = false;
      int            exit_status     = 0;
      std::ostream  &warnings;

      /// Every recorder's file written and put in place (wipe, the
      /// script's end, remove recorders).
      void finish_recorders() { finish_recorders(0, recorders.size()); }
      /// Recorders first to last - 1 finished and removed, also when one
      /// fails (its error is then reported once): every temporary file is
      /// written out first, and the files are put in place only if none
      /// failed (those already in place are removed if one then fails).
      /// A write error, which the writer thread may have met after the
      /// script's last record, names the recorder and the time of the
      /// last line the failed write held.
      void finish_recorders(std::size_t first, std::size_t last);
      /// Every recorder records the committed state.
      void record();
    };

    /// The words of one command, read in order; each read names what it
    /// expected when the word is missing or not a number.
    class Words
    {
    public:
      Words(Tcl_Interp *interp, int objc, Tcl_Obj *const objv[]);
      bool        done() const { return next >= objc; }
      std::size_t left() const { return objc - next; }
      std::string word(const char *what);
      std::string peek() const;
      double      real(const char *what);
      int         integer(const char *what);
      /// The words from here up to the first that is not a number (an
      /// integer), as reals (integers).
      std::vector<double> numbers(const char *what);
      std::vector<int>    integers(const char *what);
      /// The command's name and sub-type ("element zeroLength").
      const std::string name;
      Tcl_Interp *const interp;

    private:
      int            objc, next = 1;
      Tcl_Obj *const *objv;
    };

    /// "<what>: poundfe does not support it" as a script error.
    [[noreturn]] void unsupported(const std::string &what);

    using Procedure = std::function<void(Session &, Words &)>;
    /// A Tcl command that runs `procedure`; a ScriptError or InputError it
    /// throws is the command's Tcl error, prefixed by the command's name.
    void define(Tcl_Interp *interp, Session &session, const std::string &name,
                Procedure procedure);

    /// The result of the running command.
    void set_result(Tcl_Interp *interp, double value);
    void set_result(Tcl_Interp *interp, const std::vector<double> &values);
    void set_result(Tcl_Interp *interp, const std::vector<int> &values);

    /// Adds the element; ScriptError when its tag exists already.
    ///
    /// made_undamped: OpenSees's `rayleigh` sets the factors of the nodes
    /// and elements that exist when it runs (Domain::setRayleighDampingFactors
    /// loops over them); a node or element made later keeps its
    /// constructor's zeros until the next `rayleigh` or `region -rayleigh`.
    /// Domain::rayleigh holds the last command's factors, so a node or
    /// element made after it gets zeros of its own (Domain::node_alpha_m,
    /// Domain::element_rayleigh), as one made again after `remove`.
    void add_element(opensees::Domain &d, std::unique_ptr<opensees::Element> element);
    /// Whether any of the four Rayleigh factors is nonzero.
    bool has_factors(const opensees::RayleighFactors &f);
    /// A member's mass per length rho, lumped: rho L/2 on each node's
    /// translations (OpenSees's beam-columns and truss without -cMass), as
    /// the element's (opensees::Domain::LumpedMass), its ground-motion load
    /// in the reactions.
    /// A beam-column's -cMass (opensees::beam_consistent_mass on geomTransf
    /// transf's axes; none when rho is 0), its ground-motion load in the
    /// reactions; refused on Corotational members and on nodes that have
    /// moved. Made before the element, so that a refusal leaves none.
    std::optional<opensees::Domain::ConsistentMass>
    consistent_beam_mass(const opensees::Domain &d, int element, const std::array<int, 2> &nodes,
                         double rho, double torsion_ratio, int transf, bool ground_load_twice);
    /// The member's mass: `mass` when given, else rho lumped (add_lumped_mass).
    void add_member_mass(opensees::Domain &d, int element, const std::array<int, 2> &nodes,
                         double rho, const std::optional<opensees::Domain::ConsistentMass> &mass);
    void add_lumped_mass(opensees::Domain &d, int element, const std::array<int, 2> &nodes,
                         double rho);
    /// m on each translation of both nodes, as the element's.
    void add_node_masses(opensees::Domain &d, int element, const std::array<int, 2> &nodes,
                         double m);
    /// element forceBeamColumn | nonlinearBeamColumn | dispBeamColumn (after
    /// the type).
    void beam_column_element(Session &session, Words &words, const std::string &type);

    /// The open Fiber section of OpenSeesPy's conventions made and added to
    /// the domain (nothing when none is open).
    void close_open_section(Session &session);

    /// Every command of a script (opensees_command.cc): the model, section
    /// and analysis commands, the OpenSees commands poundfe lacks (each
    /// refusing with its name), `exit` and the namespace poundfe::.
    void define_commands(Tcl_Interp *interp, Session &session);
    void define_model_commands(Tcl_Interp *interp, Session &session);
    void define_section_commands(Tcl_Interp *interp, Session &session);
    void define_analysis_commands(Tcl_Interp *interp, Session &session);
    /// region (opensees_tcl_regions.cc).
    void define_region_commands(Tcl_Interp *interp, Session &session);
    /// print and printModel (opensees_tcl_print.cc).
    void define_print_commands(Tcl_Interp *interp, Session &session);
    /// reset (opensees_tcl_domain.cc).
    void define_domain_commands(Tcl_Interp *interp, Session &session);
    void define_poundfe_commands(Tcl_Interp *interp, Session &session);
    /// poundfe::energy's and poundfe::impacts's start of a transient
    /// `analyze` and their committed step (nothing while both are off).
    void begin_observing(Session &session);
    /// poundfe::locateEvents's setting and gaps given to the analysis at
    /// the start of an `analyze`.
    void begin_locating(Session &session);
    void observe_step(Session &session);
    /// The observers that are on, started again (`reset`), or turned off
    /// (`wipe`).
    void restart_observers(Session &session);
    void stop_observers(Session &session);
    /// remove element | ele | node | sp | SPconstraint | timeSeries (after
    /// the word `what`); false for any other word.
    bool remove_model_object(Session &session, Words &words, const std::string &what);
  } // namespace opensees_tcl
} // namespace poundfe

#endif
