#include <poundfe/input/named_files.h>

#include <sstream>

namespace poundfe
{
  namespace
  {
    /// Whether the entry at `path` ("Section/.../Entry") names one file.
    bool
    names_a_file(const std::string &path)
    {
      const std::size_t slash = path.rfind('/');
      const std::string entry = slash == std::string::npos ? path : path.substr(slash + 1);
      const std::string suffix = " file";
      return entry == "File" ||
             (entry.size() > suffix.size() &&
              entry.compare(entry.size() - suffix.size(), suffix.size(), suffix) == 0);
    }

    /// The files of Nodal forces/Tabulated: 'building floor node dof file'
    /// separated by ';' (the fifth field of each).
    std::vector<std::string>
    tabulated_files(const std::string &value)
    {
      std::vector<std::string> files;
      std::istringstream       items(value);
      for (std::string item; std::getline(items, item, ';');)
        {
          std::istringstream fields(item);
          std::string        field;
          for (int i = 0; i < 5 && fields >> field; ++i)
            if (i == 4)
              files.push_back(field);
        }
      return files;
    }
  } // namespace

  std::vector<NamedFile>
  named_files(const InputParameters &input)
  {
    std::vector<NamedFile> files;
    for (const auto &[path, value] : input.values)
      {
        if (value.empty())
          continue;
        if (path == "Nodal forces/Tabulated")
          for (const std::string &file : tabulated_files(value))
            files.push_back({path, file, input.resolve(file)});
        else if (names_a_file(path))
          files.push_back({path, value, input.resolve(value)});
      }
    return files;
  }
} // namespace poundfe
