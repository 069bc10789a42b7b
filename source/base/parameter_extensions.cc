#include <polyfrac/base/parameter_extensions.h>

namespace PolyFrac
{
  namespace
  {
    /** The extensions by subsection. A function's static, so that it
     * exists before the registration objects of other files use it. */
    std::map<std::string, std::vector<ParameterExtension>> &
    extensions()
    {
      static std::map<std::string, std::vector<ParameterExtension>> all;
      return all;
    }
  } // namespace



  void
  add_parameter_extension(const std::string        &subsection,
                          const ParameterExtension &extension)
  {
    extensions()[subsection].push_back(extension);
  }



  void
  declare_parameter_extensions(const std::string &subsection,
                               ParameterHandler  &prm)
  {
    for (const ParameterExtension &extension : extensions()[subsection])
      extension.declare(prm);
  }



  std::shared_ptr<ParameterHandler>
  parse_parameter_extensions(const std::string      &subsection,
                             ParameterHandler       &prm,
                             const ParameterContext &context)
  {
    auto values = std::make_shared<ParameterHandler>();
    for (const ParameterExtension &extension : extensions()[subsection])
      {
        extension.check(prm, context);
        extension.declare(*values);
        for (const std::string &entry : extension.entries())
          values->set(entry, prm.get(entry));
      }
    return values;
  }



  std::vector<std::string>
  parameter_extension_entries(const std::string &subsection)
  {
    std::vector<std::string> entries;
    for (const ParameterExtension &extension : extensions()[subsection])
      for (const std::string &entry : extension.entries())
        entries.push_back(subsection + "/" + entry);
    return entries;
  }



  std::vector<UnusedEntry>
  unused_parameter_extension_entries(const std::string &subsection,
                                     ParameterHandler  &values)
  {
    std::vector<UnusedEntry> unused;
    for (const ParameterExtension &extension : extensions()[subsection])
      for (const auto &[entry, choice] : extension.unused_entries(values))
        unused.emplace_back(subsection + "/" + entry, choice);
    return unused;
  }
} // namespace PolyFrac
