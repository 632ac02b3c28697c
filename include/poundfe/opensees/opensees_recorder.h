// OpenSees's Node recorder: after each committed step, one line of the
// committed time (-time) and each node's DOFs of one response (disp, vel,
// accel, reaction), separated by spaces, with -precision significant digits
// (6 by default), as OpenSees's DataFileStream writes them. The file appears
// complete when the script ends (or at wipe), and not at all when it fails.
#ifndef poundfe_opensees_opensees_recorder_h
#define poundfe_opensees_opensees_recorder_h

#include <poundfe/opensees/opensees_domain.h>

#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  class AtomicFile;

  namespace opensees
  {
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

    class NodeRecorder
    {
    public:
      explicit NodeRecorder(NodeRecorderSpec spec);
      ~NodeRecorder();
      /// One line of the domain's committed state.
      void record(const Domain &domain);
      /// Writes the last lines and puts the file in place.
      void finish();

    private:
      NodeRecorderSpec            spec;
      std::unique_ptr<AtomicFile> file;
      std::string                 buffer;
    };
  } // namespace opensees
} // namespace poundfe

#endif
