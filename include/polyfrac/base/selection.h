#ifndef polyfrac_base_selection_h
#define polyfrac_base_selection_h

#include <deal.II/base/exceptions.h>

#include <cstddef>
#include <string>

namespace PolyFrac
{
  /**
   * The names of the values of an enum that a Patterns::Selection entry
   * chooses: a specialisation holds `static constexpr std::array<const char
   * *, N> names`, in the order of the enum's values (0, 1, ...). The text of
   * the parameter file is parsed into the enum once (parse_selection()),
   * and the code compares enum values; selection_name() prints a value as
   * the file writes it.
   */
  template <typename Enum>
  struct SelectionNames;

  /** The names of @p Enum joined by '|', for Patterns::Selection. */
  template <typename Enum>
  std::string
  selection_pattern()
  {
    std::string pattern;
    for (const char *name : SelectionNames<Enum>::names)
      pattern += (pattern.empty() ? "" : "|") + std::string(name);
    return pattern;
  }

  /** The value of @p Enum named @p name (which its pattern has checked). */
  template <typename Enum>
  Enum
  parse_selection(const std::string &name)
  {
    const auto &names = SelectionNames<Enum>::names;
    for (std::size_t i = 0; i < names.size(); ++i)
      if (name == names[i])
        return static_cast<Enum>(i);
    AssertThrow(false,
                dealii::ExcMessage("<" + name + "> is none of " +
                                   selection_pattern<Enum>() + "."));
    return Enum();
  }

  /** The name of @p value, as the parameter file writes it. */
  template <typename Enum>
  std::string
  selection_name(const Enum value)
  {
    return SelectionNames<Enum>::names[static_cast<std::size_t>(value)];
  }
} // namespace PolyFrac

#endif
