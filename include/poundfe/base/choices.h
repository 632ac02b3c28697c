// Choices of a parameter file: each enum has one table of its names (used
// to parse, in help texts, in messages and in summary.json), and add_choice
// declares an entry whose help lists the allowed values (deal.II's PRM
// output prints only the documentation, not the Selection pattern).
#ifndef poundfe_base_choices_h
#define poundfe_base_choices_h

#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  template <typename Enum>
  class NameTable
  {
  public:
    NameTable(std::vector<std::pair<Enum, std::string>> entries)
      : entries(std::move(entries))
    {}

    const std::string &
    name(const Enum value) const
    {
      for (const auto &e : entries)
        if (e.first == value)
          return e.second;
      throw std::logic_error("an enum value without a name");
    }

    /// Only for names that passed the Selection pattern of names().
    Enum
    value(const std::string &name) const
    {
      for (const auto &e : entries)
        if (e.second == name)
          return e.first;
      throw std::invalid_argument("unknown name '" + name + "'");
    }

    std::vector<std::string>
    names() const
    {
      std::vector<std::string> result;
      for (const auto &e : entries)
        result.push_back(e.second);
      return result;
    }

  private:
    std::vector<std::pair<Enum, std::string>> entries;
  };

  /// Declare `name` (default `default_value`) with a Selection of `choices`
  /// and "Allowed: a, b, c." after the documentation; `set` receives each
  /// value read.
  void add_choice(dealii::ParameterHandler                      &prm,
                  const std::string                             &name,
                  const std::string                             &default_value,
                  const std::string                             &documentation,
                  const std::vector<std::string>                &choices,
                  const std::function<void(const std::string &)> &set);

  /// A choice bound to a string (registries of names: contact laws, solvers).
  void add_choice(dealii::ParameterHandler       &prm,
                  const std::string              &name,
                  std::string                    &value,
                  const std::string              &documentation,
                  const std::vector<std::string> &choices);

  /// A choice bound to an enum, converted when the file is parsed.
  template <typename Enum>
  void
  add_choice(dealii::ParameterHandler &prm,
             const std::string        &name,
             Enum                     &value,
             const std::string        &documentation,
             const NameTable<Enum>    &table)
  {
    add_choice(prm, name, table.name(value), documentation, table.names(),
               [&value, &table](const std::string &s) { value = table.value(s); });
  }
} // namespace poundfe

#endif
