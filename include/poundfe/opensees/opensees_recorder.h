// OpenSees's Node, Element and Drift recorders: after each committed step
// (or, with -dT, each step at least dT after the last record), one
// line of the committed time (-time) and then each node's DOFs of one
// response (disp, vel, accel, reaction), or each element's values of one
// response (Element::response: force, localForce, basicForce,
// basicDeformation, section i force|deformation), separated by spaces,
// with -precision significant digits (6 by default), as OpenSees's
// DataFileStream writes them (setprecision(p): printf's %.pg, which
// std::to_chars gives in general format with precision p;
// write_precision_text below gives the same text faster). The file
// appears complete when the script ends (or at wipe), and not at all when
// it fails. The Envelope recorders keep each value's extremes and write
// three rows when they finish. Given a writer thread (set_queue,
// output/output_queue.h), a recorder hands each line's doubles to it and
// the text is made and written there: the same bytes.
#ifndef poundfe_opensees_opensees_recorder_h
#define poundfe_opensees_opensees_recorder_h

#include <poundfe/opensees/opensees_domain.h>
#include <poundfe/output/output_queue.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  class AtomicFile;

  namespace opensees
  {
    /// The room write_precision_text needs after `out` for precision p.
    constexpr std::size_t
    precision_text_room(const int precision)
    {
      return static_cast<std::size_t>(precision > 0 ? precision : 6) + 16;
    }

    /// Writes x as printf's %.{precision}g at `out` (precision_text_room
    /// characters of room) and returns the end of the text: x correctly
    /// rounded to p significant digits, trailing zeros removed, fixed
    /// notation when its decimal exponent X (after the rounding) has
    /// -4 <= X < p, scientific (d.ddde-05) otherwise. std::to_chars(general,
    /// p) gives that text (Ryu printf, some 600 instructions a number); the
    /// short path here writes |x| = m 2^e times 10^(p-1-X) = m 5^q 2^(e+q)
    /// as a quotient of 128-bit integers, whose integer part and remainder
    /// give the p digits and the rounding exactly. Ties, and all the short
    /// path does not cover (p outside 1 to 17, |q| > 27, subnormals,
    /// infinities, NaN), go to std::to_chars.
    char *write_precision_text(char *out, double x, int precision);

    /// What every recorder's output takes: -file, -time, -precision, and
    /// when it records (-dT, -rTolDt: OpenSees's deltaT and relDeltaTTol).
    struct OutputSpec
    {
      std::string file;
      bool        time      = false;
      int         precision = 6;
      double      interval  = 0;    // -dT: 0 records at every commit
      double      interval_tolerance = 1e-5; // -rTolDt
    };

    struct NodeRecorderSpec : OutputSpec
    {
      std::vector<int>          nodes;
      std::vector<unsigned int> dofs; // 0-based
      enum class Response
      {
        disp,
        vel,
        accel,
        reaction
      } response = Response::disp;
      /// -timeSeries: a series for each DOF (or none) whose factor at the
      /// time is added to the value (absolute accelerations).
      std::vector<std::shared_ptr<const TimeSeries>> series;
    };

    /// A recorder's file: lines of numbers, written when the script ends.
    class Recorder : public OutputQueue::Sink
    {
    public:
      explicit Recorder(const OutputSpec &output);
      /// Its lines pushed reach the file's text before it goes.
      ~Recorder() override;
      /// Its lines formatted and written on `queue`'s thread from now on.
      void set_queue(std::shared_ptr<OutputQueue> queue);
      /// One line of the domain's committed state, when it is due.
      virtual void record(const Domain &domain);
      /// Writes the last lines into its temporary file: the first half of
      /// finishing, where a write error is met before any file of the
      /// script is put in place (opensees_tcl.h, Session::finish_recorders).
      virtual void write_out();
      /// The second half: the file written out put in place (none when
      /// write_out wrote none, as a Drift recorder without pairs).
      void put_in_place();
      /// The path of its file once put in place, else empty.
      std::string placed_path() const;
      /// `reset` (OpenSees's Recorder::restart): the Envelope recorders
      /// start their extremes again; the others go on.
      virtual void restart() {}
      /// Whether it records the node or the element (`remove node`,
      /// `remove element` refuse what a recorder records).
      virtual bool records_node(int /*tag*/) const { return false; }
      virtual bool records_element(int /*tag*/) const { return false; }
      /// The analysis time of the last line given to the file's text: after
      /// a write error, of the last line the failed write held (found on
      /// the writer thread, the error may surface at a later command).
      double last_line_time() const { return text_time; }

    protected:
      /// The line's values after the time.
      virtual void values(const Domain &domain, std::vector<double> &line) = 0;
      /// Whether a record at `time` is due (OpenSees's recorders: always
      /// without -dT, else when time - next >= -dT rTolDt, the next then
      /// time + dT), and the next due time moved on if so.
      bool due(double time);
      /// One line of numbers, recorded at analysis time `at`, into the
      /// file's text (through the queue, if any).
      void write_line(double at, const std::vector<double> &numbers);
      const bool time;
      /// The time of the last record that was due.
      double recorded_time = 0;

    private:
      /// A queued line: its time, then its `n - 1` numbers (append_text).
      void consume(const double *numbers, std::size_t n) override;
      /// The text of one line of `n` numbers, written out when enough.
      void append_text(const double *numbers, std::size_t n, double at);

      std::shared_ptr<OutputQueue> queue; // none: inline
      std::unique_ptr<AtomicFile>  file;
      std::string                 buffer; // its first `used` characters are text
      std::size_t                 used = 0;
      std::vector<double>         line; // the values of one record, its storage kept
      int                         precision;
      double                      interval, interval_tolerance, next_time = 0;
      double                      text_time = 0; // last_line_time()
      bool                        written_out = false, placed = false;
    };

    class NodeRecorder : public Recorder
    {
    public:
      using Spec = NodeRecorderSpec;
      explicit NodeRecorder(NodeRecorderSpec spec);
      bool records_node(const int tag) const override
      {
        return std::find(spec.nodes.begin(), spec.nodes.end(), tag) != spec.nodes.end();
      }

    protected:
      void             values(const Domain &domain, std::vector<double> &line) override;
      NodeRecorderSpec spec;
      /// The nodes, found at the first record (nodes are never removed
      /// while a recorder lives: wipe finishes the recorders first).
      std::vector<const Node *> nodes;
    };

    struct ElementRecorderSpec : OutputSpec
    {
      std::vector<int>         elements;
      std::vector<std::string> response; // OpenSees's words ("section", "1", "force")
    };

    class ElementRecorder : public Recorder
    {
    public:
      using Spec = ElementRecorderSpec;
      explicit ElementRecorder(ElementRecorderSpec spec);
      bool records_element(const int tag) const override
      {
        return std::find(spec.elements.begin(), spec.elements.end(), tag) != spec.elements.end();
      }

    protected:
      void values(const Domain &domain, std::vector<double> &line) override;
      ElementRecorderSpec spec;
      /// Each element's response resolved at the first record
      /// (Element::response_reader), instead of its words matched at every
      /// step.
      std::vector<Element::ResponseReader> readers;
    };

    /// recorder Drift (DriftRecorder.cpp): for each pair of nodes i, j whose
    /// coordinates differ along perpDirn, (u_j - u_i) / |x_j - x_i| along
    /// -dof, after the time (the domain's) with -time; a pair at the same
    /// coordinate is left out, as OpenSees leaves it.
    struct DriftRecorderSpec : OutputSpec
    {
      std::vector<int> i_nodes, j_nodes;
      unsigned int     dof = 0, perpendicular = 1; // 0-based
    };

    class DriftRecorder : public Recorder
    {
    public:
      DriftRecorder(DriftRecorderSpec spec, const Domain &domain);
      bool records_node(const int tag) const override
      {
        for (const auto &pair : pairs)
          if (pair[0] == tag || pair[1] == tag)
            return true;
        return false;
      }
      /// With no pair kept, nothing: no file, as OpenSees's.
      void record(const Domain &domain) override;
      void write_out() override;
      bool has_pairs() const { return !pairs.empty(); }

    private:
      void values(const Domain &domain, std::vector<double> &line) override;
      /// The pairs kept, each with 1 / its length.
      std::vector<std::array<int, 2>> pairs;
      std::vector<double>             inverse_lengths;
      unsigned int                    dof;
    };

    /// recorder EnvelopeNode and EnvelopeElement (EnvelopeNodeRecorder.cpp,
    /// EnvelopeElementRecorder.cpp): the values of a Node or Element
    /// recorder at each record that is due, kept as three rows, the least,
    /// the largest and the largest magnitude of each, written when the
    /// recorder finishes (the script's end, wipe, remove recorders); with
    /// -time each value is preceded by the time it was reached (of the
    /// magnitude: the time it last grew).
    template <typename Values>
    class EnvelopeRecorder : public Values
    {
    public:
      explicit EnvelopeRecorder(typename Values::Spec spec);
      void record(const Domain &domain) override;
      void write_out() override;
      void restart() override { first = true; }

    private:
      std::vector<double> current;
      /// Rows min, max, max |.|: value k at 2k + 1 after its time with
      /// -time, else at k.
      std::array<std::vector<double>, 3> rows;
      bool                               first = true;
    };
    using EnvelopeNodeRecorder    = EnvelopeRecorder<NodeRecorder>;
    using EnvelopeElementRecorder = EnvelopeRecorder<ElementRecorder>;
  } // namespace opensees
} // namespace poundfe

#endif
