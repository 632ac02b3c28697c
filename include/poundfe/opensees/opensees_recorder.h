// OpenSees's Node and Element recorders: after each committed step, one
// line of the committed time (-time) and then each node's DOFs of one
// response (disp, vel, accel, reaction), or each element's values of one
// response (Element::response: force, localForce, basicForce,
// basicDeformation, section i force|deformation), separated by spaces,
// with -precision significant digits (6 by default), as OpenSees's
// DataFileStream writes them (setprecision(p): printf's %.pg, which
// std::to_chars gives in general format with precision p;
// write_precision_text below gives the same text faster). The file
// appears complete when the script ends (or at wipe), and not at all when
// it fails.
#ifndef poundfe_opensees_opensees_recorder_h
#define poundfe_opensees_opensees_recorder_h

#include <poundfe/opensees/opensees_domain.h>

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

    struct NodeRecorderSpec
    {
      std::string               file;
      bool                      time = false;
      std::vector<int>          nodes;
      std::vector<unsigned int> dofs; // 0-based
      enum class Response
      {
        disp,
        vel,
        accel,
        reaction
      } response    = Response::disp;
      int precision = 6;
    };

    /// A recorder's file: lines of numbers, written when the script ends.
    class Recorder
    {
    public:
      Recorder(const std::string &file, bool time, int precision);
      virtual ~Recorder();
      /// One line of the domain's committed state.
      void record(const Domain &domain);
      /// Writes the last lines and puts the file in place.
      void finish();

    protected:
      /// The line's values after the time.
      virtual void values(const Domain &domain, std::vector<double> &line) = 0;

    private:
      std::unique_ptr<AtomicFile> file;
      std::string                 buffer; // its first `used` characters are text
      std::size_t                 used = 0;
      std::vector<double>         line; // the values of one record, its storage kept
      bool                        time;
      int                         precision;
    };

    class NodeRecorder : public Recorder
    {
    public:
      explicit NodeRecorder(NodeRecorderSpec spec);

    private:
      void             values(const Domain &domain, std::vector<double> &line) override;
      NodeRecorderSpec spec;
      /// The nodes, found at the first record (nodes are never removed
      /// while a recorder lives: wipe finishes the recorders first).
      std::vector<const Node *> nodes;
    };

    struct ElementRecorderSpec
    {
      std::string              file;
      bool                     time = false;
      std::vector<int>         elements;
      std::vector<std::string> response; // OpenSees's words ("section", "1", "force")
      int                      precision = 6;
    };

    class ElementRecorder : public Recorder
    {
    public:
      explicit ElementRecorder(ElementRecorderSpec spec);

    private:
      void values(const Domain &domain, std::vector<double> &line) override;
      ElementRecorderSpec spec;
      /// Each element's response resolved at the first record
      /// (Element::response_reader), instead of its words matched at every
      /// step.
      std::vector<Element::ResponseReader> readers;
    };
  } // namespace opensees
} // namespace poundfe

#endif
