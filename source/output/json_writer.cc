#include <poundfe/output/atomic_file.h>
#include <poundfe/output/finite_output.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/base/input_file.h>

#include <deal.II/base/exceptions.h>

#include <charconv>
#include <cmath>

namespace poundfe
{
  namespace
  {
    /// `x` as JSON; NaN is null ("not defined"), an infinity a numerical
    /// failure (output/finite_output.h).
    std::string
    number(const double x, const std::string &key)
    {
      if (std::isinf(x))
        throw_not_finite(x, key, "summary.json");
      if (std::isnan(x))
        return "null";
      char buffer[32];
      return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, x).ptr);
    }
  } // namespace

  std::string
  json_escape(const std::string &s)
  {
    std::string out = "\"";
    for (const char c : s)
      switch (c)
        {
          case '"':
            out += "\\\"";
            break;
          case '\\':
            out += "\\\\";
            break;
          case '\n':
            out += "\\n";
            break;
          default:
            out += c;
        }
    return out + "\"";
  }

  void
  JsonWriter::prefix(const std::string &key)
  {
    constexpr std::size_t block = std::size_t(1) << 20;
    if (file && text.size() >= block)
      {
        file->write(text);
        text.clear(); // its capacity kept: one block's memory for the whole file
      }
    if (!first.back())
      text += ",";
    first.back() = false;
    text += "\n" + std::string(2 * (first.size() - 1), ' ');
    if (!key.empty())
      text += json_escape(key) + ": ";
  }

  JsonWriter &
  JsonWriter::begin_object(const std::string &key)
  {
    if (started)
      prefix(key);
    started = true;
    text += "{";
    first.push_back(true);
    return *this;
  }

  JsonWriter &
  JsonWriter::end_object()
  {
    first.pop_back();
    text += "\n" + std::string(2 * (first.size() - 1), ' ') + "}";
    return *this;
  }

  JsonWriter &
  JsonWriter::begin_array(const std::string &key)
  {
    prefix(key);
    text += "[";
    first.push_back(true);
    return *this;
  }

  JsonWriter &
  JsonWriter::end_array()
  {
    first.pop_back();
    text += "\n" + std::string(2 * (first.size() - 1), ' ') + "]";
    return *this;
  }

  JsonWriter &
  JsonWriter::value(const std::string &key, const double x)
  {
    prefix(key);
    text += number(x, key);
    return *this;
  }

  JsonWriter &
  JsonWriter::value(const std::string &key, const long x)
  {
    prefix(key);
    text += std::to_string(x);
    return *this;
  }

  JsonWriter &
  JsonWriter::value(const std::string &key, const std::string &x)
  {
    prefix(key);
    text += json_escape(x);
    return *this;
  }

  JsonWriter &
  JsonWriter::value(const std::string &key, const bool x)
  {
    prefix(key);
    text += x ? "true" : "false";
    return *this;
  }

  JsonWriter &
  JsonWriter::value(const std::string &key, const std::vector<double> &x)
  {
    prefix(key);
    text += "[";
    for (std::size_t i = 0; i < x.size(); ++i)
      text += (i ? ", " : "") + number(x[i], key);
    text += "]";
    return *this;
  }

  JsonWriter &
  JsonWriter::value(const std::string &key, const std::vector<std::optional<double>> &x)
  {
    prefix(key);
    text += "[";
    for (std::size_t i = 0; i < x.size(); ++i)
      text += (i ? ", " : "") + (x[i] ? number(*x[i], key) : std::string("null"));
    text += "]";
    return *this;
  }

  JsonWriter &
  JsonWriter::value(const std::string &key, const std::vector<std::string> &x)
  {
    prefix(key);
    text += "[";
    for (std::size_t i = 0; i < x.size(); ++i)
      text += (i ? ", " : "") + json_escape(x[i]);
    text += "]";
    return *this;
  }

  void
  JsonWriter::finish()
  {
    Assert(file, dealii::ExcMessage("finish() is for a streamed text"));
    text += "\n";
    file->write(text);
    text.clear();
  }

  void
  begin_summary(JsonWriter &json, const std::string &command, const InputFile &input,
                const std::string &status)
  {
    json.begin_object()
      .value("program", "poundfe")
      .value("command", command)
      .value("input", input.file)
      .value("status", status);
  }
} // namespace poundfe
