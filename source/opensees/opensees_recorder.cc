// OpenSees's Node and Element recorders (NodeRecorder.cpp,
// ElementRecorder.cpp, DataFileStream.cpp: values streamed with
// setprecision(p), separated by " ", one line per record).
#include <poundfe/opensees/opensees_recorder.h>
#include <poundfe/output/atomic_file.h>

#include <charconv>

namespace poundfe
{
  namespace opensees
  {
    namespace
    {
      /// The text a recorder keeps before it writes to its file.
      constexpr std::size_t flush_size = 1u << 16;
    } // namespace

    Recorder::Recorder(const std::string &file_name, const bool with_time, const int digits)
      : file(std::make_unique<AtomicFile>(file_name))
      , time(with_time)
      , precision(digits < 0 ? 6 : digits) // as the stream's precision
    {
      buffer.reserve(2 * flush_size);
    }

    Recorder::~Recorder() = default;

    void
    Recorder::record(const Domain &domain)
    {
      line.clear();
      if (time)
        line.push_back(domain.time);
      values(domain, line);
      // room for each number: sign, the digits, the point and an exponent
      const std::size_t start = buffer.size(), room = precision + 16;
      buffer.resize(start + line.size() * room + 1);
      char *const end = buffer.data() + buffer.size();
      char       *out = buffer.data() + start;
      for (std::size_t i = 0; i < line.size(); ++i)
        {
          if (i > 0)
            *out++ = ' ';
          out = std::to_chars(out, end, line[i], std::chars_format::general, precision).ptr;
        }
      *out++ = '\n';
      buffer.resize(out - buffer.data());
      if (buffer.size() > flush_size)
        {
          file->write(buffer);
          buffer.clear();
        }
    }

    void
    Recorder::finish()
    {
      if (!file)
        return;
      file->write(buffer);
      buffer.clear();
      file->commit();
      file.reset();
    }

    NodeRecorder::NodeRecorder(NodeRecorderSpec s)
      : Recorder(s.file, s.time, s.precision)
      , spec(std::move(s))
    {}

    void
    NodeRecorder::values(const Domain &domain, std::vector<double> &line) const
    {
      using Response = NodeRecorderSpec::Response;
      std::map<int, std::vector<double>> reactions;
      if (spec.response == Response::reaction)
        reactions = domain.reactions();
      for (const int tag : spec.nodes)
        {
          const Node &node = domain.node(tag);
          for (const unsigned int k : spec.dofs)
            switch (spec.response)
              {
                case Response::disp:
                  line.push_back(node.disp.at(k));
                  break;
                case Response::vel:
                  line.push_back(node.vel.at(k));
                  break;
                case Response::accel:
                  line.push_back(node.accel.at(k));
                  break;
                case Response::reaction:
                  line.push_back(reactions.at(tag).at(k));
                  break;
              }
        }
    }

    ElementRecorder::ElementRecorder(ElementRecorderSpec s)
      : Recorder(s.file, s.time, s.precision)
      , spec(std::move(s))
    {}

    void
    ElementRecorder::values(const Domain &domain, std::vector<double> &line) const
    {
      for (const int tag : spec.elements)
        {
          const std::vector<double> v = domain.elements.at(tag)->response(spec.response);
          line.insert(line.end(), v.begin(), v.end());
        }
    }
  } // namespace opensees
} // namespace poundfe
