#include <polyfrac/contact/friction_law.h>

#include <algorithm>

namespace PolyFrac
{
  namespace FrictionLaws
  {
    namespace
    {
      /** The name of the law chosen in the subsection Contact of @p prm
       * (entered). */
      std::string
      chosen(ParameterHandler &prm)
      {
        return prm.get("Friction law");
      }

      /** The laws in the order of their names (the order in which the
       * files register them is not defined). */
      std::vector<Law> &
      laws();

      /** The law called @p name (the entry's pattern admits no other). */
      const Law &
      find(const std::string &name)
      {
        const auto &all = laws();
        const auto  law =
          std::find_if(all.begin(), all.end(), [&](const Law &l) {
            return l.name == name;
          });
        Assert(law != all.end(), ExcInternalError());
        return *law;
      }

      /** The factory of @p law in dimension dim. */
      template <int dim>
      const Factory<dim> &
      factory(const Law &law)
      {
        if constexpr (dim == 2)
          return law.create_2d;
        else
          return law.create_3d;
      }

      /** The entry Contact/Friction law, the laws' own entries, their
       * checks and the entries the chosen law leaves unused. */
      ParameterExtension
      extension()
      {
        ParameterExtension extension;
        extension.entries = []() {
          std::vector<std::string> entries = {"Friction law"};
          for (const Law &law : laws())
            for (const std::string &entry : law.entries)
              if (std::find(entries.begin(), entries.end(), entry) ==
                  entries.end())
                entries.push_back(entry);
          return entries;
        };
        extension.declare = [](ParameterHandler &prm) {
          std::string names, documentation = "Friction on the fracture faces.";
          for (const Law &law : laws())
            {
              names += (names.empty() ? "" : "|") + law.name;
              documentation += " " + law.name + ": " + law.description;
            }
          prm.declare_entry("Friction law",
                            "Coulomb",
                            Patterns::Selection(names),
                            documentation);
          for (const Law &law : laws())
            law.declare(prm);
        };
        extension.check = [](ParameterHandler       &prm,
                             const ParameterContext &context) {
          const Law &law = find(chosen(prm));
          if (context.dim == 2)
            factory<2>(law)(prm, context, {});
          else
            factory<3>(law)(prm, context, {});
        };
        extension.unused_entries = [](ParameterHandler &prm) {
          const Law &law = find(chosen(prm));
          std::vector<std::pair<std::string, std::string>> unused;
          for (const Law &other : laws())
            for (const std::string &entry : other.entries)
              if (std::find(law.entries.begin(), law.entries.end(), entry) ==
                    law.entries.end() &&
                  std::find_if(unused.begin(),
                               unused.end(),
                               [&](const auto &e) {
                                 return e.first == entry;
                               }) == unused.end())
                unused.emplace_back(entry,
                                    "Contact/Friction law = " + law.name);
          return unused;
        };
        return extension;
      }

      std::vector<Law> &
      laws()
      {
        static std::vector<Law> all;
        return all;
      }
    } // namespace



    void
    register_law(const Law &law)
    {
      if (laws().empty())
        add_parameter_extension("Contact", extension());
      auto &all = laws();
      all.insert(std::find_if(all.begin(),
                              all.end(),
                              [&](const Law &l) { return law.name < l.name; }),
                 law);
    }



    template <int dim>
    std::unique_ptr<FrictionLaw<dim>>
    create(const Parameters &prm, const std::vector<Point<dim>> &centroids)
    {
      std::unique_ptr<FrictionLaw<dim>> law;
      prm.read_subsection("Contact",
                          [&](ParameterHandler       &handler,
                              const ParameterContext &context) {
                            law = factory<dim>(find(
                              chosen(handler)))(handler, context, centroids);
                          });
      return law;
    }



    template <int dim>
    std::unique_ptr<FrictionLaw<dim>>
    create(const Parameters           &prm,
           const MeshGeometry<dim>    &geometry,
           const FractureNetwork<dim> &network)
    {
      std::vector<Point<dim>> centroids;
      for (const auto &fracture_face : network.fracture_faces)
        centroids.push_back(geometry.faces[fracture_face.face].centroid);
      return create(prm, centroids);
    }



    template std::unique_ptr<FrictionLaw<2>>
    create(const Parameters &, const std::vector<Point<2>> &);
    template std::unique_ptr<FrictionLaw<2>>
    create(const Parameters &,
           const MeshGeometry<2> &,
           const FractureNetwork<2> &);
    template std::unique_ptr<FrictionLaw<3>>
    create(const Parameters &,
           const MeshGeometry<3> &,
           const FractureNetwork<3> &);
    template std::unique_ptr<FrictionLaw<3>>
    create(const Parameters &, const std::vector<Point<3>> &);
  } // namespace FrictionLaws
} // namespace PolyFrac
