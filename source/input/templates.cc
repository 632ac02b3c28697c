#include <poundfe/input/templates.h>

#include <map>

namespace poundfe
{
  namespace
  {
    const std::map<std::string, std::string> &
    templates()
    {
      static const std::map<std::string, std::string> texts = {
#include "poundfe_templates.inc"
      };
      return texts;
    }
  } // namespace

  std::vector<std::string>
  template_kinds()
  {
    std::vector<std::string> kinds;
    for (const auto &entry : templates())
      kinds.push_back(entry.first);
    return kinds;
  }

  const std::string *
  input_template(const std::string &kind)
  {
    const auto it = templates().find(kind);
    return it == templates().end() ? nullptr : &it->second;
  }
} // namespace poundfe
