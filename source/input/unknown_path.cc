// The reader's words for a path that names nothing declared (unknown_path.h).
#include <poundfe/input/unknown_path.h>

#include <algorithm>
#include <cctype>
#include <set>

namespace poundfe
{
  std::size_t
  edit_distance(const std::string &a, const std::string &b)
  {
    const auto same = [](const char x, const char y) {
      return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
    };
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
      row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
      {
        std::size_t diagonal = row[0];
        row[0]               = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
          {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same(a[i - 1], b[j - 1]) ? 0 : 1)});
            diagonal = above;
          }
      }
    return row[b.size()];
  }

  namespace
  {
    /// The names declared right under `section` ("" for the top), entries
    /// when `entries`, subsections otherwise, in declaration order.
    std::vector<std::string>
    names_under(const std::vector<std::string> &declared, const std::string &section,
                const bool entries)
    {
      const std::string      prefix = section.empty() ? "" : section + "/";
      std::vector<std::string> names;
      for (const std::string &path : declared)
        if (path.size() > prefix.size() && path.compare(0, prefix.size(), prefix) == 0)
          {
            const std::string rest  = path.substr(prefix.size());
            const std::size_t slash = rest.find('/');
            if ((slash == std::string::npos) == entries)
              {
                const std::string name = rest.substr(0, slash);
                if (std::find(names.begin(), names.end(), name) == names.end())
                  names.push_back(name);
              }
          }
      return names;
    }

    /// Up to three of `names` closest to `written` (see the header).
    std::vector<std::string>
    closest(const std::vector<std::string> &names, const std::string &written)
    {
      const std::size_t                                limit = std::max<std::size_t>(1, written.size() / 3);
      std::vector<std::pair<std::size_t, std::size_t>> near; // (distance, index)
      for (std::size_t i = 0; i < names.size(); ++i)
        if (const std::size_t d = edit_distance(names[i], written); d <= limit)
          near.emplace_back(d, i);
      std::stable_sort(near.begin(), near.end());
      std::vector<std::string> chosen;
      for (std::size_t k = 0; k < near.size() && k < 3; ++k)
        chosen.push_back(names[near[k].second]);
      return chosen;
    }

    /// Paths (at most three) of the entries named `entry` in any subsection.
    std::vector<std::string>
    same_name_elsewhere(const std::vector<std::string> &declared, const std::string &entry)
    {
      std::vector<std::string> paths;
      for (const std::string &path : declared)
        {
          const std::size_t slash = path.rfind('/');
          const std::string name  = slash == std::string::npos ? path : path.substr(slash + 1);
          if (paths.size() < 3 && edit_distance(name, entry) == 0)
            paths.push_back(path);
        }
      return paths;
    }

    std::string
    did_you_mean(const std::vector<std::string> &candidates)
    {
      if (candidates.empty())
        return "";
      std::string text = " (did you mean ";
      for (std::size_t i = 0; i < candidates.size(); ++i)
        text += (i == 0 ? "" : i + 1 == candidates.size() ? " or " : ", ") + ("'" + candidates[i] + "'");
      return text + "?)";
    }

    /// The longest leading part of `sections` (joined by '/') that is
    /// declared, and how many of them it holds.
    std::size_t
    declared_depth(const std::vector<std::string> &declared, const std::vector<std::string> &sections)
    {
      std::string prefix;
      for (std::size_t k = 0; k < sections.size(); ++k)
        {
          prefix += sections[k] + "/";
          const bool found = std::any_of(declared.begin(), declared.end(), [&](const std::string &p) {
            return p.compare(0, prefix.size(), prefix) == 0;
          });
          if (!found)
            return k;
        }
      return sections.size();
    }
  } // namespace

  std::string
  unknown_path_problem(const std::vector<std::string> &declared, const std::string &path,
                       const bool names_subsection)
  {
    std::vector<std::string> parts;
    for (std::size_t start = 0;;)
      {
        const std::size_t slash = path.find('/', start);
        parts.push_back(path.substr(start, slash - start));
        if (slash == std::string::npos)
          break;
        start = slash + 1;
      }
    const std::string entry = names_subsection ? "" : parts.back();
    if (!names_subsection)
      parts.pop_back();
    const std::size_t depth = declared_depth(declared, parts);
    std::string       parent;
    for (std::size_t k = 0; k < depth; ++k)
      parent += (k == 0 ? "" : "/") + parts[k];
    if (depth < parts.size()) // a subsection that is not declared
      {
        std::string missing = parent;
        for (std::size_t k = depth; k < parts.size(); ++k)
          missing += (missing.empty() ? "" : "/") + parts[k];
        return "There is no such subsection to be entered: " + missing +
               did_you_mean(closest(names_under(declared, parent, false), parts[depth]));
      }
    std::vector<std::string> candidates = closest(names_under(declared, parent, true), entry);
    if (candidates.empty())
      candidates = same_name_elsewhere(declared, entry);
    return "No entry with name <" + entry + "> in " +
           (parent.empty() ? std::string("the top level") : "'" + parent + "'") +
           did_you_mean(candidates);
  }
} // namespace poundfe
