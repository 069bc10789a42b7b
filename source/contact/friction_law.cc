#include <polyfrac/contact/friction_law.h>

#include <algorithm>

namespace PolyFrac
{
  namespace FrictionLaws
  {
    namespace
    {
      /** The name of the law chosen in @p prm (the subsection Contact,
       * entered, or ContactParameters::friction_law). */
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
    create(const ContactParameters       &prm,
           const ParameterContext        &context,
           const std::vector<Point<dim>> &centroids)
    {
      ParameterHandler &entries = *prm.friction_law;
      return factory<dim>(find(chosen(entries)))(entries, context, centroids);
    }



    template <int dim>
    std::unique_ptr<FrictionLaw<dim>>
    create(const ContactParameters    &prm,
           const ParameterContext     &context,
           const MeshGeometry<dim>    &geometry,
           const FractureNetwork<dim> &network)
    {
      std::vector<Point<dim>> centroids;
      for (const auto &fracture_face : network.fracture_faces)
        centroids.push_back(geometry.faces[fracture_face.face].centroid);
      return create(prm, context, centroids);
    }



    template std::unique_ptr<FrictionLaw<2>>
    create(const ContactParameters &,
           const ParameterContext &,
           const std::vector<Point<2>> &);
    template std::unique_ptr<FrictionLaw<2>>
    create(const ContactParameters &,
           const ParameterContext &,
           const MeshGeometry<2> &,
           const FractureNetwork<2> &);
    template std::unique_ptr<FrictionLaw<3>>
    create(const ContactParameters &,
           const ParameterContext &,
           const MeshGeometry<3> &,
           const FractureNetwork<3> &);
    template std::unique_ptr<FrictionLaw<3>>
    create(const ContactParameters &,
           const ParameterContext &,
           const std::vector<Point<3>> &);
  } // namespace FrictionLaws
} // namespace PolyFrac
