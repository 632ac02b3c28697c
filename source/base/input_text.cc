#include <poundfe/base/exceptions.h>
#include <poundfe/base/input_text.h>
#include <poundfe/base/content_digest.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

namespace poundfe
{
  void
  check_input_file(const std::string &file, const std::string &what, const std::string &parameter)
  {
    namespace fs = std::filesystem;
    std::error_code    error;
    const fs::file_type type = fs::status(file, error).type();
    const auto refuse = [&](const std::string &problem) {
      throw InputError(file, 0, parameter, problem);
    };
    if (type == fs::file_type::not_found)
      refuse("cannot open the " + what + " (no such file)");
    if (type == fs::file_type::directory)
      refuse("is a directory, not a " + what);
    // before opening: opening a FIFO waits for a writer, a device never ends
    if (type == fs::file_type::fifo)
      refuse("is a named pipe (FIFO), not a regular file: the " + what +
             " must be a file whose end can be known");
    if (type == fs::file_type::character || type == fs::file_type::block)
      refuse("is a device (like /dev/zero), not a regular file: the " + what +
             " must be a file whose end can be known");
    if (type != fs::file_type::regular)
      refuse("cannot open the " + what + " (" +
             (error ? error.message() : std::string("not a regular file")) + ")");
    const std::uintmax_t size = fs::file_size(file, error);
    if (!error && size > max_input_bytes)
      refuse("has " + std::to_string(size) + " bytes, more than the " +
             std::to_string(max_input_bytes) + " an input file may have");
  }

  std::string
  input_file_digest(const std::string &file)
  {
    try
      {
        check_input_file(file, "file");
      }
    catch (const InputError &e)
      {
        return "(" + e.problem() + ")";
      }
    // FNV-1a, 64 bits: no cryptographic claim, only that an edited file
    // (a value changed, a row added or removed) gives another number
    ContentDigest     digest;
    std::uintmax_t    size = 0;
    std::ifstream     in(file, std::ios::binary);
    std::vector<char> buffer(1 << 16);
    while (in.read(buffer.data(), buffer.size()) || in.gcount() > 0)
      {
        digest.add(buffer.data(), static_cast<std::size_t>(in.gcount()));
        size += in.gcount();
        if (size > max_input_bytes)
          return "(more than " + std::to_string(max_input_bytes) + " bytes)";
      }
    if (!in.eof())
      return "(cannot be read)";
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(digest.value()));
    return std::to_string(size) + " bytes, FNV-1a " + hex;
  }

  namespace
  {
    /// The bytes of a regular file, at most max_input_bytes of them (a file
    /// that grows while it is read is refused too).
    std::string
    read_bytes(const std::string &file, const std::string &what, const std::string &parameter)
    {
      check_input_file(file, what, parameter);
      std::ifstream in(file, std::ios::binary);
      if (!in)
        throw InputError(file, 0, parameter,
                         "cannot open the " + what + " (" + std::strerror(errno) + ")");
      std::string bytes;
      char        buffer[1 << 16];
      while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
        {
          bytes.append(buffer, in.gcount());
          if (bytes.size() > max_input_bytes)
            throw InputError(file, 0, parameter,
                             "more than the " + std::to_string(max_input_bytes) +
                               " bytes an input file may have");
        }
      if (in.bad())
        throw InputError(file, 0, parameter, "cannot read the " + what);
      return bytes;
    }

    /// Refuses a NUL byte (a binary file) and a line longer than
    /// max_line_length, naming the line.
    void
    check_text_lines(const std::string &file, const std::string &text, const std::string &what,
                     const std::string &parameter)
    {
      int line = 1;
      for (std::size_t start = 0; start <= text.size(); ++line)
        {
          std::size_t end = text.find('\n', start);
          if (end == std::string::npos)
            end = text.size();
          const std::size_t nul = text.find('\0', start);
          if (nul < end)
            throw InputError(file, line, parameter,
                             "a NUL byte (column " + std::to_string(nul - start + 1) +
                               "): a binary file, not a text " + what);
          if (end - start > max_line_length)
            throw InputError(file, line, parameter,
                             "a line of " + std::to_string(end - start) + " characters, more than "
                               "the " + std::to_string(max_line_length) + " a line may have");
          start = end + 1;
        }
    }
  } // namespace

  std::string
  read_input_text(const std::string &file, const std::string &what, const std::string &parameter)
  {
    std::string bytes = read_bytes(file, what, parameter);
    // a UTF-8 byte-order mark (spreadsheets write one) is not part of the text
    if (bytes.compare(0, 3, "\xEF\xBB\xBF") == 0)
      bytes.erase(0, 3);
    std::string text;
    text.reserve(bytes.size());
    for (std::size_t i = 0; i < bytes.size(); ++i)
      if (bytes[i] != '\r')
        text += bytes[i];
      else
        {
          // CRs before an LF belong to it (CR LF, and CR CR LF of files
          // converted twice); a CR alone (old Mac files) ends a line itself
          std::size_t last = i;
          while (last + 1 < bytes.size() && bytes[last + 1] == '\r')
            ++last;
          if (last + 1 < bytes.size() && bytes[last + 1] == '\n')
            i = last; // the LF comes next
          else
            text += '\n';
        }
    check_text_lines(file, text, what, parameter);
    return text;
  }

  namespace
  {
    bool
    is_blank(const char c)
    {
      return c == ' ' || c == '\t' || c == '\f' || c == '\v';
    }

    std::string
    trim(const std::string &s)
    {
      std::size_t first = 0, last = s.size();
      while (first < last && is_blank(s[first]))
        ++first;
      while (last > first && is_blank(s[last - 1]))
        --last;
      return s.substr(first, last - first);
    }

    /// `statement` starts with `keyword` (lower or upper case, as
    /// ParameterHandler accepts) followed by a blank or the end.
    bool
    starts_with_keyword(const std::string &statement, const std::string &keyword)
    {
      if (statement.size() < keyword.size())
        return false;
      bool lower = true, upper = true;
      for (std::size_t i = 0; i < keyword.size(); ++i)
        {
          lower = lower && statement[i] == keyword[i];
          upper = upper && statement[i] == std::toupper(static_cast<unsigned char>(keyword[i]));
        }
      return (lower || upper) &&
             (statement.size() == keyword.size() || is_blank(statement[keyword.size()]));
    }

    /// Where a statement of the file stands: the open subsections.
    struct Section
    {
      std::string name;
      int         line;
    };

    /// "A/B/" of the open sections.
    std::string
    path_of(const std::vector<Section> &sections)
    {
      std::string path;
      for (const Section &s : sections)
        path += s.name + "/";
      return path;
    }

    /// What the scan has seen: the sections entered (path -> line), the
    /// settings, the index of set lines.
    struct PrmScan
    {
      std::vector<Section>       sections;
      std::map<std::string, int> entered;
      unsigned int               n_settings = 0;
    };

    void
    scan_statement(const std::string &file, const std::string &statement, const int line,
                   PrmScan &scan, PrmText &prm)
    {
      std::vector<Section> &sections = scan.sections;
      if (starts_with_keyword(statement, "subsection"))
        {
          const std::string name = trim(statement.substr(10));
          if (name.empty())
            throw InputError(file, line, "", "'subsection' needs a name");
          const std::string path = path_of(sections) + name;
          // a second entry would silently overrule what the first set
          const auto [first, is_new] = scan.entered.emplace(path, line);
          if (!is_new)
            throw InputError(file, line, "",
                             "'subsection " + name + "' (" + path + ") is entered a second time; "
                             "the first is at line " + std::to_string(first->second) +
                             " (set its entries in one place)");
          sections.push_back({name, line});
        }
      else if (starts_with_keyword(statement, "end"))
        {
          if (sections.empty())
            throw InputError(file, line, "", "'end' without an open 'subsection'");
          sections.pop_back();
        }
      else if (starts_with_keyword(statement, "set"))
        {
          const std::size_t equals = statement.find('=');
          if (equals == std::string::npos)
            throw InputError(file, line, "", "'set' needs 'set <entry> = <value>'");
          const std::string path = path_of(sections) + trim(statement.substr(3, equals - 3));
          const auto [first, is_new] = prm.lines.emplace(path, line);
          if (!is_new)
            throw InputError(file, line, path,
                             "is set a second time; the first is at line " +
                               std::to_string(first->second) + " (the last would win silently)");
          ++scan.n_settings;
        }
      else if (starts_with_keyword(statement, "include"))
        ++scan.n_settings;
      // anything else: ParameterHandler names the line
    }
  } // namespace

  PrmText
  prepare_prm_text(const std::string &file, const std::string &text)
  {
    PrmText     prm;
    PrmScan     scan;
    std::string statement; // continued lines joined
    int                  statement_line = 0;
    int                  line           = 0;
    prm.text.reserve(text.size());
    for (std::size_t start = 0; start < text.size();)
      {
        ++line;
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos)
          end = text.size();
        std::string content = text.substr(start, end - start);
        start               = end + 1;
        const std::size_t hash = content.find('#');
        if (hash != std::string::npos)
          content.erase(hash);
        content = trim(content);
        prm.text += content;
        prm.text += '\n';
        if (statement.empty())
          statement_line = line;
        const bool continued = !content.empty() && content.back() == '\\';
        statement += continued ? content.substr(0, content.size() - 1) : content;
        if (continued)
          continue;
        statement = trim(statement);
        if (!statement.empty())
          scan_statement(file, statement, statement_line, scan, prm);
        statement.clear();
      }
    if (!trim(statement).empty())
      throw InputError(file, statement_line, "",
                       "the last line ends in '\\' (continued) but no line follows");
    if (!scan.sections.empty())
      throw InputError(file, scan.sections.back().line, "",
                       "'subsection " + scan.sections.back().name + "' is never closed by 'end'");
    if (scan.n_settings == 0)
      throw InputError(file, 0, "",
                       "the file sets no parameter (it is empty or all comments); refused "
                       "rather than running the built-in default model");
    return prm;
  }

  namespace
  {
    /// The brackets and keys of a JSON text outside its strings, scanned
    /// character by character by check_json_structure().
    class JsonStructureScan
    {
    public:
      JsonStructureScan(const std::string &file, const std::string &parameter)
        : file(file)
        , parameter(parameter)
      {}

      /// A character outside the strings at `line`; `last_string` is the
      /// string before it (a key if `c` is ':').
      void
      take(const char c, const int line, const std::string &last_string)
      {
        if (c == ':' && !open.empty() && open.back().close == '}')
          {
            // a key given twice: boost's reader keeps both, readers take one
            const auto [first, is_new] = open.back().keys.emplace(last_string, line);
            if (!is_new)
              throw InputError(file, line, parameter,
                               "the key \"" + last_string.substr(0, 80) +
                                 "\" appears a second time in one object; the first is at line " +
                                 std::to_string(first->second));
          }
        else if (c == '{' || c == '[')
          {
            open.push_back({c == '{' ? '}' : ']', {}});
            if (open.size() > max_json_depth)
              throw InputError(file, line, parameter,
                               "nested more than " + std::to_string(max_json_depth) +
                                 " levels deep");
          }
        else if (c == '}' || c == ']')
          {
            if (open.empty() || open.back().close != c)
              throw InputError(file, line, parameter, std::string("unexpected '") + c + "'");
            open.pop_back();
          }
      }

      /// Whether an object or an array is still open.
      bool
      inside() const
      {
        return !open.empty();
      }

    private:
      /// An open object or array: its closing bracket, an object's keys (key -> line).
      struct Level
      {
        char                       close;
        std::map<std::string, int> keys;
      };
      const std::string &file;
      const std::string &parameter;
      std::vector<Level> open;
    };
  } // namespace

  void
  check_json_structure(const std::string &file, const std::string &text,
                       const std::string &parameter)
  {
    int               line      = 1;
    bool              in_string = false, escaped = false;
    std::size_t       string_start = 0;
    std::string       last_string; // a key if ':' follows it
    JsonStructureScan scan(file, parameter);
    for (std::size_t i = 0; i < text.size(); ++i)
      {
        const char c = text[i];
        if (c == '\n')
          ++line;
        if (in_string)
          {
            if (escaped)
              escaped = false;
            else if (c == '\\')
              escaped = true;
            else if (c == '"')
              {
                in_string   = false;
                last_string = text.substr(string_start, i - string_start);
              }
            continue;
          }
        if (c == '"')
          in_string = true, string_start = i + 1;
        else
          scan.take(c, line, last_string);
      }
    if (in_string || scan.inside())
      throw InputError(file, line, parameter,
                       "the file ends inside a string or an open '{' or '['");
  }

  std::string
  read_json_text(const std::string &file, const std::string &what, const std::string &parameter)
  {
    std::string text = read_input_text(file, what, parameter);
    check_json_structure(file, text, parameter);
    return text;
  }

  void
  check_json_text(const std::string &file, const std::string &text)
  {
    const std::size_t first = text.find_first_not_of(" \t\n\r");
    if (first == std::string::npos)
      throw InputError(file, 0, "",
                       "the file sets no parameter (it is empty); refused rather than running "
                       "the built-in default model");
    const int line = 1 + std::count(text.begin(), text.begin() + first, '\n');
    if (text[first] != '{')
      throw InputError(file, line, "",
                       "a JSON parameter file is an object { \"Section\": { ... } }, not '" +
                         text.substr(first, std::min(text.find_first_of("\n\r", first),
                                                     first + 16) - first) + "'");
    const std::size_t next = text.find_first_not_of(" \t\n\r", first + 1);
    if (next != std::string::npos && text[next] == '}')
      throw InputError(file, line, "",
                       "the file sets no parameter (an empty object); refused rather than "
                       "running the built-in default model");
    check_json_structure(file, text);
  }
} // namespace poundfe
