#include <poundfe/base/exceptions.h>
#include <poundfe/base/input_text.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

namespace poundfe
{
  std::string
  read_input_text(const std::string &file, const std::string &what)
  {
    std::error_code error;
    if (std::filesystem::is_directory(file, error))
      throw InputError(file, 0, "", "is a directory, not a " + what);
    std::ifstream in(file, std::ios::binary);
    if (!in)
      throw InputError(file, 0, "", "cannot open the " + what);
    const std::string bytes{std::istreambuf_iterator<char>(in), {}};
    if (in.bad())
      throw InputError(file, 0, "", "cannot read the " + what);
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

    void
    scan_statement(const std::string &file, const std::string &statement, const int line,
                   std::vector<Section> &sections, PrmText &prm, unsigned int &n_settings)
    {
      if (starts_with_keyword(statement, "subsection"))
        {
          const std::string name = trim(statement.substr(10));
          if (name.empty())
            throw InputError(file, line, "", "'subsection' needs a name");
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
          std::string path;
          for (const Section &s : sections)
            path += s.name + "/";
          prm.lines[path + trim(statement.substr(3, equals - 3))] = line;
          ++n_settings;
        }
      else if (starts_with_keyword(statement, "include"))
        ++n_settings;
      // anything else: ParameterHandler names the line
    }
  } // namespace

  PrmText
  prepare_prm_text(const std::string &file, const std::string &text)
  {
    PrmText              prm;
    std::vector<Section> sections;
    unsigned int         n_settings = 0;
    std::string          statement; // continued lines joined
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
          scan_statement(file, statement, statement_line, sections, prm, n_settings);
        statement.clear();
      }
    if (!trim(statement).empty())
      throw InputError(file, statement_line, "",
                       "the last line ends in '\\' (continued) but no line follows");
    if (!sections.empty())
      throw InputError(file, sections.back().line, "",
                       "'subsection " + sections.back().name + "' is never closed by 'end'");
    if (n_settings == 0)
      throw InputError(file, 0, "",
                       "the file sets no parameter (it is empty or all comments); refused "
                       "rather than running the built-in default model");
    return prm;
  }

  void
  check_json_text(const std::string &file, const std::string &text)
  {
    int                line  = 1;
    unsigned int       depth = 0;
    bool               in_string = false, escaped = false, first = true;
    std::vector<char>  open; // the closing bracket each level expects
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
              in_string = false;
            continue;
          }
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r')
          continue;
        if (first)
          {
            std::size_t next = text.find_first_not_of(" \t\n\r", i + 1);
            if (c != '{')
              throw InputError(file, line, "",
                               "a JSON parameter file is an object { \"Section\": { ... } }, "
                               "not '" + text.substr(i, std::min(text.find_first_of("\n\r", i), i + 16) - i) + "'");
            if (next != std::string::npos && text[next] == '}')
              throw InputError(file, line, "",
                               "the file sets no parameter (an empty object); refused rather "
                               "than running the built-in default model");
            first = false;
          }
        if (c == '"')
          in_string = true;
        else if (c == '{' || c == '[')
          {
            open.push_back(c == '{' ? '}' : ']');
            if (++depth > max_json_depth)
              throw InputError(file, line, "",
                               "nested more than " + std::to_string(max_json_depth) +
                                 " levels deep");
          }
        else if (c == '}' || c == ']')
          {
            if (open.empty() || open.back() != c)
              throw InputError(file, line, "", std::string("unexpected '") + c + "'");
            open.pop_back();
            --depth;
          }
      }
    if (first)
      throw InputError(file, 0, "",
                       "the file sets no parameter (it is empty); refused rather than running "
                       "the built-in default model");
    if (in_string || !open.empty())
      throw InputError(file, line, "", "the file ends inside a string or an open '{' or '['");
  }
} // namespace poundfe
