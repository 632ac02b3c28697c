// A small JSON builder for summary.json (objects, arrays, numbers, strings):
// in memory (str()), or streamed into an AtomicFile in blocks of about a
// megabyte, so that the summary of a model with a million hinges (75 MB of
// text for 660,000 hinges) is never whole in memory.
#ifndef poundfe_output_json_writer_h
#define poundfe_output_json_writer_h

#include <optional>
#include <string>
#include <vector>

namespace poundfe
{
  struct InputFile;
  class AtomicFile;

  class JsonWriter
  {
  public:
    /// In memory (str()), or with `file`, streamed into it (finish()).
    explicit JsonWriter(AtomicFile *file = nullptr)
      : file(file)
    {}

    JsonWriter &begin_object(const std::string &key = "");
    JsonWriter &end_object();
    JsonWriter &begin_array(const std::string &key = "");
    JsonWriter &end_array();
    JsonWriter &value(const std::string &key, double x);
    JsonWriter &value(const std::string &key, long x);
    JsonWriter &value(const std::string &key, unsigned long x) { return value(key, long(x)); }
    JsonWriter &value(const std::string &key, int x) { return value(key, long(x)); }
    JsonWriter &value(const std::string &key, unsigned int x) { return value(key, long(x)); }
    JsonWriter &value(const std::string &key, const std::string &x);
    JsonWriter &value(const std::string &key, const char *x) { return value(key, std::string(x)); }
    JsonWriter &value(const std::string &key, bool x);
    JsonWriter &value(const std::string &key, const std::vector<double> &x);
    JsonWriter &value(const std::string &key, const std::vector<std::string> &x);
    /// A list whose missing entries are null (a ratio that has no meaning).
    JsonWriter &value(const std::string &key, const std::vector<std::optional<double>> &x);

    std::string str() const { return text + "\n"; }
    /// Streamed: the rest of the text and the final newline into the file
    /// (the caller commits it).
    void finish();

  private:
    /// Before each value: the comma, the new line and its indentation, the
    /// key; a streamed text goes to its file when a block is full.
    void        prefix(const std::string &key);
    AtomicFile *file;
    std::string text;
    bool        started = false; // the root has begun
    std::vector<bool> first{true};
  };

  std::string json_escape(const std::string &s);

  /// Opens a command's summary.json with program, command, input (the
  /// parameter file) and status.
  void begin_summary(JsonWriter &json, const std::string &command, const InputFile &input,
                     const std::string &status = "completed");
} // namespace poundfe

#endif
