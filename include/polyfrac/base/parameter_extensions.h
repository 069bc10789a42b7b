#ifndef polyfrac_base_parameter_extensions_h
#define polyfrac_base_parameter_extensions_h

#include <deal.II/base/parameter_handler.h>

#include <polyfrac/base/parameter_context.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace PolyFrac
{
  using namespace dealii;

  /**
   * Entries that a component adds to a subsection of the parameter file
   * from its own files (ASPECT's plugins, in deal.II idiom): the friction
   * laws add theirs to the subsection Contact. The parameters of the
   * subsection (ContactParameters) declare them, check them when they read
   * the file and list those the choices leave unused, with the rest of the
   * subsection and without knowing the plugin: base/ knows no physics.
   */
  struct ParameterExtension
  {
    /** The entries it declares. */
    std::function<std::vector<std::string>()> entries;
    /** Declares them (in the subsection, entered). */
    std::function<void(ParameterHandler &)> declare;
    /** Reads and checks them as the component will (in the subsection,
     * entered); throws naming the file and the entry. */
    std::function<void(ParameterHandler &, const ParameterContext &)> check;
    /**
     * The entries the choices made in the subsection (entered) leave
     * unused, each with the choice that does (e.g. "Contact/Friction law
     * = Coulomb"), for the warnings about entries that are set but unused.
     */
    std::function<std::vector<std::pair<std::string, std::string>>(
      ParameterHandler &)>
      unused_entries;
  };

  /**
   * Adds @p extension to the subsection @p subsection. Called while the
   * program starts, by the registration object of the component (e.g.
   * FrictionLaws::Registration).
   */
  void
  add_parameter_extension(const std::string        &subsection,
                          const ParameterExtension &extension);

  /** Declares the extensions of the subsection @p subsection in @p prm
   * (the subsection entered). */
  void
  declare_parameter_extensions(const std::string &subsection,
                               ParameterHandler  &prm);

  /**
   * Checks the extensions of the subsection @p subsection in @p prm (the
   * subsection entered) and returns their entries with the values of
   * @p prm, declared at the top level of a handler of their own: what the
   * components behind the extensions read later (e.g. the chosen friction
   * law's coefficients).
   */
  std::shared_ptr<ParameterHandler>
  parse_parameter_extensions(const std::string      &subsection,
                             ParameterHandler       &prm,
                             const ParameterContext &context);

  /** The entries the extensions of @p subsection add, as
   * "Subsection/Entry". */
  std::vector<std::string>
  parameter_extension_entries(const std::string &subsection);

  /** The entries of the extensions of @p subsection that the choices in
   * @p values (as parse_parameter_extensions() returns them) leave
   * unused, as "Subsection/Entry", each with the choice. */
  std::vector<UnusedEntry>
  unused_parameter_extension_entries(const std::string &subsection,
                                     ParameterHandler  &values);
} // namespace PolyFrac

#endif
