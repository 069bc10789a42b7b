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



  const std::map<std::string, std::vector<ParameterExtension>> &
  parameter_extensions()
  {
    return extensions();
  }
} // namespace PolyFrac
