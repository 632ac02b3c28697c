// A small JSON builder for summary.json (objects, arrays, numbers, strings).
#ifndef poundfe_output_json_writer_h
#define poundfe_output_json_writer_h

#include <string>
#include <vector>

namespace poundfe
{
  struct InputFile;

  class JsonWriter
  {
  public:
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

    std::string str() const { return text + "\n"; }

  private:
    void        prefix(const std::string &key);
    std::string text;
    std::vector<bool> first{true};
  };

  std::string json_escape(const std::string &s);

  /// Opens a command's summary.json with program, command, input (the
  /// parameter file) and status.
  void begin_summary(JsonWriter &json, const std::string &command, const InputFile &input,
                     const std::string &status = "completed");
} // namespace poundfe

#endif
