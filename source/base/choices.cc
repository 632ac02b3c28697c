#include <poundfe/base/choices.h>

#include <deal.II/base/parameter_handler.h>

namespace poundfe
{
  void
  add_choice(dealii::ParameterHandler                      &prm,
             const std::string                             &name,
             const std::string                             &default_value,
             const std::string                             &documentation,
             const std::vector<std::string>                &choices,
             const std::function<void(const std::string &)> &set)
  {
    std::string selection, allowed;
    for (const std::string &c : choices)
      {
        selection += (selection.empty() ? "" : "|") + c;
        allowed += (allowed.empty() ? "" : ", ") + c;
      }
    const std::string help =
      documentation + (documentation.empty() ? "" : " ") + "Allowed: " + allowed + ".";
    prm.declare_entry(name, default_value, dealii::Patterns::Selection(selection), help);
    prm.add_action(name, set);
  }

  void
  add_choice(dealii::ParameterHandler       &prm,
             const std::string              &name,
             std::string                    &value,
             const std::string              &documentation,
             const std::vector<std::string> &choices)
  {
    add_choice(prm, name, value, documentation, choices,
               [&value](const std::string &s) { value = s; });
  }
} // namespace poundfe
