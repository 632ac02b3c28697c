// OpenSees's Node recorder (NodeRecorder.cpp, DataFileStream.cpp: values
// streamed with setprecision(p), separated by " ", one line per record).
#include <poundfe/opensees/opensees_recorder.h>
#include <poundfe/output/atomic_file.h>

#include <sstream>

namespace poundfe
{
  namespace opensees
  {
    NodeRecorder::NodeRecorder(NodeRecorderSpec s)
      : spec(std::move(s))
      , file(std::make_unique<AtomicFile>(spec.file))
    {}

    NodeRecorder::~NodeRecorder() = default;

    void
    NodeRecorder::record(const Domain &domain)
    {
      using Response = NodeRecorderSpec::Response;
      std::map<int, std::vector<double>> reactions;
      if (spec.response == Response::reaction)
        reactions = domain.reactions();
      std::ostringstream line;
      line.precision(spec.precision);
      bool first = true;
      auto put   = [&](const double value) {
        line << (first ? "" : " ") << value;
        first = false;
      };
      if (spec.time)
        put(domain.time);
      for (const int tag : spec.nodes)
        {
          const Node &node = domain.node(tag);
          for (const unsigned int k : spec.dofs)
            switch (spec.response)
              {
                case Response::disp:
                  put(node.disp.at(k));
                  break;
                case Response::vel:
                  put(node.vel.at(k));
                  break;
                case Response::accel:
                  put(node.accel.at(k));
                  break;
                case Response::reaction:
                  put(reactions.at(tag).at(k));
                  break;
              }
        }
      buffer += line.str() + "\n";
      if (buffer.size() > (1u << 16))
        {
          file->write(buffer);
          buffer.clear();
        }
    }

    void
    NodeRecorder::finish()
    {
      if (!file)
        return;
      file->write(buffer);
      buffer.clear();
      file->commit();
      file.reset();
    }
  } // namespace opensees
} // namespace poundfe
