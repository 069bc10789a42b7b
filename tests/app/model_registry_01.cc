// Checks the model registry (ModelRegistry), which drives the warnings about
// entries the chosen model does not read, both ways:
// - every entry a model lists is a declared entry (a typo in a list would
//   leave the entry it meant unwarned), and every model can be chosen
//   through Model/Model;
// - every entry of the subsections that depend on the model (Material, Body
//   force, Boundary conditions, Initial stress, Contact with the friction
//   laws' entries, Flow, Nonlinear solver) is listed by some model, so that
//   a new entry cannot escape the warnings by being on no list;
// - for each model and a sample of entries, setting the entry warns "is not
//   used by Model = ..." exactly when the model does not list it.

#include <polyfrac/app/model_registry.h>
#include <polyfrac/app/parameters.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>

using namespace PolyFrac;

namespace
{
  const std::string scene = "model_registry_01.prm";

  /** Whether @p list holds @p entry. */
  bool
  holds(const std::vector<std::string> &list, const std::string &entry)
  {
    return std::find(list.begin(), list.end(), entry) != list.end();
  }

  /** Every declared entry as "Subsection/Entry" (top-level entries as
   * "Entry"), read from the printed default tree. */
  std::vector<std::string>
  declared_entries()
  {
    std::ostringstream tree;
    Parameters::print_defaults(2, tree);
    std::istringstream       in(tree.str());
    std::vector<std::string> entries, subsections;
    const std::regex         subsection(R"(^\s*subsection\s+(.*\S)\s*$)");
    const std::regex         set(R"(^\s*set\s+(.*?)\s*=.*$)");
    const std::regex         end(R"(^\s*end\s*$)");
    for (std::string line; std::getline(in, line);)
      {
        std::smatch match;
        if (std::regex_match(line, match, subsection))
          subsections.push_back(match[1]);
        else if (std::regex_match(line, end))
          subsections.pop_back();
        else if (std::regex_match(line, match, set))
          entries.push_back(
            (subsections.empty() ? "" : subsections.back() + "/") +
            std::string(match[1]));
      }
    return entries;
  }

  /** The warnings of the scene with Model = @p model and @p setting. */
  std::vector<std::string>
  warnings(const std::string &model, const std::string &setting)
  {
    Parameters prm(2);
    prm.parse(scene, {"Model/Model=" + model, setting});
    return prm.warnings;
  }
} // namespace



int
main()
{
  std::ofstream(scene) << "set Dimension = 2\n"
                          "subsection Fractures\n"
                          "  set Segments = -0.5, 0 : 0.5, 0\n"
                          "end\n";
  const std::vector<std::string> declared = declared_entries();
  const std::vector<std::string> dependent =
    ModelRegistry::model_dependent_entries();

  // Every listed entry is declared; every model can be chosen.
  for (const ModelRegistry::Description &model : ModelRegistry::models())
    {
      for (const std::string &entry : model.entries())
        AssertThrow(holds(declared, entry),
                    ExcMessage("Model = " + model.name + " lists <" + entry +
                               ">, which is not an entry."));
      Parameters prm(2);
      prm.parse(scene, {"Model/Model=" + model.name});
      AssertThrow(prm.model_description().name == model.name,
                  ExcInternalError());
      std::cout << model.name << ": " << model.entries().size()
                << " entries read" << std::endl;
    }

  // The subsections that depend on the model have no entry on no list.
  unsigned int n_checked = 0;
  for (const std::string &entry : declared)
    for (const std::string subsection : {"Material/",
                                         "Body force/",
                                         "Boundary conditions/",
                                         "Initial stress/",
                                         "Contact/",
                                         "Flow/",
                                         "Nonlinear solver/"})
      if (entry.rfind(subsection, 0) == 0)
        {
          AssertThrow(holds(dependent, entry),
                      ExcMessage("<" + entry +
                                 "> depends on the model, but no model "
                                 "lists it: it would never be warned "
                                 "about."));
          ++n_checked;
        }
  std::cout << n_checked << " model-dependent entries, each listed"
            << std::endl;

  // Setting an entry warns exactly when the chosen model does not list it.
  for (const auto &[entry, value] :
       std::vector<std::pair<std::string, std::string>>{
         {"Material/Lame mu", "2e9"},
         {"Fractures/Traction", "1; 0"},
         {"Contact/Number of load steps", "2"},
         {"Contact/Friction coefficient", "0.3"},
         {"Flow/Viscosity", "2e-3"},
         {"Flow/Biot coefficient", "0.8"},
         {"Nonlinear solver/Anderson depth", "3"},
         {"Exact solution/Matrix pressure", "x"}})
    for (const ModelRegistry::Description &model : ModelRegistry::models())
      {
        const std::vector<std::string> found =
          warnings(model.name, entry + "=" + value);
        const bool warned =
          holds(found,
                entry + " is not used by Model = " + model.name +
                  " and is ignored");
        AssertThrow(warned == !holds(model.entries(), entry),
                    ExcMessage(entry + " under Model = " + model.name +
                               (warned ? ": warned, but the model reads it" :
                                         ": not warned, but the model does "
                                         "not read it")));
        std::cout << entry << " under " << model.name << ": "
                  << (warned ? "warned" : "read") << std::endl;
      }
}
